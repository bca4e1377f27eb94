#pragma once
// Assembling a built-in object, the one way every built-in object is made: pieces of geometry
// added part by part, each part with its material, then the paper's UV pass over the whole (or,
// for an object whose pieces carry UVs of their own, those UVs).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "builtin/materials.h"
#include "matbase/uniform_source.h"
#include "matgeom/object_asset.h"

namespace matgeom::builtin {

class ObjectBuilder {
 public:
  explicit ObjectBuilder(uint32_t seed) : random_(seed) {}

  // Shape parameters and materials draw from this, so a seed fixes the object.
  matbase::UniformSource& random() { return random_; }

  // A new part (material slot) named `name` with a material of `finish`; returns its id.
  uint32_t add_part(const std::string& name, Finish finish);
  // A new part with a material of its own (images it names come from add_image); returns its id.
  uint32_t add_part(const std::string& name, const matmaterial::MaterialInputs& material);
  // An image for materials to name; returns its index.
  int add_image(matbase::ImagePixels image);

  // Appends a closed piece of geometry (positions and normals) to part `part`.
  void add(uint32_t part, const TriangleMesh& piece);
  // Appends a piece with UVs of its own whose triangle parts are ids add_part returned. An object
  // made of such pieces keeps their UVs: finish() makes no UV pass.
  void add_uv_mapped(const TriangleMesh& piece);

  // Runs the UV pass (charts, LSCM, packing at the paper's texel density into
  // kBuiltinTileResolution tiles), which also makes tangents, repeats each finish's maps to
  // their physical size on its part, and returns the object; an object of UV-mapped pieces gets
  // tangents from its own UVs instead.
  ObjectAsset finish();

 private:
  // The finishes' library maps at their physical size on the object's UVs.
  void repeat_maps_to_size();

  matbase::UniformSource random_;
  ObjectAsset asset_;
  std::vector<std::optional<double>> tile_sizes_;  // by part: its library maps' physical size
  size_t uv_mapped_pieces_ = 0;
  size_t plain_pieces_ = 0;
};

}  // namespace matgeom::builtin
