#pragma once
// An object ready to render: its mesh (one part per material slot), the slots' Principled
// materials and the 8-bit images they reference. Produced by the mesh readers and the built-in
// objects; libmatrender turns it into scene materials (matrender/asset.h).
#include <algorithm>
#include <string>
#include <utility>
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

// The parts k of the asset with keep[k] (parts beyond keep's size are dropped), alone: their
// triangles and the vertices they use, renumbered in order with their names and materials; the
// images and notes stay. Throws std::invalid_argument when no kept part has a triangle.
ObjectAsset kept_parts(const ObjectAsset& asset, const std::vector<bool>& keep);

// Adds `note` to `notes` unless it is there already: each note is said once.
inline void add_note(std::vector<std::string>& notes, std::string note) {
  if (std::find(notes.begin(), notes.end(), note) == notes.end()) notes.push_back(std::move(note));
}

}  // namespace matgeom
