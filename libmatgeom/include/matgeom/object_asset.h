#pragma once
// An object ready to render: its mesh (one part per material slot), the slots' Principled
// materials and the 8-bit images they reference. Produced by the mesh readers and the built-in
// objects; libmatrender turns it into scene materials (matrender/asset.h).
#include <string>
#include <vector>

#include "matbase/image/image_pixels.h"
#include "matgeom/mesh.h"
#include "matmaterial/material_inputs.h"

namespace matgeom {

struct ObjectAsset {
  TriangleMesh mesh;                     // part k uses materials[k]
  std::vector<matmaterial::MaterialInputs> materials;
  std::vector<matbase::ImagePixels> images;
  // What the file holds that the reader does not apply, or applies otherwise than Blender 3.4, a
  // sentence each, each said once ("the glTF extension \"KHR_materials_volume\" is not applied").
  // Tools show them once per file.
  std::vector<std::string> notes;
};

}  // namespace matgeom
