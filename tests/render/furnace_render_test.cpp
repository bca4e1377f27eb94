// White furnace through the whole renderer: a plane under a uniform white background, seen from
// angle theta, shows its directional albedo a(theta), which shaders_ref computes independently by
// double-precision quadrature. Tolerances come from the spread between pixels.
#include <catch2/catch.hpp>

#include <cmath>

#include "matrender/camera.h"
#include "matrender/render.h"
#include "matrender/scene.h"
#include "shaders_ref/directional_albedo.h"
#include "test_scenes.h"

using namespace matrender;

namespace {

// Pixel statistics of the plane seen from polar angle acos(cos_view) through a narrow camera.
test_scenes::PixelStatistics furnace(const Material& material, double cos_view, int channel) {
  Scene scene;
  scene.add_mesh(test_scenes::horizontal_square(100.0), {scene.add_material(material)});
  scene.set_background(glm::vec3(1.0f));
  const double sin_view = std::sqrt(1.0 - cos_view * cos_view);
  const glm::dvec3 eye(sin_view, 0.0, cos_view);
  const glm::dvec3 up = cos_view > 0.999 ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1);
  const Camera camera = Camera::look_at(eye, glm::dvec3(0.0), up, 0.002, 24, 24);
  RenderSettings settings;
  settings.samples_per_pixel = 32;
  settings.seed = 11;
  FrameBuffers frame;
  const RenderStats stats = render(scene, camera, settings, frame);
  REQUIRE(stats.discarded_samples == 0);
  return test_scenes::channel_statistics(frame, channel);
}

void check_against_reference(const Material& material, const shaders_ref::PrincipledParams& params, double cos_view) {
  const glm::dvec3 wo(std::sqrt(1.0 - cos_view * cos_view), 0.0, cos_view);
  const glm::dvec3 albedo = shaders_ref::directional_albedo(params, wo);
  for (int c = 0; c < 3; ++c) {
    const auto s = furnace(material, cos_view, c);
    INFO("roughness " << params.roughness << " metallic " << params.metallic << " cos_view " << cos_view << " channel "
                      << c << ": rendered " << s.mean << " +- " << s.standard_error << ", reference " << albedo[c]);
    CHECK(std::abs(s.mean - albedo[c]) < 4.0 * s.standard_error + 2e-4 * albedo[c]);
  }
}

}  // namespace

TEST_CASE("Furnace: an albedo-1 Lambertian plane shows exactly 1", "[render]") {
  for (double cos_view : {1.0, 0.5, 0.1}) {
    const auto s = furnace(test_scenes::lambert(1.0f), cos_view, 1);
    CHECK(std::abs(s.mean - 1.0) < 4.0 * s.standard_error + 1e-4);
  }
}

TEST_CASE("Furnace: principled diffuse, base colour 1, matches the reference albedo", "[render]") {
  for (float roughness : {0.0f, 0.5f, 1.0f}) {
    Material m;
    m.set(matrender::MaterialParameter::BaseColor, glm::vec3(1.0f));
    m.set(matrender::MaterialParameter::Roughness, roughness);
    m.set(matrender::MaterialParameter::Specular, 0.0f);
    shaders_ref::PrincipledParams p;
    p.base_color = glm::dvec3(1.0);
    p.roughness = roughness;
    p.specular = 0.0;
    for (double cos_view : {1.0, 0.4}) check_against_reference(m, p, cos_view);
  }
}

TEST_CASE("Furnace: metallic 1 over a roughness sweep matches the reference albedo", "[render]") {
  for (float roughness : {0.05f, 0.2f, 0.5f, 1.0f}) {
    Material m;
    m.set(matrender::MaterialParameter::BaseColor, glm::vec3(1.0f, 0.8f, 0.5f));
    m.set(matrender::MaterialParameter::Metallic, 1.0f);
    m.set(matrender::MaterialParameter::Roughness, roughness);
    shaders_ref::PrincipledParams p;
    p.base_color = glm::dvec3(1.0, 0.8, 0.5);
    p.metallic = 1.0;
    p.roughness = roughness;
    for (double cos_view : {1.0, 0.5, 0.15}) check_against_reference(m, p, cos_view);
  }
}

TEST_CASE("Furnace: a dielectric with both lobes matches the reference albedo", "[render]") {
  Material m;
  m.set(matrender::MaterialParameter::BaseColor, glm::vec3(0.6f, 0.7f, 0.8f));
  m.set(matrender::MaterialParameter::Roughness, 0.3f);
  m.set(matrender::MaterialParameter::Specular, 0.5f);
  m.set(matrender::MaterialParameter::SpecularTint, 0.5f);
  shaders_ref::PrincipledParams p;
  p.base_color = glm::dvec3(0.6, 0.7, 0.8);
  p.roughness = 0.3;
  p.specular = 0.5;
  p.specular_tint = 0.5;
  for (double cos_view : {0.9, 0.3}) check_against_reference(m, p, cos_view);
}
