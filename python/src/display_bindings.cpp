#include "display_bindings.h"

#include <cmath>
#include <vector>

#include <pybind11/numpy.h>

#include "image_arrays.h"
#include "matbase/image/image_writing.h"
#include "owned_array.h"

namespace matpredict_python {
namespace {

namespace py = pybind11;

py::array_t<uint8_t> display_image(const py::array& color, double exposure_stops) {
  const matbase::FloatImage linear = float_image(color, "color");
  if (linear.channels != 3) throw py::value_error("color: expected (H, W, 3) linear RGB, got " + std::to_string(linear.channels) + " channels");
  if (!std::isfinite(exposure_stops) || std::abs(exposure_stops) > matbase::kMaxExposureStops)
    throw py::value_error("exposure_stops: expected a number from -126 to 126");
  const double gain = std::exp2(exposure_stops);
  std::vector<uint8_t> codes(linear.values.size());
  for (size_t i = 0; i < codes.size(); ++i) codes[i] = matbase::display_code(static_cast<float>(linear.values[i] * gain));
  return owned_array<uint8_t>(std::move(codes), {linear.height, linear.width, 3});
}

}  // namespace

void bind_display(py::module_& module) {
  module.def("display_image", &display_image, py::arg("color"), py::kw_only(), py::arg("exposure_stops") = 0.0,
             "A linear colour image (render()'s 'color', (H, W, 3)) as an 8-bit display image, (H, W, 3)\n"
             "uint8: times 2^exposure_stops (a Scene's exposure_stops is its file's), clipped to [0, 1],\n"
             "sRGB-encoded (Blender's 'Standard' view) and rounded: the bytes of render_object's PNG.");
}

}  // namespace matpredict_python
