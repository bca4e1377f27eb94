#pragma once
// How many metres of surface one unit of UV space covers, and materials whose maps repeat to
// match: a material folder says how long one repeat of its maps is on a surface (MatSynth's
// physical size), and a part's UVs say how long one UV unit is, so their ratio is how often the
// maps must repeat per UV unit for the texture to have its physical size.
#include <cstdint>
#include <optional>

#include "matgeom/mesh.h"
#include "matgeom/object_asset.h"
#include "matmaterial/folder/material_folder.h"

namespace matgeom {

// sqrt(surface area / UV area) over the triangles of `part`: the mean length one UV unit spans
// on the surface (exact for a UV layout that is an isometry up to a uniform scale, the UV pass's
// aim). None when the mesh has no UVs or the part no UV area.
std::optional<double> metres_per_uv_unit(const TriangleMesh& mesh, uint32_t part);

// The number of repeats per UV unit that gives maps covering `tile_size_m` their physical size on
// `part`; 1 when the part's UVs give no scale.
double texture_repeats(const TriangleMesh& mesh, uint32_t part, double tile_size_m);

// The material with every image it reads (parameters and normal map) repeated `repeats` times
// per UV unit, on top of the transform it has: an image placed at T(uv) is then looked up at
// T(repeats uv), scaled about the origin of our (Blender's, v-up) UVs as a Blender Mapping node's
// Scale does and as matrender::with_texture_repeats repeats it. In glTF's terms (v down) that is
// about (0, 1), so the transform's offset moves too.
matmaterial::MaterialInputs with_texture_repeats(const matmaterial::MaterialInputs& material, double repeats);

// Puts every part of `asset` in `material` (its images replace the asset's; the parts keep their
// names), its maps repeated to their physical size on each part's UVs when it has one.
void assign_material_to_all_parts(ObjectAsset& asset, const matmaterial::FolderMaterial& material);

}  // namespace matgeom
