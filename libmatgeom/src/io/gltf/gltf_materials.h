#pragma once
// glTF materials to MaterialInputs, as Blender 3.4's glTF importer builds its node setups
// (docs/conventions.md), with the images they reference and the UV set each samples.
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/gltf/gltf_file.h"
#include "matbase/image/image_pixels.h"
#include "matmaterial/material_inputs.h"

namespace matgeom::gltf {

struct ConvertedMaterial {
  matmaterial::MaterialInputs inputs;
  // The UV set (TEXCOORD_n) its textures sample; none when it has no texture. MaterialInputs has
  // one UV set, so a material whose textures name two is refused.
  std::optional<int> uv_set;
};

class GltfMaterials {
 public:
  explicit GltfMaterials(const GltfFile& file);
  ~GltfMaterials();
  GltfMaterials(const GltfMaterials&) = delete;
  GltfMaterials& operator=(const GltfMaterials&) = delete;

  // Material `index` of the file, converted on first use. Throws std::runtime_error naming the
  // path, the material and the member for a value it cannot read.
  const ConvertedMaterial& material(size_t index);

  // The images the converted materials reference, in order of first reference.
  std::vector<matbase::ImagePixels> take_images();
  // What the converted materials hold that is not applied, a sentence each, each said once.
  std::vector<std::string> take_notes();

  // The state of a conversion (images, notes, the UV set of the material at hand), opaque.
  struct Conversion;

 private:
  const GltfFile& file_;
  std::unique_ptr<Conversion> conversion_;
  std::map<size_t, ConvertedMaterial> converted_;
};

}  // namespace matgeom::gltf
