#include "builtin/shapes.h"

#include <algorithm>
#include <stdexcept>

#include "matgeom/tangents.h"

namespace matgeom::builtin {
namespace {

glm::dvec2 unit(glm::dvec2 v) { return v / glm::length(v); }

// Outward normal (radial, z) of a profile segment walked with the material on its left.
glm::dvec2 segment_normal(const ProfilePoint& a, const ProfilePoint& b) {
  const glm::dvec2 d = unit(glm::dvec2(b.r - a.r, b.z - a.z));
  return {d.y, -d.x};
}

// A ring of the lathe: a profile point with the normal its vertices carry.
struct LatheRing {
  size_t point;
  glm::dvec2 normal;
};

}  // namespace

TriangleMesh box_mesh(const glm::dvec3& lower, const glm::dvec3& upper) {
  TriangleMesh mesh;
  const glm::dvec3 centre = 0.5 * (lower + upper), half = 0.5 * (upper - lower);
  for (int axis = 0; axis < 3; ++axis)
    for (int side = -1; side <= 1; side += 2) {
      glm::dvec3 n(0.0);
      n[axis] = side;
      // (u, v, n) right-handed, so corners in (u, v) order wind counter-clockwise about n.
      glm::dvec3 u(0.0);
      u[(axis + 1) % 3] = 1.0;
      const glm::dvec3 v = glm::cross(n, u);
      const uint32_t base = static_cast<uint32_t>(mesh.positions.size());
      for (const glm::dvec2 c : {glm::dvec2(-1, -1), glm::dvec2(1, -1), glm::dvec2(1, 1), glm::dvec2(-1, 1)}) {
        mesh.positions.emplace_back(centre + half * (n + c.x * u + c.y * v));
        mesh.normals.emplace_back(n);
      }
      mesh.triangles.emplace_back(base, base + 1, base + 2);
      mesh.triangles.emplace_back(base, base + 2, base + 3);
    }
  return mesh;
}

TriangleMesh lathe_mesh(const std::vector<ProfilePoint>& profile, int segments, double crease_degrees) {
  if (profile.size() < 3 || segments < 3) throw std::invalid_argument("lathe_mesh: profile or segments too small");
  const bool closed_loop = profile.front().r == profile.back().r && profile.front().z == profile.back().z &&
                           profile.front().r > 0.0;
  const size_t last = profile.size() - 1;
  const double cos_crease = std::cos(crease_degrees * kPi / 180.0);

  // Rings along the profile; a crease point gets two rings (one per adjacent segment).
  std::vector<std::vector<LatheRing>> rings_at(profile.size());
  for (size_t i = 0; i <= last; ++i) {
    const bool on_axis = !closed_loop && (i == 0 || i == last);
    if (on_axis) continue;
    const size_t prev = i > 0 ? i - 1 : last - 1, next = i < last ? i + 1 : 1;
    const glm::dvec2 in = segment_normal(profile[prev], profile[i]), out = segment_normal(profile[i], profile[next]);
    if (glm::dot(in, out) < cos_crease) {
      rings_at[i] = {{i, in}, {i, out}};
    } else {
      rings_at[i] = {{i, unit(in + out)}};
    }
  }

  TriangleMesh mesh;
  const auto add_ring = [&](const LatheRing& ring) {
    const uint32_t start = static_cast<uint32_t>(mesh.positions.size());
    for (int j = 0; j < segments; ++j) {
      const double phi = 2.0 * kPi * j / segments, c = std::cos(phi), s = std::sin(phi);
      const ProfilePoint& p = profile[ring.point];
      mesh.positions.emplace_back(p.r * c, p.r * s, p.z);
      mesh.normals.emplace_back(ring.normal.x * c, ring.normal.x * s, ring.normal.y);
    }
    return start;
  };
  const auto add_pole = [&](size_t i, double normal_z) {
    mesh.positions.emplace_back(0.0, 0.0, profile[i].z);
    mesh.normals.emplace_back(0.0, 0.0, normal_z);
    return static_cast<uint32_t>(mesh.positions.size() - 1);
  };
  const uint32_t n = static_cast<uint32_t>(segments);
  // Ring vertex start of segment i's lower and upper end (the ring of point i that faces it).
  std::vector<uint32_t> start_out(profile.size()), start_in(profile.size());
  for (size_t i = 0; i <= last; ++i) {
    if (rings_at[i].empty()) continue;
    start_in[i] = add_ring(rings_at[i].front());
    start_out[i] = rings_at[i].size() == 2 ? add_ring(rings_at[i].back()) : start_in[i];
  }
  if (closed_loop) start_in[last] = start_in[0], start_out[last] = start_out[0];

  for (size_t i = 0; i < last; ++i) {
    const bool from_pole = !closed_loop && i == 0, to_pole = !closed_loop && i + 1 == last;
    if (from_pole) {
      const glm::dvec2 normal = segment_normal(profile[0], profile[1]);
      const uint32_t pole = add_pole(0, normal.y >= 0.0 ? 1.0 : -1.0);
      for (uint32_t j = 0; j < n; ++j) mesh.triangles.emplace_back(pole, start_in[1] + (j + 1) % n, start_in[1] + j);
    } else if (to_pole) {
      const glm::dvec2 normal = segment_normal(profile[i], profile[last]);
      const uint32_t pole = add_pole(last, normal.y >= 0.0 ? 1.0 : -1.0);
      for (uint32_t j = 0; j < n; ++j) mesh.triangles.emplace_back(start_out[i] + j, start_out[i] + (j + 1) % n, pole);
    } else {
      const uint32_t lower = start_out[i], upper = start_in[i + 1];
      for (uint32_t j = 0; j < n; ++j) {
        const uint32_t a = lower + j, b = lower + (j + 1) % n, c = upper + (j + 1) % n, d = upper + j;
        mesh.triangles.emplace_back(a, b, c);
        mesh.triangles.emplace_back(a, c, d);
      }
    }
  }
  return mesh;
}

TriangleMesh cylinder_mesh(double radius, double z0, double z1, int segments) {
  return lathe_mesh({{0.0, z0}, {radius, z0}, {radius, z1}, {0.0, z1}}, segments);
}

TriangleMesh torus_arc_mesh(double major_radius, double minor_radius, double from, double to, int major_segments,
                            int minor_segments) {
  TriangleMesh mesh;
  const auto centre = [&](double theta) { return major_radius * glm::dvec3(std::cos(theta), 0.0, std::sin(theta)); };
  const auto radial = [](double theta) { return glm::dvec3(std::cos(theta), 0.0, std::sin(theta)); };
  const glm::dvec3 y(0.0, 1.0, 0.0);
  const uint32_t m = static_cast<uint32_t>(minor_segments);
  for (int i = 0; i <= major_segments; ++i) {
    const double theta = from + (to - from) * i / major_segments;
    for (int k = 0; k < minor_segments; ++k) {
      const double phi = 2.0 * kPi * k / minor_segments;
      const glm::dvec3 n = std::cos(phi) * radial(theta) + std::sin(phi) * y;
      mesh.positions.emplace_back(centre(theta) + minor_radius * n);
      mesh.normals.emplace_back(n);
    }
  }
  // With theta increasing, the surface's d/dphi x d/dtheta points along n ((y, tangent, radial)
  // is right-handed at phi = 0), so (a, b, c) with b one step in phi and d one step in theta
  // winds counter-clockwise seen from outside; a decreasing arc reverses it.
  for (uint32_t i = 0; i < static_cast<uint32_t>(major_segments); ++i)
    for (uint32_t k = 0; k < m; ++k) {
      const uint32_t a = i * m + k, b = i * m + (k + 1) % m, c = (i + 1) * m + (k + 1) % m, d = (i + 1) * m + k;
      if (to > from) {
        mesh.triangles.emplace_back(a, b, c);
        mesh.triangles.emplace_back(a, c, d);
      } else {
        mesh.triangles.emplace_back(a, d, c);
        mesh.triangles.emplace_back(a, c, b);
      }
    }
  // Flat caps at both ends, facing away from the tube.
  for (const bool at_end : {false, true}) {
    const double theta = at_end ? to : from;
    glm::dvec3 facing(-std::sin(theta), 0.0, std::cos(theta));
    if ((to > from) != at_end) facing = -facing;
    const uint32_t centre_vertex = static_cast<uint32_t>(mesh.positions.size());
    mesh.positions.emplace_back(centre(theta));
    mesh.normals.emplace_back(facing);
    const uint32_t rim = static_cast<uint32_t>(mesh.positions.size());
    const uint32_t ring = at_end ? static_cast<uint32_t>(major_segments) * m : 0u;
    for (uint32_t k = 0; k < m; ++k) {
      mesh.positions.push_back(mesh.positions[ring + k]);
      mesh.normals.emplace_back(facing);
    }
    for (uint32_t k = 0; k < m; ++k) {
      glm::uvec3 t(centre_vertex, rim + k, rim + (k + 1) % m);
      const glm::dvec3 p0(mesh.positions[t.x]), p1(mesh.positions[t.y]), p2(mesh.positions[t.z]);
      if (glm::dot(glm::cross(p1 - p0, p2 - p0), facing) < 0.0) std::swap(t.y, t.z);
      mesh.triangles.push_back(t);
    }
  }
  return mesh;
}

TriangleMesh cushion_mesh(const glm::dvec3& size, double edge_power, int resolution) {
  // Samples crowd toward the edges, where the surface turns fastest: u = sin(pi/2 t).
  std::vector<double> grid;
  for (int k = 0; k <= resolution; ++k) grid.push_back(std::sin(0.5 * kPi * (2.0 * k / resolution - 1.0)));
  grid.front() = -1.0, grid.back() = 1.0;
  const auto height = [&](double u, double v) {
    const double h = (1.0 - std::pow(std::abs(u), edge_power)) * (1.0 - std::pow(std::abs(v), edge_power));
    return 0.5 * size.z * std::sqrt(std::max(0.0, h));
  };
  TriangleMesh mesh;
  const uint32_t row = static_cast<uint32_t>(resolution + 1);
  for (const double side : {1.0, -1.0}) {
    TriangleMesh surface;
    for (const double v : grid)
      for (const double u : grid) {
        const double h = height(u, v);
        surface.positions.emplace_back(0.5 * size.x * u, 0.5 * size.y * v, h > 0.0 ? side * h : 0.0);
      }
    for (uint32_t j = 0; j < row - 1; ++j)
      for (uint32_t i = 0; i < row - 1; ++i) {
        const uint32_t a = j * row + i, b = a + 1, c = a + row + 1, d = a + row;
        if (side > 0.0) {
          surface.triangles.emplace_back(a, b, c);
          surface.triangles.emplace_back(a, c, d);
        } else {
          surface.triangles.emplace_back(a, c, b);
          surface.triangles.emplace_back(a, d, c);
        }
      }
    compute_vertex_normals(surface);
    append_part(mesh, surface, 0);
  }
  mesh.triangle_parts.clear();
  return mesh;
}

TriangleMesh transformed(TriangleMesh mesh, const glm::dmat4& transform) {
  transform_mesh(mesh, transform);
  return mesh;
}

void append_part(TriangleMesh& mesh, const TriangleMesh& piece, uint32_t part) {
  const uint32_t offset = static_cast<uint32_t>(mesh.positions.size());
  if (mesh.triangle_parts.size() != mesh.triangles.size()) mesh.triangle_parts.resize(mesh.triangles.size(), 0);
  mesh.positions.insert(mesh.positions.end(), piece.positions.begin(), piece.positions.end());
  mesh.normals.insert(mesh.normals.end(), piece.normals.begin(), piece.normals.end());
  for (const glm::uvec3& t : piece.triangles) {
    mesh.triangles.push_back(t + glm::uvec3(offset));
    mesh.triangle_parts.push_back(part);
  }
}

}  // namespace matgeom::builtin
