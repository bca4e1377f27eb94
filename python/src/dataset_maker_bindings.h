#pragma once
// make_dataset from Python (matdataset/maker): a dataset from a configuration dict.
#include <pybind11/pybind11.h>

namespace matpredict_python {

void bind_dataset_maker(pybind11::module_& module);

}  // namespace matpredict_python
