#include "isolation_bindings.h"

#include <algorithm>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "image_arrays.h"
#include "matbase/input_error.h"
#include "matdataset/format/sample_reader.h"
#include "matlearn/isolation/object_isolation.h"
#include "owned_array.h"

namespace matpredict_python {
namespace {

namespace py = pybind11;

// Where an image's and a prompt's errors point.
constexpr const char* kImageName = "the image";

// A photograph as its display-encoded RGB in [0, 1]: 8- and 16-bit integers scaled by their
// largest code, floats as they are; a grey image in all three channels. A fourth channel is
// alpha, the object where some pixel is transparent.
std::pair<matbase::FloatImage, std::optional<matbase::Mask>> photo_of(const py::array& image) {
  const char kind = image.dtype().kind();
  const double scale = kind == 'u' && image.itemsize() == 1 ? 1.0 / 255.0 : kind == 'u' && image.itemsize() == 2 ? 1.0 / 65535.0 : 1.0;
  if (kind != 'f' && scale == 1.0)
    throw py::type_error("image: expected uint8, uint16 or float values, got dtype " + std::string(py::str(image.dtype())));
  const matbase::FloatImage pixels = float_image(image, "image");
  if (pixels.channels != 1 && pixels.channels != 3 && pixels.channels != 4)
    throw py::value_error("image: expected 1 (grey), 3 (RGB) or 4 (RGBA) channels, got " + std::to_string(pixels.channels));
  matbase::FloatImage rgb(pixels.width, pixels.height, 3);
  for (size_t p = 0; p < pixels.pixel_count(); ++p) {
    const size_t in = p * static_cast<size_t>(pixels.channels);
    for (size_t c = 0; c < 3; ++c) {
      const float value = static_cast<float>(pixels.values[in + (pixels.channels == 1 ? 0 : c)] * scale);
      if (!(value >= 0.0f && value <= 1.0f))
        throw py::value_error("image: expected values in [0, 1] (display-encoded RGB), got " + std::to_string(value));
      rgb.values[3 * p + c] = value;
    }
  }
  std::optional<matbase::Mask> mask = matdataset::alpha_mask(pixels);
  return {std::move(rgb), std::move(mask)};
}

matlearn::Prompt prompt_of(const std::optional<std::tuple<int, int, int, int>>& box,
                           const std::optional<std::vector<std::vector<int>>>& points) {
  matlearn::Prompt prompt;
  if (box) prompt.box = matbase::PixelBox{std::get<0>(*box), std::get<1>(*box), std::get<2>(*box), std::get<3>(*box)};
  for (const std::vector<int>& point : points.value_or(std::vector<std::vector<int>>{})) {
    if ((point.size() != 2 && point.size() != 3) || (point.size() == 3 && point[2] != 0 && point[2] != 1))
      throw py::value_error("points: expected (x, y) or (x, y, 1) on the object, (x, y, 0) off it");
    prompt.points.push_back({point[0], point[1], point.size() == 2 || point[2] == 1});
  }
  return prompt;
}

py::dict isolate(const SegmenterMaker& make_segmenter, const py::array& image, const py::object& mask_array,
                 const std::optional<std::tuple<int, int, int, int>>& box, const std::optional<std::vector<std::vector<int>>>& points,
                 const std::string& segmenter_name, int size, const std::string& background_name) {
  if (size < 1) throw py::value_error("size: expected a whole number of at least 1, got " + std::to_string(size));
  if (const std::optional<std::string> problem = matlearn::segmenter_choice_problem(segmenter_name))
    throw py::value_error("segmenter: " + *problem);
  if (background_name != "black" && background_name != "white")
    throw py::value_error("background: expected \"black\" or \"white\", got \"" + background_name + "\"");
  const matdataset::CropBackground background =
      background_name == "white" ? matdataset::CropBackground::White : matdataset::CropBackground::Black;
  auto [rgb, mask] = photo_of(image);
  if (!mask_array.is_none()) mask = mask_of(mask_array, rgb.width, rgb.height);
  const matlearn::Prompt prompt = prompt_of(box, points);
  matlearn::IsolatedObject object;
  {
    py::gil_scoped_release release;
    if (mask) {
      if (std::none_of(mask->begin(), mask->end(), [](uint8_t v) { return v != 0; }))
        throw matbase::InputError(std::string(kImageName) + ": the mask marks no pixel of the object");
      object = {*mask, matdataset::isolated_input(rgb, *mask, size, background)};
    } else {
      const std::shared_ptr<const matlearn::Segmenter> segmenter = make_segmenter(segmenter_name);
      object = matlearn::isolate_object(rgb, prompt, *segmenter, size, background, kImageName);
    }
  }
  const matdataset::IsolatedInput& isolated = object.isolated;
  py::dict result;
  const py::ssize_t h = rgb.height, w = rgb.width, s = size;
  result["mask"] = owned_array<bool, uint8_t>(std::move(object.mask), {h, w});
  result["input"] = owned_array<float>(std::vector<float>(isolated.input.rgb.values), {s, s, 3});
  result["input_mask"] = owned_array<bool, uint8_t>(std::vector<uint8_t>(isolated.input.mask), {s, s});
  result["crop"] = py::make_tuple(isolated.crop.left, isolated.crop.top, isolated.crop.side);
  return result;
}

// The box around the mask's pixels, grown by `grow` of its width and height on each side within
// the image; None for an empty mask.
py::object mask_box(const py::array& mask, double grow) {
  if (mask.ndim() < 2)
    throw py::value_error("mask: expected shape (H, W), got " + std::to_string(mask.ndim()) + " dimension(s)");
  if (!(grow >= 0.0 && grow <= 10.0)) throw py::value_error("grow: expected a fraction in [0, 10], got " + std::to_string(grow));
  const int height = static_cast<int>(mask.shape(0)), width = static_cast<int>(mask.shape(1));
  const std::optional<matbase::PixelBox> bounds = matbase::mask_bounds(mask_of(mask, width, height), width, height);
  if (!bounds) return py::none();
  const matbase::PixelBox box = matlearn::grown_box(*bounds, grow, width, height);
  return py::make_tuple(box.x0, box.y0, box.x1, box.y1);
}

}  // namespace

void bind_mask_box(py::module_& module) {
  module.def("mask_box", &mask_box, py::arg("mask"), py::arg("grow") = 0.0,
             "The box prompt around an object's mask, as isolate's `box` takes it: (x0, y0, x1, y1), the\n"
             "first and last pixel column and row holding a nonzero entry of `mask` (H, W), grown by `grow`\n"
             "of the box's width and height on each side (rounded half away from zero) and kept inside the\n"
             "image; None when the mask is empty. With a label AOV: mask_box(frame['label'][:, :, 0] == k, 0.05).");
}

void bind_isolation(py::module_& module, SegmenterMaker make_segmenter) {
  module.def("isolate",
             [make_segmenter](const py::array& image, const py::object& mask, const std::optional<std::tuple<int, int, int, int>>& box,
                              const std::optional<std::vector<std::vector<int>>>& points, const std::string& segmenter, int size,
                              const std::string& background) {
               return isolate(make_segmenter, image, mask, box, points, segmenter, size, background);
             },
             py::arg("image"), py::kw_only(), py::arg("mask") = py::none(), py::arg("box") = py::none(),
             py::arg("points") = py::none(), py::arg("segmenter") = "grabcut", py::arg("size") = 224,
             py::arg("background") = "black",
             "Isolates the object in an image as evaluate --image does, for Model.predict: `image` (H, W, 3)\n"
             "RGB (or grey (H, W), or RGBA) as stored, display-encoded: uint8, uint16 or floats in [0, 1].\n"
             "The object is `mask` (H, W, nonzero inside) when given, else the alpha where some pixel is\n"
             "transparent, else what the segmenter finds from the prompt: 'grabcut' (OpenCV's GrabCut, no\n"
             "weights) or 'sam:CHECKPOINT' (Segment Anything, a checkpoint scripts/convert_segment_anything.py\n"
             "wrote; loaded once and kept for the next calls; loads libtorch):\n"
             "`box` (x0, y0, x1, y1), the first and last pixel column and row around the object, and\n"
             "`points`, (x, y) on the object or (x, y, 0) off it; none means the image's central 90 %.\n"
             "Returns {'mask': (H, W) bool, the object cleaned into one region with its holes filled;\n"
             "'input': (size, size, 3) float32, the square around it (4 % margin) with `background`\n"
             "('black' or 'white') off the object, resized as dataset samples are; 'input_mask': (size,\n"
             "size) bool; 'crop': (left, top, side) of the square in the image's pixels}. A prompt outside\n"
             "the image or an object not found raises matpredict.InputError.");
}

}  // namespace matpredict_python
