// Every style of the procedural library rendered on a textured plane: finite pixels, its class in
// the label AOV, and material AOVs that are its maps' values where the camera hits the plane.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "../render/test_scenes.h"
#include "matbase/image/srgb.h"
#include "matgeom/tangents.h"
#include "matmaterial/library/material_library.h"
#include "matrender/asset.h"
#include "matrender/render.h"
#include "matrender/scene.h"

using namespace matrender;

namespace {

constexpr int kImageSize = 32;
constexpr int kMapSize = 16;
constexpr double kEyeHeight = 3.0;
const double kTanHalfFov = 0.3;  // the camera sees x, y in [-0.9, 0.9] of the 2 m plane

// The plane's (u, v) under pixel (px, py)'s centre, for the camera straight above it.
glm::dvec2 uv_under_pixel(int px, int py) {
  const double x = (2.0 * (px + 0.5) / kImageSize - 1.0) * kTanHalfFov * kEyeHeight;
  const double y = (1.0 - 2.0 * (py + 0.5) / kImageSize) * kTanHalfFov * kEyeHeight;
  return {x / 2.0 + 0.5, y / 2.0 + 0.5};
}

// The lowest and highest decoded value of channel `channel` among the texels within two texels
// of (u, v): what bilinear filtering over the pixel's footprint can return there.
std::pair<double, double> texel_bounds(const matbase::ImagePixels& image, matmaterial::ColorSpace space, glm::dvec2 uv,
                                       int channel) {
  const int cx = static_cast<int>(std::floor(uv.x * image.width)), cy = static_cast<int>(std::floor((1.0 - uv.y) * image.height));
  double low = 1e9, high = -1e9;
  for (int dy = -2; dy <= 2; ++dy)
    for (int dx = -2; dx <= 2; ++dx) {
      const int x = ((cx + dx) % image.width + image.width) % image.width;
      const int y = ((cy + dy) % image.height + image.height) % image.height;
      const double code = matbase::texel_channel(image, static_cast<size_t>(y * image.width + x), channel) / 255.0;
      const double value = space == matmaterial::ColorSpace::SRGB ? matbase::srgb_to_linear(code) : code;
      low = std::min(low, value);
      high = std::max(high, value);
    }
  return {low, high};
}

}  // namespace

TEST_CASE("Every library style renders finite pixels, labelled with its class, its AOVs its maps", "[material]") {
  matgeom::TriangleMesh plane = test_scenes::horizontal_square(2.0);
  plane.normals.assign(plane.positions.size(), glm::vec3(0.0f, 0.0f, 1.0f));
  matgeom::compute_tangents(plane);
  const Camera camera = Camera::look_at({0, 0, kEyeHeight}, {0, 0, 0}, {0, 1, 0}, 2.0 * std::atan(kTanHalfFov),
                                        kImageSize, kImageSize);
  for (const matmaterial::LibraryStyleInfo& style : matmaterial::library_styles()) {
    const matmaterial::LibraryMaterialSpec spec{style.material_class, style.name, 2};
    INFO(matmaterial::library_material_name(spec));
    const matmaterial::FolderMaterial generated = matmaterial::generate_library_material(spec, {kMapSize, 0});
    Scene scene;
    scene.add_mesh(plane, {scene.add_material(material_from_desc(generated.material, generated.images))});
    scene.add_lamp(PointLamp{glm::dvec3(0.5, 0.5, 2.0), 100.0, glm::dvec3(1.0)});
    RenderSettings settings;
    settings.samples_per_pixel = 4;
    settings.aovs = all_aovs();
    FrameBuffers frame;
    render(scene, camera, settings, frame);

    CHECK(std::all_of(frame.color.begin(), frame.color.end(), [](float c) { return std::isfinite(c) && c >= 0.0f; }));
    int covered = 0, uncovered = 0, outside = 0;
    for (int py = 0; py < kImageSize; ++py)
      for (int px = 0; px < kImageSize; ++px) {
        const size_t i = static_cast<size_t>(py * kImageSize + px);
        if (frame.alpha[i] < 1.0f) {
          ++uncovered;  // holes of a perforated material let samples through
          continue;
        }
        ++covered;
        CHECK(frame.label[i] == matmaterial::label_id(style.material_class));
        const glm::dvec2 uv = uv_under_pixel(px, py);
        for (const matmaterial::MaterialParameterInfo& info : matmaterial::kMaterialParameters) {
          const matmaterial::MaterialInput& input = generated.material[info.id];
          const int channels = info.kind == matmaterial::ParameterKind::Color ? 3 : 1;
          for (int c = 0; c < channels; ++c) {
            const double aov = frame.parameter(info.id)[channels * i + static_cast<size_t>(c)];
            double low = input.value[c], high = input.value[c];
            if (input.image >= 0) {
              const auto [l, h] = texel_bounds(generated.images[static_cast<size_t>(input.image)], info.texture_space,
                                                uv, channels == 3 ? c : input.channel);
              low = l * input.value[c];
              high = h * input.value[c];
            }
            if (aov < low - 1e-4 || aov > high + 1e-4) {
              ++outside;
              UNSCOPED_INFO(info.name << "[" << c << "] at pixel (" << px << ", " << py << "): " << aov
                                      << " outside [" << low << ", " << high << "]");
            }
          }
        }
      }
    CHECK(outside == 0);
    const bool perforated = generated.material[matmaterial::MaterialParameter::Alpha].image >= 0;
    if (perforated) {
      CHECK(uncovered > 0);
      CHECK(covered > 0);
    } else {
      CHECK(covered == kImageSize * kImageSize);
    }
  }
}
