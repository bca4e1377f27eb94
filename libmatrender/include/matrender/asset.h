#pragma once
// Bringing a matgeom::ObjectAsset (glTF or built-in object) into a scene.
#include <cstdint>
#include <optional>
#include <vector>

#include "matgeom/object_asset.h"
#include "matrender/material.h"
#include "matrender/scene.h"

namespace matrender {

// Adds the asset's mesh and a material per part; returns the material id of each part. Part k
// uses material_overrides[k] when that is set (an id already in the scene), else the asset's own
// slot k (each input a constant or its image, in the colour space of the parameter table), else
// the default Material. Images are decoded once per colour space and wrap they are used with,
// and only for the slots that are used. `options` go to Scene::add_mesh.
std::vector<uint32_t> add_asset(Scene& scene, const matgeom::ObjectAsset& asset,
                                const std::vector<std::optional<uint32_t>>& material_overrides = {},
                                const MeshOptions& options = {});

// One material of matgeom's, its image indices into `images` (a material folder's, an asset's),
// as add_asset makes it: each input a constant or its image in the table's colour space.
Material material_from_desc(const matmaterial::MaterialInputs& desc, const std::vector<matbase::ImagePixels>& images);

}  // namespace matrender
