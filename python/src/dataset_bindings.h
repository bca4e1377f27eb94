#pragma once
// A MatPredict dataset read from Python (matdataset/format): its samples as dicts of numpy
// arrays, decoded and resized as libmatlearn's trainer reads them, and verify_dataset.
#include <pybind11/pybind11.h>

namespace matpredict_python {

void bind_datasets(pybind11::module_& module);

}  // namespace matpredict_python
