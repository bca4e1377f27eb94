#include "python_errors.h"

#include "matbase/input_error.h"
#include "matdataset/format/dataset_error.h"

namespace matpredict_python {

void bind_errors(pybind11::module_& module) {
  const auto& input_error = pybind11::register_exception<matbase::InputError>(module, "InputError", PyExc_ValueError);
  input_error.attr("__doc__") =
      "A bad file, key or value (a ValueError); the message names the file or 'the scene', the JSON pointer or key, "
      "and the problem.";
  const auto& dataset_error =
      pybind11::register_exception<matdataset::DatasetError>(module, "DatasetError", input_error.ptr());
  dataset_error.attr("__doc__") = "A dataset's file missing, unreadable or refused (an InputError); the message names it.";
}

}  // namespace matpredict_python
