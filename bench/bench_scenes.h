#pragma once
// Scenes the benchmarks render: procedural meshes of a chosen size (lit and seen with
// matrender/paper_setup.h), the benchmarks' material, and memory figures.
#include <cstddef>
#include <string>
#include <vector>

#include "matgeom/mesh.h"
#include "matmaterial/material_inputs.h"
#include "matrender/camera.h"
#include "matrender/lamp.h"
#include "matrender/material.h"
#include "matrender/scene.h"
#include "matrender/scene_builder.h"

namespace bench {

// A bumpy closed sphere of radius about 0.3 m with close to `triangles` triangles.
matgeom::TriangleMesh displaced_sphere(size_t triangles);

// The benchmarks' plain material: an orange-brown dielectric, roughness 0.35, no textures; as an
// object file's material, and as the renderer's.
matmaterial::MaterialInputs bench_material_inputs();
matrender::Material bench_material();

// Built-in `object` (seed 0) in the library material `spec` ("metal:1"), its maps at
// `material_resolution` texels, under the paper's rig at its target illuminance.
matrender::BuiltScene builtin_in_library_material(const std::string& object, const std::string& spec,
                                                  int material_resolution);

// Cell (k, k) of a 2 x 2 grid about the scene's bounding sphere, which fills 90 % of a 50 mm
// lens's field of view: k = 0 looks from above, k = 1 from the side.
matrender::Camera framed_grid_view(const matrender::BuiltScene& built, int k, int resolution);

// Peak resident memory since the last reset, and resident memory now, in MiB (Linux /proc).
double peak_rss_mib();
double rss_mib();
void reset_peak_rss();

}  // namespace bench
