#pragma once
// The paper's "UV texture preprocessing" for every part of a mesh: texel-density
// normalisation, charts cut along sharp edges, conformal flattening (LSCM) and greedy packing
// into UDIM tiles with a fixed gutter, with a report per part.
#include <cstdint>
#include <string>
#include <vector>

#include "matgeom/mesh.h"
#include "matgeom/uv/chart_segmentation.h"
#include "matgeom/uv/uv_distortion.h"

namespace matgeom {

struct UvPassOptions {
  double texel_density_scale = 1.0;  // the paper's user scale s (it studies 0.1 .. 2)
  ChartOptions charts;
  // A chart whose L2 stretch (uv_distortion.h) exceeds this after flattening is halved and
  // flattened again: LSCM keeps angles but lets the scale drift across a curved chart, and the
  // texel density should hold everywhere, not only on average.
  double max_stretch = 1.2;
  // A chart covering less than this fraction of its bounding box (an arc flattened from a ring,
  // say) is halved too: packing places boxes, so the rest of the box would be wasted texture.
  double min_box_fill = 0.2;
  int tile_resolution = 4096;  // pixels per UDIM tile side (the paper's 4k material maps)
  int gutter_pixels = 2;
  bool keep_existing_uvs = false;  // only report on the mesh's own UVs
};

struct UvPartReport {
  std::string part;
  uint32_t charts = 0;
  uint32_t shrunk_charts = 0;  // single triangles larger than a tile, scaled down to fit
  int tiles = 0;
  UvDistortion distortion;
  // Chart area over the area the packing occupies: whole tiles before the last one, and the
  // used rectangle of the last tile (Packing::last_tile_width x last_tile_height).
  double packing_efficiency = 0.0;
  double target_density = 0.0;    // pixels per metre: s * target_texel_density(area)
  double achieved_density = 0.0;  // sqrt(UV area in pixels^2 / surface area)
};

struct UvPassResult {
  TriangleMesh mesh;  // same triangles and parts; vertices split along chart seams; new UVs
  std::vector<UvPartReport> parts;  // one per part that has triangles, in part order
};

// The paper's target: d = d0 (l / l0)^-1 with l = sqrt(A / pi), d0 = 512 px/m at l0 = 1 m.
double target_texel_density(double surface_area_m2);

// Each part is charted and packed on its own, starting at UDIM tile 0 (u in [0, 1)): parts take
// different materials, so their textures are separate images. A chart larger than a tile is
// halved (and re-flattened) until it fits, so the density holds unless a single triangle is
// larger than a tile (then that triangle is shrunk to fit and counted in the report). Tangents are
// recomputed for the new UVs when the mesh has normals (flat-shaded meshes get none). Throws
// std::invalid_argument for an invalid mesh or options.
UvPassResult uv_pass(const TriangleMesh& mesh, const UvPassOptions& options = {});

}  // namespace matgeom
