#include "matgeom/uv/uv_pass.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <stdexcept>

#include "matbase/pi.h"
#include "matgeom/tangents.h"
#include "matgeom/uv/conformal_flattening.h"
#include "matgeom/uv/uv_packing.h"
#include "triangle_area.h"

namespace matgeom {
namespace {

// Triangles of the source mesh seen two ways: over their own (source) vertices, which keep
// their attributes in the output, and over vertices welded by position, which LSCM flattens so
// that attribute seams inside a chart do not tear it.
struct Chart {
  std::vector<uint32_t> triangles;           // source triangle indices
  std::vector<uint32_t> source_vertices;     // distinct source vertices, in order of first use
  std::vector<glm::uvec3> source_triangles;  // triangles over source_vertices
  std::vector<uint32_t> welded_of_source;    // welded vertex of each source_vertices entry
  std::vector<glm::dvec3> welded_positions;
  std::vector<glm::uvec3> welded_triangles;
  std::vector<glm::dvec2> uvs;  // per welded vertex, in tile units
  glm::dvec2 lower{0.0}, upper{0.0};  // UV bounds
  bool shrunk = false;  // scaled below the target density to fit in a tile
};

Chart make_chart(const TriangleMesh& mesh, std::vector<uint32_t> triangles) {
  Chart chart;
  chart.triangles = std::move(triangles);
  std::unordered_map<uint32_t, uint32_t> local_of_source;
  std::map<std::tuple<float, float, float>, uint32_t> welded_of_position;
  for (const uint32_t t : chart.triangles) {
    glm::uvec3 local, welded;
    for (int c = 0; c < 3; ++c) {
      const uint32_t v = mesh.triangles[t][c];
      const auto [it, inserted] = local_of_source.emplace(v, static_cast<uint32_t>(chart.source_vertices.size()));
      if (inserted) {
        chart.source_vertices.push_back(v);
        const glm::vec3& p = mesh.positions[v];
        const auto [w, new_position] = welded_of_position.emplace(
            std::make_tuple(p.x, p.y, p.z), static_cast<uint32_t>(chart.welded_positions.size()));
        if (new_position) chart.welded_positions.emplace_back(p);
        chart.welded_of_source.push_back(w->second);
      }
      local[c] = it->second;
      welded[c] = chart.welded_of_source[it->second];
    }
    chart.source_triangles.push_back(local);
    chart.welded_triangles.push_back(welded);
  }
  return chart;
}

std::vector<glm::dvec3> source_positions(const TriangleMesh& mesh, const Chart& chart) {
  std::vector<glm::dvec3> positions;
  for (const uint32_t v : chart.source_vertices) positions.emplace_back(mesh.positions[v]);
  return positions;
}

double surface_area(const std::vector<glm::dvec3>& p, const std::vector<glm::uvec3>& triangles) {
  double area = 0.0;
  for (const glm::uvec3& t : triangles) area += triangle_area(p[t.x], p[t.y], p[t.z]);
  return area;
}

double uv_area(const std::vector<glm::dvec2>& uv, const std::vector<glm::uvec3>& triangles) {
  double area = 0.0;
  for (const glm::uvec3& t : triangles) {
    const glm::dvec2 a = uv[t.y] - uv[t.x], b = uv[t.z] - uv[t.x];
    area += 0.5 * std::abs(a.x * b.y - a.y * b.x);
  }
  return area;
}

void update_bounds(Chart& chart) {
  chart.lower = glm::dvec2(std::numeric_limits<double>::max());
  chart.upper = glm::dvec2(std::numeric_limits<double>::lowest());
  for (const glm::dvec2& uv : chart.uvs) chart.lower = glm::min(chart.lower, uv), chart.upper = glm::max(chart.upper, uv);
}

glm::dvec2 rotated(const glm::dvec2& uv, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return glm::dvec2(c * uv.x - s * uv.y, s * uv.x + c * uv.y);
}

// Width and height of the bounding box of the points turned by `angle`.
glm::dvec2 rotated_box_size(const std::vector<glm::dvec2>& uvs, double angle) {
  glm::dvec2 lower(std::numeric_limits<double>::max()), upper(std::numeric_limits<double>::lowest());
  for (const glm::dvec2& uv : uvs) {
    const glm::dvec2 r = rotated(uv, angle);
    lower = glm::min(lower, r), upper = glm::max(upper, r);
  }
  return upper - lower;
}

// Rotation of the flattened chart with the smallest bounding box, in 3-degree steps, lying
// with its long side along u: LSCM's orientation is arbitrary (set by its pins), and tight, flat
// boxes make low shelves that waste little.
void rotate_to_smallest_box(Chart& chart) {
  double best_area = std::numeric_limits<double>::max(), best_angle = 0.0;
  for (int step = 0; step < 30; ++step) {
    const double angle = glm::radians(3.0 * step);
    const glm::dvec2 size = rotated_box_size(chart.uvs, angle);
    if (size.x * size.y < best_area) best_area = size.x * size.y, best_angle = angle;
  }
  const glm::dvec2 size = rotated_box_size(chart.uvs, best_angle);
  if (size.y > size.x) best_angle += 0.5 * matbase::kPi;
  for (glm::dvec2& uv : chart.uvs) uv = rotated(uv, best_angle);
  update_bounds(chart);
}

// Flattens the chart and scales it so that its UV area (in tile units) times resolution^2
// equals density^2 times its surface area: every chart has exactly the target density.
void flatten_at_density(Chart& chart, double density, int resolution) {
  chart.uvs = flatten_lscm(chart.welded_positions, chart.welded_triangles);
  const double area_3d = surface_area(chart.welded_positions, chart.welded_triangles);
  const double area_uv = uv_area(chart.uvs, chart.welded_triangles);
  const double scale = area_uv > 0.0 ? density / resolution * std::sqrt(area_3d / area_uv) : 0.0;
  for (glm::dvec2& uv : chart.uvs) uv *= scale;
  rotate_to_smallest_box(chart);
}

// Groups of the chart's triangles connected through (welded) edges, in order of first triangle:
// a piece joined to another at a single vertex would be free to turn about it.
std::vector<std::vector<uint32_t>> edge_connected_pieces(const Chart& chart) {
  std::vector<uint32_t> parent(chart.triangles.size());
  std::iota(parent.begin(), parent.end(), 0u);
  const auto root = [&](uint32_t k) {
    while (parent[k] != k) k = parent[k] = parent[parent[k]];
    return k;
  };
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> first_of_edge;
  for (uint32_t k = 0; k < chart.welded_triangles.size(); ++k)
    for (int c = 0; c < 3; ++c) {
      const uint32_t a = chart.welded_triangles[k][c], b = chart.welded_triangles[k][(c + 1) % 3];
      if (a == b) continue;
      const auto [it, inserted] = first_of_edge.emplace(std::minmax(a, b), k);
      if (!inserted) parent[root(k)] = root(it->second);
    }
  std::vector<std::vector<uint32_t>> pieces;
  std::map<uint32_t, size_t> piece_of_root;
  for (uint32_t k = 0; k < chart.triangles.size(); ++k) {
    const auto [it, inserted] = piece_of_root.emplace(root(k), pieces.size());
    if (inserted) pieces.emplace_back();
    pieces[it->second].push_back(chart.triangles[k]);
  }
  return pieces;
}

// Charts of one part, each flattened at the density, no larger than a tile allows, with an L2
// stretch within the bound and filling enough of its box: any other chart is halved at the
// median of its triangles along its longer UV side; a single triangle too large is scaled down to fit (and
// marked shrunk).
std::vector<Chart> flattened_charts(const TriangleMesh& mesh, std::vector<std::vector<uint32_t>> pending,
                                    double density, const UvPassOptions& options) {
  const double resolution = options.tile_resolution;
  const double usable = resolution - 2.0 * options.gutter_pixels - 1.0;  // the ceiling may add a pixel
  std::vector<Chart> charts;
  while (!pending.empty()) {
    Chart chart = make_chart(mesh, std::move(pending.back()));
    pending.pop_back();
    flatten_at_density(chart, density, options.tile_resolution);
    const glm::dvec2 size_px = (chart.upper - chart.lower) * resolution;
    const double largest = std::max(size_px.x, size_px.y);
    const bool splittable = chart.triangles.size() > 1 && largest > 0.0;
    const bool stretched =
        splittable &&
        measure_uv_distortion(chart.welded_positions, chart.welded_triangles, chart.uvs).stretch_l2 > options.max_stretch;
    const bool sparse = splittable && uv_area(chart.uvs, chart.welded_triangles) <
                                          options.min_box_fill * (chart.upper.x - chart.lower.x) * (chart.upper.y - chart.lower.y);
    if (largest <= usable && !stretched && !sparse) {
      charts.push_back(std::move(chart));
      continue;
    }
    if (chart.triangles.size() == 1) {
      for (glm::dvec2& uv : chart.uvs) uv *= usable / largest;
      update_bounds(chart);
      chart.shrunk = true;
      charts.push_back(std::move(chart));
      continue;
    }
    const int axis = size_px.x >= size_px.y ? 0 : 1;
    std::vector<std::pair<double, uint32_t>> keyed;
    for (size_t k = 0; k < chart.triangles.size(); ++k) {
      const glm::uvec3 t = chart.welded_triangles[k];
      keyed.emplace_back(chart.uvs[t.x][axis] + chart.uvs[t.y][axis] + chart.uvs[t.z][axis], chart.triangles[k]);
    }
    std::sort(keyed.begin(), keyed.end());
    const size_t half = keyed.size() / 2;
    for (const auto& [begin, end] : {std::pair{size_t{0}, half}, std::pair{half, keyed.size()}}) {
      std::vector<uint32_t> side;
      for (size_t k = begin; k < end; ++k) side.push_back(keyed[k].second);
      std::sort(side.begin(), side.end());
      for (std::vector<uint32_t>& piece : edge_connected_pieces(make_chart(mesh, side)))
        pending.push_back(std::move(piece));
    }
  }
  // A deterministic order whatever the splitting: by first source triangle.
  std::sort(charts.begin(), charts.end(), [](const Chart& a, const Chart& b) {
    return *std::min_element(a.triangles.begin(), a.triangles.end()) <
           *std::min_element(b.triangles.begin(), b.triangles.end());
  });
  return charts;
}

// The paper's density for the part's area times the user scale; 0 for a part without area (all
// its triangles degenerate), whose charts then collapse to points instead of growing without
// bound.
double part_target_density(const Chart& part, double scale) {
  const double area = surface_area(part.welded_positions, part.welded_triangles);
  return area > 0.0 ? scale * target_texel_density(area) : 0.0;
}

std::vector<std::vector<uint32_t>> part_triangles(const TriangleMesh& mesh) {
  std::vector<std::vector<uint32_t>> parts(mesh.part_count());
  for (size_t t = 0; t < mesh.triangle_count(); ++t)
    parts[mesh.triangle_parts.empty() ? 0 : mesh.triangle_parts[t]].push_back(static_cast<uint32_t>(t));
  return parts;
}

std::string part_name(const TriangleMesh& mesh, size_t part) {
  return part < mesh.part_names.size() ? mesh.part_names[part] : "part " + std::to_string(part);
}

void check_options(const UvPassOptions& options) {
  if (!(options.texel_density_scale > 0.0) || !std::isfinite(options.texel_density_scale))
    throw std::invalid_argument("uv_pass: the texel density scale must be positive");
  if (!(options.min_box_fill >= 0.0 && options.min_box_fill < 1.0))
    throw std::invalid_argument("uv_pass: the box fill bound must be in [0, 1)");
  if (!(options.max_stretch >= 1.0))
    throw std::invalid_argument("uv_pass: the stretch bound must be at least 1 (an isometry's stretch)");
  if (options.tile_resolution < 8 || options.gutter_pixels < 0 || 4 * options.gutter_pixels >= options.tile_resolution)
    throw std::invalid_argument("uv_pass: tile resolution " + std::to_string(options.tile_resolution) +
                                " and gutter " + std::to_string(options.gutter_pixels) + " do not make a usable tile");
}

// The report of a part whose UVs are final (tile-unit UVs on `mesh`).
UvPartReport measure_part(const TriangleMesh& mesh, const std::vector<uint32_t>& triangles, const std::string& name,
                          double target, int resolution) {
  const Chart whole = make_chart(mesh, triangles);
  const std::vector<glm::dvec3> positions = source_positions(mesh, whole);
  std::vector<glm::dvec2> uvs;
  for (const uint32_t v : whole.source_vertices) uvs.emplace_back(mesh.uvs[v]);
  UvPartReport report;
  report.part = name;
  report.distortion = measure_uv_distortion(positions, whole.source_triangles, uvs);
  report.target_density = target;
  const double area = surface_area(positions, whole.source_triangles);
  report.achieved_density = area > 0.0 ? resolution * std::sqrt(uv_area(uvs, whole.source_triangles) / area) : 0.0;
  return report;
}

}  // namespace

double target_texel_density(double surface_area_m2) {
  constexpr double kD0 = 512.0;  // px/m
  constexpr double kL0 = 1.0;    // m
  const double characteristic_length = std::sqrt(surface_area_m2 / matbase::kPi);
  return kD0 * kL0 / characteristic_length;
}

UvPassResult uv_pass(const TriangleMesh& mesh, const UvPassOptions& options) {
  validate_mesh(mesh, "uv_pass");
  check_options(options);
  const std::vector<std::vector<uint32_t>> parts = part_triangles(mesh);
  UvPassResult result;
  result.mesh = mesh;
  const int resolution = options.tile_resolution;

  if (options.keep_existing_uvs && !mesh.uvs.empty()) {
    for (size_t p = 0; p < parts.size(); ++p) {
      if (parts[p].empty()) continue;
      const Chart whole = make_chart(mesh, parts[p]);
      const double target = part_target_density(whole, options.texel_density_scale);
      result.parts.push_back(measure_part(mesh, parts[p], part_name(mesh, p), target, resolution));
    }
    return result;
  }

  TriangleMesh& out = result.mesh;
  out.positions.clear();
  out.normals.clear();
  out.uvs.clear();
  out.tangents.clear();
  out.colors.clear();
  for (size_t p = 0; p < parts.size(); ++p) {
    if (parts[p].empty()) continue;
    // The part as a compact surface: its area sets the density, its charts come from it.
    const Chart whole = make_chart(mesh, parts[p]);
    const double target = part_target_density(whole, options.texel_density_scale);
    const std::vector<uint32_t> chart_of = segment_charts(whole.welded_positions, whole.welded_triangles, options.charts);
    std::vector<std::vector<uint32_t>> pieces;  // charts grow through edges, so each is connected
    for (size_t k = 0; k < parts[p].size(); ++k) {
      if (chart_of[k] >= pieces.size()) pieces.resize(chart_of[k] + 1);
      pieces[chart_of[k]].push_back(parts[p][k]);
    }
    const std::vector<Chart> charts = flattened_charts(mesh, std::move(pieces), target, options);

    std::vector<glm::ivec2> sizes;
    for (const Chart& chart : charts) {
      const glm::dvec2 size = glm::ceil((chart.upper - chart.lower) * static_cast<double>(resolution));
      sizes.emplace_back(std::max(1, static_cast<int>(size.x)), std::max(1, static_cast<int>(size.y)));
    }
    const Packing packing = pack_rectangles(sizes, {resolution, options.gutter_pixels});
    double chart_area_px = 0.0;
    uint32_t shrunk_charts = 0;
    for (size_t c = 0; c < charts.size(); ++c) {
      const Chart& chart = charts[c];
      const PackedRectangle& place = packing.rectangles[c];
      const glm::dvec2 origin = glm::dvec2(place.origin) / static_cast<double>(resolution) +
                                glm::dvec2(static_cast<double>(place.tile), 0.0);
      const uint32_t first_vertex = static_cast<uint32_t>(out.positions.size());
      for (size_t v = 0; v < chart.source_vertices.size(); ++v) {
        const uint32_t source = chart.source_vertices[v];
        out.positions.push_back(mesh.positions[source]);
        if (!mesh.normals.empty()) out.normals.push_back(mesh.normals[source]);
        if (!mesh.colors.empty()) out.colors.push_back(mesh.colors[source]);
        out.uvs.push_back(glm::vec2(origin + (chart.uvs[chart.welded_of_source[v]] - chart.lower)));
      }
      for (size_t k = 0; k < chart.triangles.size(); ++k)
        out.triangles[chart.triangles[k]] = chart.source_triangles[k] + glm::uvec3(first_vertex);
      chart_area_px += uv_area(chart.uvs, chart.welded_triangles) * resolution * resolution;
      if (chart.shrunk) ++shrunk_charts;
    }
    // Distortion and achieved density from the final single-precision UVs, as users see them.
    UvPartReport report = measure_part(out, parts[p], part_name(mesh, p), target, resolution);
    report.charts = static_cast<uint32_t>(charts.size());
    report.shrunk_charts = shrunk_charts;
    report.tiles = packing.tiles;
    const double occupied = (packing.tiles - 1.0) * resolution * resolution +
                            static_cast<double>(packing.last_tile_width) * packing.last_tile_height;
    report.packing_efficiency = occupied > 0.0 ? chart_area_px / occupied : 0.0;
    result.parts.push_back(report);
  }
  // Tangents follow the new UVs; a mesh without normals (flat shading) keeps none.
  if (!out.normals.empty()) compute_tangents(out);
  return result;
}

}  // namespace matgeom
