// ShadingFrame (orthonormal basis around a normal) and ensure_valid_reflection (Cycles' repair of
// shading normals whose mirror reflection would dip below the geometric surface).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "matbase/pi.h"
#include "uniform_floats.h"
#include "bsdf/shading_frame.h"

using matrender::ensure_valid_reflection;
using matrender::ShadingFrame;

namespace {

constexpr float kPi = matbase::kPiAs<float>;

bool is_finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

glm::vec3 reflect(const glm::vec3& wo, const glm::vec3& n) {
  return 2.0f * glm::dot(n, wo) * n - wo;
}

// The height above the geometric surface a reflected ray must keep (Cycles 3.4,
// ensure_valid_reflection): min(0.9 ng.wo, 0.01).
float reflection_threshold(const glm::vec3& ng, const glm::vec3& wo) {
  return std::min(0.9f * glm::dot(ng, wo), 0.01f);
}

// Unit vector at angle `angle` from `axis` towards the unit vector `towards` (not parallel).
glm::vec3 tilted(const glm::vec3& axis, const glm::vec3& towards, float angle) {
  const glm::vec3 side = glm::normalize(towards - glm::dot(towards, axis) * axis);
  return glm::normalize(std::cos(angle) * axis + std::sin(angle) * side);
}

}  // namespace

TEST_CASE("ShadingFrame is orthonormal and right-handed for every normal", "[render]") {
  // The axes, and normals in the tangent plane with z = -0 (copysign sees the sign of zero).
  std::vector<glm::vec3> normals = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0},     {0, -1, 0},
                                    {0, 0, 1}, {0, 0, -1}, {1, 0, -0.0f}, {0, 1, -0.0f}};
  // Around the pole n.z = -1, where the basis of Frisvad 2012 breaks down (Duff et al. 2017).
  for (float tiny : {1e-30f, 1e-20f, 1e-10f, 1e-7f, 1e-5f, 1e-3f}) {
    for (float sx : {-1.0f, 0.0f, 1.0f}) {
      for (float sy : {-1.0f, 0.0f, 1.0f}) {
        normals.push_back(glm::normalize(glm::vec3(sx * tiny, sy * tiny, -1.0f)));
        normals.push_back(glm::normalize(glm::vec3(sx * tiny, sy * tiny, 1.0f)));
        normals.push_back(glm::normalize(glm::vec3(1.0f, sx * tiny, sy * tiny)));
      }
    }
  }
  UniformFloats rng(0x5eed2000);
  for (int n = 0; n < 10000; ++n) normals.push_back(random_unit_vector(rng));

  for (const glm::vec3& n : normals) {
    const ShadingFrame f = ShadingFrame::from_normal(n);
    INFO("n = (" << n.x << ", " << n.y << ", " << n.z << ")");
    REQUIRE((is_finite(f.x) && is_finite(f.y)));
    CHECK(glm::length(f.x) == Approx(1.0f).margin(1e-6f));
    CHECK(glm::length(f.y) == Approx(1.0f).margin(1e-6f));
    CHECK(std::abs(glm::dot(f.x, f.y)) < 1e-6f);
    CHECK(std::abs(glm::dot(f.x, f.z)) < 1e-6f);
    CHECK(std::abs(glm::dot(f.y, f.z)) < 1e-6f);
    CHECK(glm::length(glm::cross(f.x, f.y) - f.z) < 1e-6f);
    const glm::vec3 v = random_unit_vector(rng);
    CHECK(glm::length(f.to_world(f.to_local(v)) - v) < 1e-6f);
    CHECK(f.to_local(n).z == Approx(1.0f).margin(1e-6f));
  }
}

TEST_CASE("ensure_valid_reflection keeps a shading normal whose reflection is valid", "[render]") {
  UniformFloats rng(0x5eed2100);
  int kept = 0;
  for (int n = 0; n < 20000; ++n) {
    const glm::vec3 ng = random_unit_vector(rng);
    glm::vec3 wo = random_unit_vector(rng);
    if (glm::dot(wo, ng) < 0.0f) wo = -wo;
    // Shading normals within 40 degrees of ng, as smooth shading and normal maps make them.
    const glm::vec3 shading = tilted(ng, random_unit_vector(rng), 0.7f * rng.next());
    const float height = glm::dot(ng, reflect(wo, shading));
    if (height < reflection_threshold(ng, wo) + 1e-5f) continue;  // not clearly valid
    const glm::vec3 result = ensure_valid_reflection(ng, wo, shading);
    CHECK(result.x == shading.x);
    CHECK(result.y == shading.y);
    CHECK(result.z == shading.z);
    ++kept;
  }
  CHECK(kept > 10000);
}

