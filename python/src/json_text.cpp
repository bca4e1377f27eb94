#include "json_text.h"

#include <cmath>
#include <string>

#include "matbase/document/document_value.h"
#include "matbase/input_error.h"

namespace matpredict_python {
namespace {

namespace py = pybind11;

class PlainValues {
 public:
  explicit PlainValues(const matbase::DocumentSource& source)
      : source_(source),
        numpy_generic_(py::module_::import("numpy").attr("generic")),
        numpy_array_(py::module_::import("numpy").attr("ndarray")),
        path_like_(py::module_::import("os").attr("PathLike")),
        fspath_(py::module_::import("os").attr("fspath")) {}

  // `value` with JSON's types only, checked.
  py::object plain(const py::handle& value, const std::string& path, int depth) const {
    if (depth > matbase::kMaxDocumentDepth)
      throw matbase::InputError(source_.place(path) + ": lists and dicts nest deeper than " +
                                std::to_string(matbase::kMaxDocumentDepth) + " levels (does a dict contain itself?)");
    if (value.is_none() || py::isinstance<py::bool_>(value) || py::isinstance<py::str>(value) ||
        py::isinstance<py::int_>(value))
      return py::reinterpret_borrow<py::object>(value);
    if (py::isinstance<py::float_>(value)) {
      const double number = value.cast<double>();
      if (!std::isfinite(number))
        throw matbase::InputError(source_.place(path) + ": expected a finite number, got " + std::string(py::repr(value)));
      return py::reinterpret_borrow<py::object>(value);
    }
    if (py::isinstance(value, numpy_generic_) || py::isinstance(value, numpy_array_))
      return plain(value.attr("tolist")(), path, depth);  // Python numbers, or nested lists of them
    if (py::isinstance(value, path_like_)) {
      const py::object text = fspath_(value);
      if (!py::isinstance<py::str>(text)) refuse(path, "a path as bytes");
      return text;
    }
    if (py::isinstance<py::dict>(value)) {
      py::dict mapping;
      for (const auto& [key, item] : value.cast<py::dict>()) {
        if (!py::isinstance<py::str>(key))
          throw py::type_error(source_.place(path) + ": expected text keys, got the key " + std::string(py::repr(key)));
        const std::string name = key.cast<std::string>();
        mapping[key] = plain(item, source_.child_path(path, name), depth + 1);
      }
      return std::move(mapping);
    }
    if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
      py::list items;
      size_t index = 0;
      for (const py::handle item : value) items.append(plain(item, source_.item_path(path, index++), depth + 1));
      return std::move(items);
    }
    refuse(path, "a value of type " + std::string(py::str(value.get_type().attr("__qualname__"))));
  }

 private:
  [[noreturn]] void refuse(const std::string& path, const std::string& found) const {
    throw py::type_error(source_.place(path) +
                         ": expected a number, text, True or False, None, a list or a dict (numpy values and "
                         "paths are taken too), got " + found);
  }

  const matbase::DocumentSource& source_;
  py::object numpy_generic_, numpy_array_, path_like_, fspath_;
};

}  // namespace

std::string json_text(const py::handle& value, const matbase::DocumentSource& source) {
  const py::object plain = PlainValues(source).plain(value, "", 0);
  return py::module_::import("json").attr("dumps")(plain, py::arg("allow_nan") = false).cast<std::string>();
}

}  // namespace matpredict_python
