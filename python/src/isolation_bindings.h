#pragma once
// matpredict.isolate: an object isolated in an image (a photograph) as evaluate --image does it.
#include <pybind11/pybind11.h>

namespace matpredict_python {

void bind_isolation(pybind11::module_& module);

}  // namespace matpredict_python