TEST_CASE("ensure_valid_reflection lifts the reflection of bent normals above the surface",
          "[render]") {
  // The returned normal is unit, and wo mirrored about it leaves above the surface, for grazing
  // views and shading normals bent far from ng, past the horizon and behind the surface. When
  // wo lies in the plane of ng and n the new normal's reflection reaches min(0.9 ng.wo, 0.01)
  // exactly. Otherwise both roots of Cycles' quadratic can reflect above the surface and Cycles
  // keeps the shallower one (bsdf_util.h: "return the one with the shallower reflection"),
  // which may sit below that threshold but never below the surface. Tolerance 1e-5: ten times
  // the float rounding of a height computed from float unit vectors.
  const glm::vec3 ng(0.0f, 0.0f, 1.0f);
  UniformFloats rng(0x5eed2200);
  struct Case {
    glm::vec3 ng, wo, n;
    bool in_plane;
  };
  std::vector<Case> cases;
  for (float cos_o : {1e-4f, 1e-3f, 0.01f, 0.05f, 0.2f, 0.5f, 0.9f, 1.0f}) {
    const glm::vec3 wo(std::sqrt(1.0f - cos_o * cos_o), 0.0f, cos_o);
    // Normals tilted in the plane of incidence (away from and towards wo) and across it.
    for (float angle = -3.1f; angle <= 3.1f; angle += 0.05f) {
      cases.push_back({ng, wo, glm::vec3(std::sin(angle), 0.0f, std::cos(angle)), true});
      cases.push_back({ng, wo, glm::vec3(0.0f, std::sin(angle), std::cos(angle)), false});
      cases.push_back(
          {ng, wo, glm::normalize(glm::vec3(std::sin(angle), std::sin(angle), std::cos(angle))), false});
    }
  }
  for (int n = 0; n < 20000; ++n) {
    // Random geometric normals, views from grazing to normal, any shading normal in front of
    // or behind the surface.
    const glm::vec3 random_ng = random_unit_vector(rng);
    glm::vec3 wo = random_unit_vector(rng);
    if (glm::dot(wo, random_ng) < 0.0f) wo = -wo;
    if (n % 2) wo = tilted(random_ng, wo, 0.5f * kPi - 0.05f * rng.next());  // grazing
    cases.push_back({random_ng, wo, random_unit_vector(rng), false});
  }

  int bent = 0;
  for (const Case& c : cases) {
    const glm::vec3 result = ensure_valid_reflection(c.ng, c.wo, c.n);
    INFO("ng (" << c.ng.x << ", " << c.ng.y << ", " << c.ng.z << "), wo (" << c.wo.x << ", "
                << c.wo.y << ", " << c.wo.z << "), n (" << c.n.x << ", " << c.n.y << ", " << c.n.z
                << ") -> (" << result.x << ", " << result.y << ", " << result.z << ")");
    REQUIRE(is_finite(result));
    CHECK(glm::length(result) == Approx(1.0f).margin(1e-5f));
    const float height = glm::dot(c.ng, reflect(c.wo, result));
    if (c.in_plane) {
      CHECK(height >= reflection_threshold(c.ng, c.wo) - 1e-5f);
    } else {
      CHECK(height > 0.0f);
    }
    bent += result != c.n;
  }
  CHECK(bent > 1000);
}

TEST_CASE("ensure_valid_reflection is finite for degenerate inputs", "[render]") {
  UniformFloats rng(0x5eed2300);
  for (int n = 0; n < 1000; ++n) {
    const glm::vec3 ng = random_unit_vector(rng);
    glm::vec3 wo = random_unit_vector(rng);
    if (glm::dot(wo, ng) < 0.0f) wo = -wo;
    const glm::vec3 tangent = glm::normalize(glm::cross(ng, random_unit_vector(rng)));
    struct Case {
      glm::vec3 wo, n;
    };
    for (const Case& c :
         {Case{wo, -ng}, Case{wo, ng}, Case{ng, ng}, Case{ng, -ng}, Case{ng, tangent}, Case{wo, wo},
          Case{tangent, ng}, Case{tangent, -ng}, Case{tangent, tangent}}) {
      const glm::vec3 result = ensure_valid_reflection(ng, c.wo, c.n);
      INFO("ng (" << ng.x << ", " << ng.y << ", " << ng.z << "), wo (" << c.wo.x << ", " << c.wo.y
                  << ", " << c.wo.z << "), n (" << c.n.x << ", " << c.n.y << ", " << c.n.z << ")");
      REQUIRE(is_finite(result));
      CHECK(glm::length(result) == Approx(1.0f).margin(1e-5f));
    }
  }
}
