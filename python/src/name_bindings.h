#pragma once
// matpredict.builtin_objects and matpredict.material_classes: the names a scene dict can use.
#include <pybind11/pybind11.h>

namespace matpredict_python {

void bind_names(pybind11::module_& module);

}  // namespace matpredict_python
