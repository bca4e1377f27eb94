#include "film/reachable_pixels.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "film/pixel_filter.h"

namespace matrender {
namespace {

// Pixels (not raster units) by which the rectangle grows beyond the filter's reach, for the
// rounding of directions and of Embree's tests: far more than either.
constexpr double kRoundingMargin = 1.0;

// floor(v) clamped to [0, limit]; v is finite.
int clamped_floor(double v, int limit) { return static_cast<int>(std::clamp(std::floor(v), 0.0, static_cast<double>(limit))); }

}  // namespace

PixelRect pixels_seeing_box(const CameraRays& rays, int width, int height, const glm::vec3& lower,
                            const glm::vec3& upper, double filter_radius) {
  const PixelRect whole{0, 0, width, height};
  if (!(lower.x <= upper.x && lower.y <= upper.y && lower.z <= upper.z)) return PixelRect{};
  double min_x = INFINITY, min_y = INFINITY, max_x = -INFINITY, max_y = -INFINITY;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p((corner & 1) ? upper.x : lower.x, (corner & 2) ? upper.y : lower.y,
                      (corner & 4) ? upper.z : lower.z);
    const std::optional<glm::vec2> raster = rays.raster_position(p);
    if (!raster || !std::isfinite(raster->x) || !std::isfinite(raster->y)) return whole;
    min_x = std::min(min_x, static_cast<double>(raster->x));
    max_x = std::max(max_x, static_cast<double>(raster->x));
    min_y = std::min(min_y, static_cast<double>(raster->y));
    max_y = std::max(max_y, static_cast<double>(raster->y));
  }
  // Pixel x samples raster positions x + 0.5 +- the filter's radius.
  const double reach = filter_radius + kRoundingMargin;
  PixelRect rect;
  rect.x0 = clamped_floor(min_x - 0.5 - reach, width);
  rect.x1 = clamped_floor(max_x - 0.5 + reach + 1.0, width);
  rect.y0 = clamped_floor(min_y - 0.5 - reach, height);
  rect.y1 = clamped_floor(max_y - 0.5 + reach + 1.0, height);
  return rect;
}

}  // namespace matrender
