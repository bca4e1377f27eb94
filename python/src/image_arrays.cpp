#include "image_arrays.h"

#include <algorithm>
#include <climits>

namespace matpredict_python {
namespace {

namespace py = pybind11;

// Numbers a metric can read: floats, integers, booleans; not strings, objects or complex values.
void check_numeric(const py::array& array, const std::string& name) {
  const char kind = array.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u' && kind != 'b')
    throw py::type_error(name + ": expected an array of numbers, got dtype " + std::string(py::str(array.dtype())));
}

std::string shape_text(const py::array& array) {
  std::string text = "(";
  for (py::ssize_t d = 0; d < array.ndim(); ++d) text += (d ? ", " : "") + std::to_string(array.shape(d));
  return text + (array.ndim() == 1 ? ",)" : ")");
}

}  // namespace

matbase::FloatImage float_image(const py::array& array, const std::string& name) {
  check_numeric(array, name);
  if (array.ndim() != 2 && array.ndim() != 3)
    throw py::value_error(name + ": expected an (H, W) or (H, W, C) array, got shape " + shape_text(array));
  const py::ssize_t h = array.shape(0), w = array.shape(1), c = array.ndim() == 3 ? array.shape(2) : 1;
  if (h < 1 || w < 1 || c < 1 || h > INT_MAX || w > INT_MAX || c > INT_MAX)
    throw py::value_error(name + ": expected a non-empty image, got shape " + shape_text(array));
  const auto values = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(array);
  if (!values) throw py::error_already_set();
  matbase::FloatImage image(static_cast<int>(w), static_cast<int>(h), static_cast<int>(c));
  std::copy(values.data(), values.data() + values.size(), image.values.begin());
  return image;
}

matbase::Mask mask_of(const py::object& mask, int width, int height) {
  if (mask.is_none()) return {};
  const py::array array = py::array::ensure(mask);
  if (!array) throw py::type_error("mask: expected None or an array");
  check_numeric(array, "mask");
  const bool one_channel = array.ndim() == 3 && array.shape(2) == 1;
  if (!(array.ndim() == 2 || one_channel) || array.shape(0) != height || array.shape(1) != width)
    throw py::value_error("mask: expected shape (" + std::to_string(height) + ", " + std::to_string(width) +
                          ") like the images, got " + shape_text(array));
  const auto values = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
  matbase::Mask result(static_cast<size_t>(values.size()));
  for (py::ssize_t k = 0; k < values.size(); ++k) result[static_cast<size_t>(k)] = values.data()[k] != 0.0 ? 1 : 0;
  return result;
}

}  // namespace matpredict_python
