#pragma once
// Scenes the benchmarks render: procedural meshes of a chosen size under the paper's rig.
#include <cstddef>
#include <vector>

#include "matgeom/mesh.h"
#include "matrender/camera.h"
#include "matrender/light.h"
#include "matrender/material.h"
#include "matrender/scene.h"

namespace bench {

// A bumpy closed sphere of radius about 0.3 m with close to `triangles` triangles.
matgeom::TriangleMesh displaced_sphere(size_t triangles);

// The paper's light rig around the mesh (minimal enclosing sphere), normalised to 1 klx at its
// centre; add_paper_rig adds it to a scene.
std::vector<matrender::Light> paper_rig_lights(const matgeom::TriangleMesh& mesh);
void add_paper_rig(matrender::Scene& scene, const matgeom::TriangleMesh& mesh);

// The benchmarks' plain material: an orange-brown dielectric, roughness 0.35, no textures.
matrender::Material bench_material();

// Camera of the paper's grid, cell (5, 16) of 16 x 32, radius 1 m around the surface centroid.
matrender::Camera paper_camera(const matgeom::TriangleMesh& mesh, int width, int height);

// Peak resident memory since the last reset, and resident memory now, in MiB (Linux /proc).
double peak_rss_mib();
double rss_mib();
void reset_peak_rss();

}  // namespace bench
