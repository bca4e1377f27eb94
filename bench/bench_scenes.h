#pragma once
// Scenes the benchmarks render: procedural meshes of a chosen size (lit and seen with
// matrender/paper_setup.h), the benchmarks' material, and memory figures.
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

// The benchmarks' plain material: an orange-brown dielectric, roughness 0.35, no textures.
matrender::Material bench_material();

// Peak resident memory since the last reset, and resident memory now, in MiB (Linux /proc).
double peak_rss_mib();
double rss_mib();
void reset_peak_rss();

}  // namespace bench
