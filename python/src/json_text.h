#pragma once
// A Python dict as JSON text, the way scene dicts and configuration dicts reach the libraries'
// document reader (matbase/document): strings become text, numbers numbers.
#include <string>

#include <pybind11/pybind11.h>

namespace matpredict_python {

inline std::string json_text(const pybind11::handle& value) {
  return pybind11::module_::import("json").attr("dumps")(value).cast<std::string>();
}

}  // namespace matpredict_python
