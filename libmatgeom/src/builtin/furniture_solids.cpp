#include "builtin/furniture_solids.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace matgeom::builtin {

// Appends a flat convex polygon (corners in order round it, either way) as a triangle fan with
// its own vertices and normal, wound counter-clockwise seen from outside the convex solid that
// contains `inside`.
void add_flat_face(TriangleMesh& mesh, std::vector<dvec3> corners, const dvec3& inside) {
  dvec3 normal(0.0), centroid(0.0);
  for (size_t k = 0; k < corners.size(); ++k) {
    normal += glm::cross(corners[k], corners[(k + 1) % corners.size()]);  // Newell's method
    centroid += corners[k];
  }
  centroid /= static_cast<double>(corners.size());
  if (glm::dot(normal, centroid - inside) < 0.0) {
    std::reverse(corners.begin(), corners.end());
    normal = -normal;
  }
  normal = glm::normalize(normal);
  const uint32_t base = static_cast<uint32_t>(mesh.positions.size());
  for (const dvec3& corner : corners) {
    mesh.positions.emplace_back(corner);
    mesh.normals.emplace_back(normal);
  }
  for (uint32_t k = 1; k + 1 < corners.size(); ++k) mesh.triangles.emplace_back(base, base + k, base + k + 1);
}

// A box whose twelve edges are cut at 45 degrees by `chamfer`, with a small triangle at each
// corner. Every face is flat: on a board this reads as an eased edge, on upholstery as a soft one.
TriangleMesh chamfered_box(const dvec3& lower, const dvec3& upper, double chamfer) {
  const dvec3 centre = 0.5 * (lower + upper), half = 0.5 * (upper - lower);
  chamfer = std::min(chamfer, 0.4 * std::min({half.x, half.y, half.z}));
  // The corner with signs `s` is cut by a triangle; its vertex on the face normal to `axis` lies
  // on that face, inset by the chamfer along the other two axes.
  const auto point = [&](const dvec3& s, int axis) {
    dvec3 p = half - dvec3(chamfer);
    p[axis] = half[axis];
    return centre + s * p;
  };
  const auto signs = [](int axis, double along, int u, double su, int v, double sv) {
    dvec3 s(0.0);
    s[axis] = along, s[u] = su, s[v] = sv;
    return s;
  };
  TriangleMesh mesh;
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (const double side : {-1.0, 1.0}) {  // the face normal to `axis`
      add_flat_face(mesh,
                    {point(signs(axis, side, u, -1, v, -1), axis), point(signs(axis, side, u, 1, v, -1), axis),
                     point(signs(axis, side, u, 1, v, 1), axis), point(signs(axis, side, u, -1, v, 1), axis)},
                    centre);
    }
    for (const double su : {-1.0, 1.0})  // the chamfer along the edge parallel to `axis`
      for (const double sv : {-1.0, 1.0}) {
        const dvec3 near = signs(axis, -1, u, su, v, sv), far = signs(axis, 1, u, su, v, sv);
        add_flat_face(mesh, {point(near, u), point(far, u), point(far, v), point(near, v)}, centre);
      }
  }
  for (const double sx : {-1.0, 1.0})
    for (const double sy : {-1.0, 1.0})
      for (const double sz : {-1.0, 1.0}) {
        const dvec3 s(sx, sy, sz);
        add_flat_face(mesh, {point(s, 0), point(s, 1), point(s, 2)}, centre);
      }
  return mesh;
}

// The solid between two horizontal rectangles (centre and half extents), the lower at
// bottom.z and the upper at top.z: a tapered leg, or a leaning post when the centres differ.
// Each side face joins two parallel edges, so it is flat.
TriangleMesh frustum(const dvec3& bottom, const dvec2& bottom_half, const dvec3& top, const dvec2& top_half) {
  const auto rectangle = [](const dvec3& c, const dvec2& h) {
    return std::array<dvec3, 4>{c + dvec3(-h.x, -h.y, 0.0), c + dvec3(h.x, -h.y, 0.0), c + dvec3(h.x, h.y, 0.0),
                                c + dvec3(-h.x, h.y, 0.0)};
  };
  const std::array<dvec3, 4> lower = rectangle(bottom, bottom_half), upper = rectangle(top, top_half);
  const dvec3 inside = 0.5 * (bottom + top);
  TriangleMesh mesh;
  add_flat_face(mesh, {lower.begin(), lower.end()}, inside);
  add_flat_face(mesh, {upper.begin(), upper.end()}, inside);
  for (int k = 0; k < 4; ++k) add_flat_face(mesh, {lower[k], lower[(k + 1) % 4], upper[(k + 1) % 4], upper[k]}, inside);
  return mesh;
}

