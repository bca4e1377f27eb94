#pragma once
// Which pixels' camera rays can meet the scene at all. A pixel's samples leave through raster
// positions within the pixel filter's radius of its centre (pixel_filter.h); when none of those
// sees the box around the scene's vertices, every camera ray of the pixel misses everything, and
// the render takes its samples without tracing them (render.cpp).
#include <glm/glm.hpp>

#include "film/camera_rays.h"

namespace matrender {

struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // pixels [x0, x1) x [y0, y1)
  bool contains(int x, int y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
};

// The pixels whose camera rays may meet the box [lower, upper]: the rectangle around its
// corners' raster positions (the box's image lies in their hull when every corner is in front of
// the camera), grown by the filter's radius and a pixel for rounding, clipped to the image of
// width x height pixels. The whole image when some corner is not in front of the camera; no
// pixel for an empty box (a lower bound above its upper one).
PixelRect pixels_seeing_box(const CameraRays& rays, int width, int height, const glm::vec3& lower,
                            const glm::vec3& upper, double filter_radius);

}  // namespace matrender
