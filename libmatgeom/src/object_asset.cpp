#include "matgeom/object_asset.h"

#include <stdexcept>

#include "matgeom/mesh_parts.h"

namespace matgeom {

ObjectAsset kept_parts(const ObjectAsset& asset, const std::vector<bool>& keep) {
  std::vector<MeshPart> parts;
  for (MeshPart& part : split_parts(asset.mesh))
    if (part.id < keep.size() && keep[part.id]) parts.push_back(std::move(part));
  if (parts.empty()) throw std::invalid_argument("kept_parts: no part kept has a triangle");
  ObjectAsset kept;
  kept.mesh = merge_parts(parts);
  for (const MeshPart& part : parts)
    kept.materials.push_back(part.id < asset.materials.size() ? asset.materials[part.id]
                                                                : matmaterial::MaterialInputs(part.name));
  kept.images = asset.images;
  kept.notes = asset.notes;
  return kept;
}

}  // namespace matgeom