// A board of constant section (half extents) leaning from `bottom` to `top`, e.g. a chair's
// back post or slat.
TriangleMesh leaning_board(const dvec3& bottom, const dvec3& top, const dvec2& half) {
  return frustum(bottom, half, top, half);
}

// Moves a solid built upright from z = 0 to z = top.z - foot.z so that its foot centre is at
// `foot` and its top centre at `top`. A shear, not a rotation: the foot stays a horizontal cut,
// as splayed legs are cut to stand flat on the floor.
TriangleMesh sheared(TriangleMesh upright, const dvec3& foot, const dvec3& top) {
  glm::dmat4 shear(1.0);
  shear[2][0] = (top.x - foot.x) / (top.z - foot.z);
  shear[2][1] = (top.y - foot.y) / (top.z - foot.z);
  return transformed(std::move(upright), translation(foot) * shear);
}

// The transform taking a solid built along +z from the origin to point along `direction` from `at`.
glm::dmat4 pointing(const dvec3& at, const dvec3& direction) {
  const dvec3 z(0.0, 0.0, 1.0), d = glm::normalize(direction);
  const dvec3 axis = glm::cross(z, d);
  const glm::dmat4 moved = translation(at);
  if (glm::length(axis) > 1e-9) return glm::rotate(moved, std::acos(std::clamp(d.z, -1.0, 1.0)), glm::normalize(axis));
  return d.z > 0.0 ? moved : glm::rotate(moved, kPi, dvec3(1.0, 0.0, 0.0));
}

// A round bar from `from` to `to` with flat ends.
TriangleMesh rod(const dvec3& from, const dvec3& to, double radius) {
  return transformed(cylinder_mesh(radius, 0.0, glm::length(to - from), kRoundSegments), pointing(from, to - from));
}

// A disc from z0 to z1 whose top edge is rounded over with radius `edge` (a table top, a seat).
TriangleMesh rounded_disc(double radius, double z0, double z1, double edge) {
  std::vector<ProfilePoint> profile = {{0.0, z0}, {radius, z0}, {radius, z1 - edge}};
  constexpr int kEdgeSamples = 4;
  for (int k = 1; k <= kEdgeSamples; ++k) {
    const double angle = 0.5 * kPi * k / kEdgeSamples;
    profile.push_back({radius - edge + edge * std::cos(angle), z1 - edge + edge * std::sin(angle)});
  }
  profile.push_back({0.0, z1});
  return lathe_mesh(profile, kDiscSegments);
}

// A horizontal ring of tube (radius `tube`) round the z axis at height z: a stool's foot rest.
TriangleMesh ring(double radius, double tube, double z) {
  // A closed profile loop, walked counter-clockwise in (r, z) so the material is on its left.
  constexpr int kTubeSamples = 10;
  std::vector<ProfilePoint> profile;
  for (int k = 0; k <= kTubeSamples; ++k) {
    const double angle = 2.0 * kPi * (k % kTubeSamples) / kTubeSamples;
    profile.push_back({radius + tube * std::cos(angle), z + tube * std::sin(angle)});
  }
  return lathe_mesh(profile, 2 * kDiscSegments);
}

// A cushion (see cushion_mesh) of `size` in its own frame, then moved by `transform`.
TriangleMesh cushion(const dvec3& size, double edge_power, const glm::dmat4& transform) {
  return transformed(cushion_mesh(size, edge_power, kCushionResolution), transform);
}

// The transform standing a cushion built flat (thickness along z, height along x) up against a
// back that leans back by `lean` radians: its thickness then points forward and a little up.
glm::dmat4 leaning_cushion(const dvec3& centre, double lean) {
  return translation(centre) * rotation_about_y(0.5 * kPi - lean);
}

}  // namespace matgeom::builtin
