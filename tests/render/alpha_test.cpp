// Alpha (Blender's Alpha input, our opacity) against closed forms: a card of constant alpha a
// passes exactly 1 - a of the light to camera rays and to shadow rays, a cut-out texture's
// shadow has its shape, the transparent bounce limit stops as Cycles' does, and a scene with no
// coverage anywhere shows its background.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "matrender/camera.h"
#include "matrender/render.h"
#include "matrender/scene.h"
#include "matrender/texture.h"
#include "test_scenes.h"

using namespace matrender;

namespace {

// A black card that scatters nothing: all it does is let 1 - alpha through.
Material black_card(float alpha) {
  Material m;
  m.set(MaterialParameter::BaseColor, glm::vec3(0.0f));
  m.set(MaterialParameter::Specular, 0.0f);
  m.set(MaterialParameter::Alpha, alpha);
  return m;
}

RenderSettings settings_with(int spp) {
  RenderSettings settings;
  settings.samples_per_pixel = spp;
  settings.aovs = AovAlpha;
  return settings;
}

// A floor of albedo 0.5 at z = 0 under a point lamp at z = 2, seen from below the card plane
// z = 1, looking down: the floor gets direct light only (what it reflects up escapes into a
// black background), one deterministic NEE sample per camera sample.
struct ShadowScene {
  Scene scene;
  Camera camera = Camera::look_at({0.0, 0.0, 0.5}, {0.0, 0.0, 0.0}, {0, 1, 0}, 2.0 * std::atan(3.0), 64, 64);
  explicit ShadowScene(const Material* card) {
    scene.add_mesh(test_scenes::horizontal_square(10.0, 0.0), {scene.add_material(test_scenes::lambert(0.5f))});
    if (card) scene.add_mesh(test_scenes::horizontal_square(2.0, 1.0), {scene.add_material(*card)});
    scene.add_lamp(PointLamp{glm::dvec3(0.0, 0.0, 2.0), 100.0, glm::dvec3(1.0)});
  }
  FrameBuffers render_frame() {
    FrameBuffers frame;
    render(scene, camera, settings_with(4), frame);
    return frame;
  }
};

}  // namespace

TEST_CASE("A card of constant alpha passes exactly 1 - alpha to the camera", "[render]") {
  for (const float alpha : {0.0f, 0.25f, 0.7f, 1.0f}) {
    Scene scene;
    scene.add_mesh(test_scenes::horizontal_square(4.0, 0.0), {scene.add_material(black_card(alpha))});
    scene.set_background(glm::vec3(1.0f));
    const Camera camera = Camera::look_at({0.0, 0.0, 2.0}, {0.0, 0.0, 0.0}, {0, 1, 0}, 0.5, 8, 8);
    for (const bool transparent_background : {false, true}) {
      RenderSettings settings = settings_with(16);
      settings.transparent_background = transparent_background;
      FrameBuffers frame;
      render(scene, camera, settings, frame);
      CAPTURE(alpha, transparent_background);
      // Seen through the card the background keeps 1 - alpha; a transparent background gives
      // nothing, and the film's coverage is the card's alpha.
      for (float v : frame.color) CHECK(v == Approx(transparent_background ? 0.0 : 1.0 - alpha).margin(1e-6));
      for (float a : frame.alpha) CHECK(a == Approx(alpha).margin(1e-6));
    }
  }
}

TEST_CASE("A card of constant alpha passes exactly 1 - alpha to shadow rays", "[render]") {
  const FrameBuffers open = ShadowScene(nullptr).render_frame();
  for (const float alpha : {0.0f, 0.3f, 0.9f, 1.0f}) {
    const Material card = black_card(alpha);
    const FrameBuffers shadowed = ShadowScene(&card).render_frame();
    CAPTURE(alpha);
    // The same samples meet the same floor points and the same lamp: only the card differs.
    for (size_t i = 0; i < open.color.size(); ++i) {
      if (!(open.color[i] > 0.0f)) continue;
      CHECK(shadowed.color[i] == Approx((1.0 - alpha) * open.color[i]).epsilon(1e-5));
    }
  }
}

