#pragma once
// Bringing a matgeom::ObjectAsset (glTF or built-in object) into a scene.
#include <cstdint>
#include <vector>

#include "matgeom/object_asset.h"
#include "matrender/material.h"
#include "matrender/scene.h"

namespace matrender {

// The renderer material Blender's importer would build from a glTF metallic-roughness slot.
Material material_from_desc(const matgeom::MaterialDesc& desc,
                            const std::vector<TexturePtr>& images_as_srgb,
                            const std::vector<TexturePtr>& images_as_data);

// Adds the asset's materials and mesh; returns the material ids it added, one per part.
std::vector<uint32_t> add_asset(Scene& scene, const matgeom::ObjectAsset& asset);

}  // namespace matrender
