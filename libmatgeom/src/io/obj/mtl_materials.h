#pragma once
// MTL materials to MaterialInputs: the Principled BSDF Blender's OBJ importer builds from each
// material the parts use, with its textures.
#include <string>
#include <vector>

#include "matgeom/object_asset.h"
#include "io/obj/obj_loading.h"
#include "io/obj/obj_parts.h"

namespace matgeom::obj {

// Every part's MaterialInputs, each file material converted once.
// What the materials hold that is not applied is added to `notes`.
std::vector<matmaterial::MaterialInputs> part_materials(const ObjFile& file, const PartTable& parts,
                                         std::vector<matbase::ImagePixels>& images, std::vector<std::string>& notes);

}  // namespace matgeom::obj
