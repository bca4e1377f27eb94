// KHR_texture_transform on our (Blender's, v up) UVs against the extension's own definition in
// glTF's UVs (v down): flip v, apply T(offset) R(rotation) S(scale) as the specification writes
// the 3 x 3 matrices, flip v back.
#include <cmath>

#include <catch2/catch.hpp>

#include "matmaterial/texture_transform.h"

using namespace matmaterial;

namespace {

glm::dvec2 by_the_specification(const matmaterial::TextureTransform& t, glm::dvec2 uv) {
  const glm::dmat3 translation(1, 0, 0, 0, 1, 0, t.offset.x, t.offset.y, 1);  // column-major
  const double c = std::cos(t.rotation), s = std::sin(t.rotation);
  // The specification's rows [cos sin 0; -sin cos 0; 0 0 1], as columns.
  const glm::dmat3 rotation(c, -s, 0, s, c, 0, 0, 0, 1);
  const glm::dmat3 scale(t.scale.x, 0, 0, 0, t.scale.y, 0, 0, 0, 1);
  const glm::dvec3 gltf = translation * rotation * scale * glm::dvec3(uv.x, 1.0 - uv.y, 1.0);
  return {gltf.x, 1.0 - gltf.y};
}

}  // namespace

TEST_CASE("A texture transform maps our UVs as KHR_texture_transform maps glTF's", "[geom]") {
  for (const matmaterial::TextureTransform t : {matmaterial::TextureTransform{}, matmaterial::TextureTransform{{0.5, -0.25}, 0.0, {1.0, 1.0}},
                                   matmaterial::TextureTransform{{0.0, 0.0}, 1.2, {1.0, 1.0}},
                                   matmaterial::TextureTransform{{0.1, 0.7}, -2.5, {3.0, -0.5}}}) {
    const matmaterial::UvAffine affine = matmaterial::uv_affine(t);
    for (const glm::dvec2 uv : {glm::dvec2(0.0), glm::dvec2(1.0), glm::dvec2(0.25, 0.9), glm::dvec2(-3.0, 7.5)}) {
      const glm::dvec2 expected = by_the_specification(t, uv);
      const glm::vec2 got = affine.apply(glm::vec2(uv));
      CAPTURE(t.offset.x, t.offset.y, t.rotation, t.scale.x, t.scale.y, uv.x, uv.y);
      CHECK(got.x == Approx(expected.x).margin(1e-5));
      CHECK(got.y == Approx(expected.y).margin(1e-5));
    }
  }
  CHECK(matmaterial::uv_affine(matmaterial::TextureTransform{}) == matmaterial::UvAffine{});
}

TEST_CASE("A texture transform widens a footprint by its larger scale, whatever the rotation", "[geom]") {
  CHECK(matmaterial::uv_affine(matmaterial::TextureTransform{}).stretch == Approx(1.0f));
  CHECK(matmaterial::uv_affine(matmaterial::TextureTransform{{0.3, 0.3}, 0.8, {4.0, 0.5}}).stretch == Approx(4.0f));
  CHECK(matmaterial::uv_affine(matmaterial::TextureTransform{{0.0, 0.0}, -2.0, {0.25, -3.0}}).stretch == Approx(3.0f));
}
