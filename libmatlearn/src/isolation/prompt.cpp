#include "matlearn/isolation/prompt.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "matbase/input_error.h"

namespace matlearn {

void check_prompt(const Prompt& prompt, int width, int height, const std::string& image) {
  const auto outside = [&](int x, int y) { return x < 0 || y < 0 || x >= width || y >= height; };
  if (const auto& box = prompt.box) {
    if (box->x1 < box->x0 || box->y1 < box->y0)
      throw matbase::InputError(fmt::format("{}: the box ({},{})-({},{}) is empty: its last column or row comes before its first",
                                            image, box->x0, box->y0, box->x1, box->y1));
    if (outside(box->x0, box->y0) || outside(box->x1, box->y1))
      throw matbase::InputError(fmt::format("{}: the box ({},{})-({},{}) reaches outside the {} x {} image (columns 0 to {}, rows 0 to {})",
                                            image, box->x0, box->y0, box->x1, box->y1, width, height, width - 1, height - 1));
  }
  for (const PromptPoint& point : prompt.points)
    if (outside(point.x, point.y))
      throw matbase::InputError(fmt::format("{}: the point ({},{}) lies outside the {} x {} image (columns 0 to {}, rows 0 to {})",
                                            image, point.x, point.y, width, height, width - 1, height - 1));
}

Prompt default_prompt(int width, int height) {
  const int inset_x = width / 20, inset_y = height / 20;
  return Prompt{matbase::PixelBox{inset_x, inset_y, width - 1 - inset_x, height - 1 - inset_y}, {}};
}

matbase::PixelBox grown_box(const matbase::PixelBox& box, double fraction, int width, int height) {
  const int grow_x = static_cast<int>(std::lround(fraction * box.width()));
  const int grow_y = static_cast<int>(std::lround(fraction * box.height()));
  return {std::max(0, box.x0 - grow_x), std::max(0, box.y0 - grow_y), std::min(width - 1, box.x1 + grow_x),
          std::min(height - 1, box.y1 + grow_y)};
}

Prompt scaled_prompt(const Prompt& prompt, int width, int height, int scaled_width, int scaled_height) {
  const double sx = static_cast<double>(scaled_width) / width, sy = static_cast<double>(scaled_height) / height;
  const auto first = [](int pixel, double scale) { return static_cast<int>(std::floor(pixel * scale)); };
  const auto last = [](int pixel, double scale, int side) {
    return std::min(side - 1, static_cast<int>(std::ceil((pixel + 1) * scale)) - 1);
  };
  const auto holding = [](int pixel, double scale, int side) {
    return std::min(side - 1, static_cast<int>(std::floor((pixel + 0.5) * scale)));
  };
  Prompt scaled;
  if (prompt.box) {
    const matbase::PixelBox& b = *prompt.box;
    scaled.box = matbase::PixelBox{first(b.x0, sx), first(b.y0, sy), last(b.x1, sx, scaled_width), last(b.y1, sy, scaled_height)};
  }
  for (const PromptPoint& point : prompt.points)
    scaled.points.push_back({holding(point.x, sx, scaled_width), holding(point.y, sy, scaled_height), point.foreground});
  return scaled;
}

}  // namespace matlearn
