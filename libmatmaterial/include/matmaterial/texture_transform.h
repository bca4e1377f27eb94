#pragma once
// A texture's own placement on the UVs, as glTF's KHR_texture_transform gives it: offset,
// rotation and scale in glTF's UV space (v down from the image's top), applied as
// uv' = T(offset) R(rotation) S(scale) uv with R = [cos r, sin r; -sin r, cos r]. Our UVs are
// Blender's (v up), so the map is v -> 1 - v, that, and v -> 1 - v again. That is the Mapping
// node Blender 3.4's importer puts before the image (texture_transform_gltf_to_blender:
// location (ox + sy sin r, 1 - oy - sy cos r), rotation Z = r, scale (sx, sy)).
#include <glm/glm.hpp>

namespace matmaterial {

// What a lookup outside [0, 1] reads: the image repeated, or its edge texels (glTF's sampler
// REPEAT and CLAMP_TO_EDGE, Blender's Image Texture extension Repeat and Extend).
enum class TextureWrap { Repeat, Clamp };

struct TextureTransform {
  glm::dvec2 offset{0.0};
  double rotation = 0.0;  // radians
  glm::dvec2 scale{1.0};

  bool is_identity() const { return *this == TextureTransform{}; }
  bool operator==(const TextureTransform& o) const {
    return offset == o.offset && rotation == o.rotation && scale == o.scale;
  }
};

// The transform as an affine map of our (v up) UVs: uv' = linear * uv + translation.
struct UvAffine {
  glm::mat2 linear{1.0f};
  glm::vec2 translation{0.0f};
  // How much wider a footprint of the UVs becomes: the larger singular value of `linear`, which
  // for a rotation times a scale is the larger |scale|.
  float stretch = 1.0f;

  glm::vec2 apply(glm::vec2 uv) const { return linear * uv + translation; }
  bool operator==(const UvAffine& other) const { return linear == other.linear && translation == other.translation; }
};

UvAffine uv_affine(const TextureTransform& transform);

}  // namespace matmaterial
