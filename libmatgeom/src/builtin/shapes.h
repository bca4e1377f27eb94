#pragma once
// Primitive solids of the built-in objects: each is a closed surface (watertight once vertices
// at equal positions are merged) with outward counter-clockwise triangles and vertex normals
// that are smooth across gentle bends and split at sharp edges. No UVs: the UV pass makes them.
// Lengths in metres; +Z up.
#include <cmath>
#include <vector>

#include <glm/glm.hpp>

#include "matbase/pi.h"
#include "matgeom/mesh.h"

namespace matgeom::builtin {

using matbase::kPi;

// Axis-aligned box between two corners.
TriangleMesh box_mesh(const glm::dvec3& lower, const glm::dvec3& upper);

// A point of a profile in the (radius, height) half-plane.
struct ProfilePoint {
  double r, z;
};

// The surface swept by revolving `profile` about the z axis in `segments` steps. The profile is
// walked with the material on its left (outside on its right, e.g. up the outside of a wall).
// It either starts and ends on the axis (r = 0: a solid or a vessel) or is a closed loop whose
// last point repeats the first (a ring, e.g. a lamp shade). Where the profile turns by more
// than `crease_degrees` the normals are split, so rims and cap edges stay sharp.
TriangleMesh lathe_mesh(const std::vector<ProfilePoint>& profile, int segments, double crease_degrees = 40.0);

// A solid cylinder about the z axis from z0 to z1 (flat caps).
TriangleMesh cylinder_mesh(double radius, double z0, double z1, int segments);

// A tube of radius `minor_radius` along the arc of radius `major_radius` about the origin in the
// xz plane, from angle `from` to `to` (radians, measured from +x toward +z), closed by flat caps.
TriangleMesh torus_arc_mesh(double major_radius, double minor_radius, double from, double to, int major_segments,
                            int minor_segments);

// A cushion centred at the origin: top and bottom surfaces z = +-(size.z / 2) h(u, v) over the
// size.x x size.y rectangle, h = ((1 - |u|^p)(1 - |v|^p))^(1/2), meeting at a seam round the
// edge. Higher `edge_power` p gives a boxier cushion.
TriangleMesh cushion_mesh(const glm::dvec3& size, double edge_power, int resolution);

// The closed profile of a thin-walled vessel: from the bottom centre out along the base, up the
// outer wall r = outer_radius(z) for z in [0, height], over a rounded lip of the wall's
// thickness, down the inside and in to the centre of the inner floor at z = floor.
template <class Radius>
std::vector<ProfilePoint> vessel_profile(Radius outer_radius, double height, double wall, double floor,
                                         int wall_samples);

// Affine transform of positions and normals (normals by the inverse transpose).
TriangleMesh transformed(TriangleMesh mesh, const glm::dmat4& transform);

// Appends `piece` to `mesh` as part `part`.
void append_part(TriangleMesh& mesh, const TriangleMesh& piece, uint32_t part);

// --- template definition ---------------------------------------------------------------------

template <class Radius>
std::vector<ProfilePoint> vessel_profile(Radius outer_radius, double height, double wall, double floor,
                                         int wall_samples) {
  std::vector<ProfilePoint> profile = {{0.0, 0.0}};
  for (int k = 0; k <= wall_samples; ++k) {
    const double z = height * k / wall_samples;
    profile.push_back({outer_radius(z), z});
  }
  const double rim = outer_radius(height);
  constexpr int kLipSamples = 5;
  for (int k = 1; k < kLipSamples; ++k) {  // half circle over the top of the wall
    const double angle = kPi * k / kLipSamples;
    profile.push_back({rim - 0.5 * wall + 0.5 * wall * std::cos(angle), height + 0.5 * wall * std::sin(angle)});
  }
  for (int k = 0; k <= wall_samples; ++k) {
    const double z = height - (height - floor) * k / wall_samples;
    profile.push_back({outer_radius(z) - wall, z});
  }
  profile.push_back({0.0, floor});
  return profile;
}

}  // namespace matgeom::builtin
