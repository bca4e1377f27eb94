#pragma once
// Assembling a built-in object: pieces of geometry added part by part, each part with its
// material, then the paper's UV pass over the whole.
#include <cstdint>
#include <string>

#include "builtin/materials.h"
#include "builtin/uniform_source.h"
#include "matgeom/object_asset.h"

namespace matgeom::builtin {

class ObjectBuilder {
 public:
  explicit ObjectBuilder(uint32_t seed) : random_(seed) {}

  // Shape parameters and materials draw from this, so a seed fixes the object.
  UniformSource& random() { return random_; }

  // A new part (material slot) named `name` with a material of `finish`; returns its id.
  uint32_t add_part(const std::string& name, Finish finish);
  // Appends a closed piece of geometry (positions and normals) to part `part`.
  void add(uint32_t part, const TriangleMesh& piece);

  // Runs the UV pass (charts, LSCM, packing at the paper's texel density into
  // kBuiltinTileResolution tiles), which also makes tangents, and returns the object.
  ObjectAsset finish();

 private:
  UniformSource random_;
  ObjectAsset asset_;
};

}  // namespace matgeom::builtin
