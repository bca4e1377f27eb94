#pragma once
// The solids furniture is built from: flat-faced boards and boxes with eased edges, frusta,
// leaning boards, rods, rounded discs, rings and cushions, and the sizes they share. Every solid
// is closed and wound outward.
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "builtin/shapes.h"
#include "matgeom/mesh.h"

namespace matgeom::builtin {

using glm::dvec2;
using glm::dvec3;

inline constexpr int kRoundSegments = 24;      // around legs, rods and handles
inline constexpr int kDiscSegments = 64;       // around round table tops and stool seats
inline constexpr int kCushionResolution = 12;  // grid of a cushion surface: 576 triangles a cushion
// Joined pieces sink this far into each other, so that no seam of light shows between them.
inline constexpr double kOverlap = 0.002;
// Machined boards have eased edges; the chamfer catches a highlight as the real edge does.
inline constexpr double kEasedEdge = 0.003;
// Gap between neighbouring doors and drawer fronts, as on fitted cabinets.
inline constexpr double kFrontGap = 0.003;

inline glm::dmat4 translation(const dvec3& offset) { return glm::translate(glm::dmat4(1.0), offset); }
inline glm::dmat4 rotation_about_y(double angle) { return glm::rotate(glm::dmat4(1.0), angle, dvec3(0.0, 1.0, 0.0)); }

// Appends a flat convex polygon (corners in order round it, either way) as a triangle fan with
// its own vertices and normal, wound counter-clockwise seen from outside the convex solid that
// contains `inside`.
void add_flat_face(TriangleMesh& mesh, std::vector<dvec3> corners, const dvec3& inside);

// A box whose twelve edges are cut at 45 degrees by `chamfer`, with a small triangle at each
// corner. Every face is flat: on a board this reads as an eased edge, on upholstery as a soft one.
TriangleMesh chamfered_box(const dvec3& lower, const dvec3& upper, double chamfer);

// The solid between two horizontal rectangles (centre and half extents), the lower at
// bottom.z and the upper at top.z: a tapered leg, or a leaning post when the centres differ.
// Each side face joins two parallel edges, so it is flat.
TriangleMesh frustum(const dvec3& bottom, const dvec2& bottom_half, const dvec3& top, const dvec2& top_half);

// A board of constant section (half extents) leaning from `bottom` to `top`, e.g. a chair's
// back post or slat.
TriangleMesh leaning_board(const dvec3& bottom, const dvec3& top, const dvec2& half);

// Moves a solid built upright from z = 0 to z = top.z - foot.z so that its foot centre is at
// `foot` and its top centre at `top`. A shear, not a rotation: the foot stays a horizontal cut,
// as splayed legs are cut to stand flat on the floor.
TriangleMesh sheared(TriangleMesh upright, const dvec3& foot, const dvec3& top);

// The transform taking a solid built along +z from the origin to point along `direction` from `at`.
glm::dmat4 pointing(const dvec3& at, const dvec3& direction);

// A round bar from `from` to `to` with flat ends.
TriangleMesh rod(const dvec3& from, const dvec3& to, double radius);

// A disc from z0 to z1 whose top edge is rounded over with radius `edge` (a table top, a seat).
TriangleMesh rounded_disc(double radius, double z0, double z1, double edge);

// A horizontal ring of tube (radius `tube`) round the z axis at height z: a stool's foot rest.
TriangleMesh ring(double radius, double tube, double z);

// A cushion (see cushion_mesh) of `size` in its own frame, then moved by `transform`.
TriangleMesh cushion(const dvec3& size, double edge_power, const glm::dmat4& transform);

// The transform standing a cushion built flat (thickness along z, height along x) up against a
// back that leans back by `lean` radians: its thickness then points forward and a little up.
glm::dmat4 leaning_cushion(const dvec3& centre, double lean);

}  // namespace matgeom::builtin
