#pragma once
// matpredict.display_image: a linear colour array as the 8-bit sRGB image render_object's PNG holds.
#include <pybind11/pybind11.h>

namespace matpredict_python {

void bind_display(pybind11::module_& module);

}  // namespace matpredict_python
