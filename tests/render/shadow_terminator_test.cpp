// The pieces of Cycles' shadow-terminator handling against what they are meant to compute: the
// smooth-surface offset lifts a sphere's facet onto the lower envelope of its vertices' tangent
// planes (Hanika 2021: outside the sphere, so that the shadow ray clears the neighbouring facets),
// vanishes on a flat triangle, and the bump shadowing term follows its closed form (Chiang, Li,
// Burley 2019).
#include <algorithm>
#include <cmath>

#include <catch2/catch.hpp>

#include "bsdf/bump_shadowing.h"
#include "integrator/shadow_terminator.h"
#include "matbase/pi.h"

using namespace matrender;

TEST_CASE("Smooth-surface offset is zero on a flat triangle", "[render]") {
  const std::array<glm::vec3, 3> v = {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)};
  const std::array<glm::vec3, 3> n = {glm::vec3(0, 0, 1), glm::vec3(0, 0, 1), glm::vec3(0, 0, 1)};
  for (const glm::vec3 w : {glm::vec3(1.0f / 3.0f), glm::vec3(0.7f, 0.2f, 0.1f), glm::vec3(0.0f, 0.5f, 0.5f)})
    CHECK(glm::length(smooth_surface_offset(v, n, w, glm::vec3(0, 0, 1))) == 0.0f);
}

TEST_CASE("Smooth-surface offset lifts a sphere's facet onto its tangent planes", "[render]") {
  // A facet of a unit sphere, about 25 degrees across, with radial vertex normals.
  const auto on_sphere = [](float theta, float phi) {
    return glm::vec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
  };
  const std::array<glm::vec3, 3> v = {on_sphere(0.2f, 0.0f), on_sphere(0.5f, -0.4f), on_sphere(0.6f, 0.3f)};
  const std::array<glm::vec3, 3> n = v;
  const glm::vec3 ng = glm::normalize(glm::cross(v[1] - v[0], v[2] - v[0]));
  REQUIRE(glm::dot(ng, v[0]) > 0.0f);  // outward
  for (const glm::vec3 w : {glm::vec3(1.0f / 3.0f), glm::vec3(0.6f, 0.3f, 0.1f), glm::vec3(0.1f, 0.45f, 0.45f)}) {
    const glm::vec3 flat = w.x * v[0] + w.y * v[1] + w.z * v[2];
    const glm::vec3 lifted = flat + smooth_surface_offset(v, n, w, ng);
    INFO("weights " << w.x << " " << w.y << " " << w.z << ": flat " << glm::length(flat) << ", lifted "
                    << glm::length(lifted));
    // The flat point lies inside the sphere; the lifted one between the sphere and the lowest of
    // the three tangent planes.
    CHECK(glm::length(flat) < 0.99f);
    CHECK(glm::length(lifted) >= 1.0f);
    float highest = -1.0f;
    for (int i = 0; i < 3; ++i) highest = std::max(highest, glm::dot(lifted - v[i], n[i]));
    CHECK(highest <= 1e-5f);
  }
  // Seen from the inside (geometric normal inward), the point is lowered instead.
  const glm::vec3 w(1.0f / 3.0f);
  CHECK(glm::dot(smooth_surface_offset(v, n, w, -ng), ng) < 0.0f);
}

TEST_CASE("Terminator offset amount: all of it at the terminator, none well inside the light", "[render]") {
  constexpr float kCutoff = 0.1f;
  CHECK(shadow_terminator_offset_amount(0.02f, -0.05f, kCutoff) == 1.0f);  // light below the facet
  CHECK(shadow_terminator_offset_amount(0.5f, 0.5f, kCutoff) == 0.0f);     // well lit
  CHECK(shadow_terminator_offset_amount(0.5f, 0.05f, kCutoff) == Approx(0.5f));
  CHECK(shadow_terminator_offset_amount(0.06f, 0.06f, kCutoff) == Approx(0.8f));
}

TEST_CASE("Bump shadowing term follows its closed form", "[render]") {
  // Smooth normal tilted by 20 degrees from the shading normal (+Z) toward +X.
  const float tilt = 20.0f * static_cast<float>(matbase::kPi) / 180.0f;
  const glm::vec3 smooth(std::sin(tilt), 0.0f, std::cos(tilt));
  for (int k = 1; k < 90; ++k) {
    const float angle = static_cast<float>(k) * static_cast<float>(matbase::kPi) / 180.0f;  // from +Z toward -X
    const glm::vec3 wi(-std::sin(angle), 0.0f, std::cos(angle));
    const double g = (double(smooth.x) * wi.x + double(smooth.z) * wi.z) / (double(wi.z) * smooth.z);
    const double expected = g >= 1.0 ? 1.0 : g < 0.0 ? 0.0 : -g * g * g + g * g + g;
    INFO("angle " << k << " degrees, G = " << g);
    CHECK(bump_shadowing_term(smooth, wi) == Approx(expected).margin(1e-5));
  }
  // Light toward the side the smooth normal leans to is not shadowed at all.
  CHECK(bump_shadowing_term(smooth, glm::normalize(glm::vec3(0.5f, 0.0f, 0.5f))) == 1.0f);
  // Below the smooth surface: black.
  CHECK(bump_shadowing_term(smooth, glm::normalize(glm::vec3(-1.0f, 0.0f, 0.2f))) == 0.0f);
}
