#pragma once
// matpredict.load_scene, matpredict.Scene and matpredict.render.
#include <pybind11/pybind11.h>

namespace matpredict_python {

void bind_render(pybind11::module_& module);

}  // namespace matpredict_python
