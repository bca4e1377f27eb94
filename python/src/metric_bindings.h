#pragma once
// The paper's eight image metrics (matlearn/image_metrics.h, metric_scores.h) on numpy arrays.
#include <pybind11/pybind11.h>

namespace matpredict_python {

void bind_metrics(pybind11::module_& module);

}  // namespace matpredict_python
