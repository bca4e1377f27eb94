#include "python_errors.h"

#include "matbase/input_error.h"
#include "matdataset/format/dataset_error.h"

namespace matpredict_python {

void bind_errors(pybind11::module_& module) {
  const auto& input_error = pybind11::register_exception<matbase::InputError>(module, "InputError", PyExc_ValueError);
  pybind11::register_exception<matdataset::DatasetError>(module, "DatasetError", input_error.ptr());
}

}  // namespace matpredict_python
