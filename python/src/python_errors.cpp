#include "python_errors.h"

#include "matbase/input_error.h"

namespace matpredict_python {

void bind_errors(pybind11::module_& module) {
  pybind11::register_exception<matbase::InputError>(module, "InputError", PyExc_ValueError);
}

}  // namespace matpredict_python