TEST_CASE("A cut-out texture casts a shadow of its shape", "[render]") {
  // A 4 x 4 checker of alpha 0 and 1 on the card (uv = card position, square side 2 m at
  // z = 1); the lamp at z = 2 projects it onto the floor at twice its size. A floor point p is
  // lit where the segment to the lamp crosses the card at an open texel: there, at
  // q = (p + lamp) / 2, uv = (q.xy + 1) / 2. Pixels whose crossing lies within a tenth of a texel
  // of a texel centre (where bilinear filtering keeps 81 % of the texel) are checked.
  std::vector<uint8_t> checker(16);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) checker[static_cast<size_t>(4 * y + x)] = (x + y) % 2 ? 255 : 0;
  Material card = black_card(1.0f);
  card[MaterialParameter::Alpha].texture =
      Texture::from_pixels8(4, 4, 1, checker.data(), ColorSpace::NonColor, TextureWrap::Clamp, "checker");
  ShadowScene lit(nullptr);
  const FrameBuffers open = lit.render_frame();
  const FrameBuffers shadowed = ShadowScene(&card).render_frame();

  int checked_open = 0, checked_blocked = 0;
  const double half_extent = 3.0 * 0.5;  // the camera sees [-1.5, 1.5]^2 of the floor from 0.5 m
  for (int py = 0; py < 64; ++py)
    for (int px = 0; px < 64; ++px) {
      // Row 0 is the image top, +Y up in the image: the camera's up is the world's +Y.
      const double x = -half_extent + 2.0 * half_extent * (px + 0.5) / 64.0;
      const double y = half_extent - 2.0 * half_extent * (py + 0.5) / 64.0;
      const glm::dvec2 uv = (glm::dvec2(x, y) / 2.0 + 1.0) / 2.0;
      if (uv.x <= 0.0 || uv.x >= 1.0 || uv.y <= 0.0 || uv.y >= 1.0) continue;
      const glm::dvec2 texel = uv * 4.0;
      const glm::dvec2 from_centre = glm::abs(glm::fract(texel) - 0.5);
      if (from_centre.x > 0.1 || from_centre.y > 0.1) continue;
      // Texture rows run bottom to top in v.
      const int tx = static_cast<int>(texel.x), ty = 3 - static_cast<int>(texel.y);
      const bool opaque = checker[static_cast<size_t>(4 * ty + tx)] == 255;
      const size_t i = 3 * static_cast<size_t>(64 * py + px);
      const double ratio = shadowed.color[i] / open.color[i];
      CAPTURE(px, py, uv.x, uv.y, opaque, ratio);
      if (opaque) {
        CHECK(ratio <= 0.2);
        ++checked_blocked;
      } else {
        CHECK(ratio >= 0.8);
        ++checked_open;
      }
    }
  CHECK(checked_open > 20);
  CHECK(checked_blocked > 20);
}

TEST_CASE("The transparent bounce limit stops camera rays as Cycles does", "[render]") {
  // Cards before a white background. Cycles keeps every limit one above its setting: with the
  // default 8, a camera ray passes 9 cards and ends at the 10th. Cards of alpha 0 keep the
  // throughput at 1, where Russian roulette never ends a path, so the limit alone decides.
  // Three cards of alpha 0.5 pass 1/8 (roulette, from the second transparent bounce on, keeps
  // half of 8 stratified samples at double weight: still exactly 1/8).
  struct Stack {
    int cards;
    float alpha;
    double expected;
  };
  for (const Stack stack : {Stack{3, 0.5f, 0.125}, Stack{9, 0.0f, 1.0}, Stack{10, 0.0f, 0.0}}) {
    Scene scene;
    const uint32_t material = scene.add_material(black_card(stack.alpha));
    for (int k = 0; k < stack.cards; ++k) scene.add_mesh(test_scenes::horizontal_square(4.0, 0.1 * k), {material});
    scene.set_background(glm::vec3(1.0f));
    FrameBuffers frame;
    render(scene, Camera::look_at({0.0, 0.0, 3.0}, {0.0, 0.0, 0.0}, {0, 1, 0}, 0.3, 4, 4), settings_with(8), frame);
    CAPTURE(stack.cards, stack.alpha);
    for (float v : frame.color) CHECK(v == Approx(stack.expected).margin(1e-7));
  }
}

TEST_CASE("A scene with alpha 0 everywhere shows its background, finite", "[render]") {
  Scene scene;
  Material glass_ghost;
  glass_ghost.set(MaterialParameter::Transmission, 1.0f);
  glass_ghost.set(MaterialParameter::Clearcoat, 1.0f);
  glass_ghost.set(MaterialParameter::Emission, glm::vec3(1.0f));
  glass_ghost.set(MaterialParameter::Alpha, 0.0f);
  scene.add_mesh(test_scenes::uv_sphere(0.5, 16), {scene.add_material(glass_ghost)});
  Material ghost = test_scenes::lambert(0.8f);
  ghost.set(MaterialParameter::Alpha, 0.0f);
  scene.add_mesh(test_scenes::horizontal_square(4.0, -0.5), {scene.add_material(ghost)});
  scene.add_lamp(PointLamp{glm::dvec3(0.0, 0.0, 2.0), 100.0, glm::dvec3(1.0)});
  scene.set_background(glm::vec3(0.25f));
  FrameBuffers frame;
  const RenderStats stats =
      render(scene, Camera::look_at({0.0, -3.0, 0.5}, {0.0, 0.0, 0.0}, {0, 0, 1}, 0.8, 16, 16), settings_with(8), frame);
  CHECK(stats.discarded_samples == 0);
  for (float v : frame.color) CHECK(v == Approx(0.25).margin(1e-6));
  for (float a : frame.alpha) CHECK(a == Approx(0.0).margin(1e-6));
}
