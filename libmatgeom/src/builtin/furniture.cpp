// Furniture assembled from boards, legs, rails and cushions. Sizes follow common catalogue and
// standard dimensions (seat, table and desk heights, mattress sizes), quoted where they are used.
// Every object faces +x (the side the paper's camera grid looks from), its width along y.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "builtin/object_builder.h"
#include "builtin/objects.h"
#include "builtin/shapes.h"

namespace matgeom::builtin {
namespace {

using glm::dvec2;
using glm::dvec3;

constexpr int kRoundSegments = 24;      // around legs, rods and handles
constexpr int kDiscSegments = 64;       // around round table tops and stool seats
constexpr int kCushionResolution = 12;  // grid of a cushion surface: 576 triangles a cushion
// Joined pieces sink this far into each other, so that no seam of light shows between them.
constexpr double kOverlap = 0.002;
// Machined boards have eased edges; the chamfer catches a highlight as the real edge does.
constexpr double kEasedEdge = 0.003;
// Gap between neighbouring doors and drawer fronts, as on fitted cabinets.
constexpr double kFrontGap = 0.003;

Finish wooden(UniformSource& random) { return random.next() < 0.65 ? Finish::Wood : Finish::PaintedWood; }
Finish upholstery(UniformSource& random) { return random.next() < 0.7 ? Finish::Fabric : Finish::Leather; }

glm::dmat4 translation(const dvec3& offset) { return glm::translate(glm::dmat4(1.0), offset); }
glm::dmat4 rotation_about_y(double angle) { return glm::rotate(glm::dmat4(1.0), angle, dvec3(0.0, 1.0, 0.0)); }

// --- solids ----------------------------------------------------------------------------------

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

// --- legs ------------------------------------------------------------------------------------

enum class LegStyle { Square, Tapered, Turned, Tube };

LegStyle random_leg_style(UniformSource& random) { return static_cast<LegStyle>(random.choice(4)); }

// A turned leg, as on a lathe: a plain cylindrical block at the top where the rails join, a bead,
// a baluster narrowing to a slim ankle and a small foot. Shape as (radius, height) fractions.
std::vector<ProfilePoint> turned_leg_profile(double radius, double height) {
  static const double kShape[][2] = {{0.62, 0.0}, {0.62, 0.03}, {0.5, 0.06},  {0.55, 0.35}, {0.8, 0.62},
                                     {0.7, 0.7},  {0.92, 0.74}, {0.72, 0.78}, {1.0, 0.8},   {1.0, 1.0}};
  std::vector<ProfilePoint> profile = {{0.0, 0.0}};
  for (const auto& point : kShape) profile.push_back({radius * point[0], height * point[1]});
  profile.push_back({0.0, height});
  return profile;
}

// A leg standing on the floor at `at`, up to `top_z`; `thickness` is its width at the top.
TriangleMesh leg(LegStyle style, const dvec2& at, double top_z, double thickness) {
  const double half = 0.5 * thickness;
  const dvec3 foot(at, 0.0);
  if (style == LegStyle::Square)
    return chamfered_box(foot - dvec3(half, half, 0.0), dvec3(at + half, top_z), kEasedEdge);
  if (style == LegStyle::Tapered) {  // mid-century legs narrow to about 60% at the foot
    return frustum(foot, dvec2(0.6 * half), dvec3(at, top_z), dvec2(half));
  }
  if (style == LegStyle::Turned)
    return transformed(lathe_mesh(turned_leg_profile(half, top_z), kRoundSegments), translation(foot));
  return transformed(cylinder_mesh(half, 0.0, top_z, kRoundSegments), translation(foot));
}

// A plain post of the leg's section from `bottom` to `top` (a chair's back post, leaning).
TriangleMesh post(LegStyle style, const dvec3& bottom, const dvec3& top, double thickness) {
  const double half = 0.5 * thickness;
  if (style == LegStyle::Square || style == LegStyle::Tapered) return leaning_board(bottom, top, dvec2(half));
  return sheared(cylinder_mesh(half, 0.0, top.z - bottom.z, kRoundSegments), bottom, top);
}

// The four corners (+-half.x, +-half.y).
std::array<dvec2, 4> corners(const dvec2& half) {
  return {dvec2(-half.x, -half.y), dvec2(half.x, -half.y), dvec2(half.x, half.y), dvec2(-half.x, half.y)};
}

// Four legs with their centres at the corners (+-half.x, +-half.y), up to `top_z`.
void add_legs(ObjectBuilder& b, uint32_t part, LegStyle style, const dvec2& half, double top_z, double thickness) {
  for (const dvec2& at : corners(half)) b.add(part, leg(style, at, top_z, thickness));
}

// Where the outer faces of aprons between legs of `leg_thickness` centred at +-half lie: set back
// 5 mm from the legs' outer faces, as a joiner sets rails so the leg's edge stays crisp.
dvec2 apron_faces(const dvec2& half, double leg_thickness) { return half + dvec2(0.5 * leg_thickness - 0.005); }

// The four rails (aprons) between legs centred at +-half, from `top_z - height` to `top_z`.
void add_aprons(ObjectBuilder& b, uint32_t part, const dvec2& half, double leg_thickness, double top_z, double height,
                double thickness) {
  const double z0 = top_z - height;
  for (const double side : {-1.0, 1.0}) {
    const dvec2 outer = side * apron_faces(half, leg_thickness), inner = outer - side * thickness;
    const dvec2 low = glm::min(outer, inner), high = glm::max(outer, inner);
    // The front or back rail along y, then a side rail along x.
    b.add(part, chamfered_box(dvec3(low.x, -half.y, z0), dvec3(high.x, half.y, top_z), kEasedEdge));
    b.add(part, chamfered_box(dvec3(-half.x, low.y, z0), dvec3(half.x, high.y, top_z), kEasedEdge));
  }
}

// --- handles ---------------------------------------------------------------------------------

enum class HandleStyle { Bar, Knob };

// A mushroom knob along +z, 25 mm deep with a 28 mm head on a 12 mm neck, as sold for cabinets.
std::vector<ProfilePoint> knob_profile() {
  return {{0.0, 0.0}, {0.006, 0.0}, {0.005, 0.012}, {0.014, 0.017}, {0.014, 0.022}, {0.011, 0.025}, {0.0, 0.025}};
}

// A handle on a front whose face is at x = face_x, centred at (y, z): a bar pull (a 10 mm bar
// 28 mm proud on two posts) lying along y if `horizontal`, along z otherwise, or a knob.
void add_handle(ObjectBuilder& b, uint32_t part, HandleStyle style, double face_x, const dvec2& centre, bool horizontal,
                double length) {
  const dvec3 on_face(face_x - kOverlap, centre.x, centre.y);
  const dvec3 outward(1.0, 0.0, 0.0);
  if (style == HandleStyle::Knob) {
    b.add(part, transformed(lathe_mesh(knob_profile(), kRoundSegments), pointing(on_face, outward)));
    return;
  }
  constexpr double kStandoff = 0.028, kBarRadius = 0.005, kPostRadius = 0.0035;
  const dvec3 direction = horizontal ? dvec3(0.0, 1.0, 0.0) : dvec3(0.0, 0.0, 1.0);
  for (const double end : {-1.0, 1.0}) {
    const dvec3 base = on_face + end * (0.5 * length - 0.012) * direction;
    b.add(part, rod(base, base + (kStandoff + kOverlap) * outward, kPostRadius));
  }
  const dvec3 bar_centre = on_face + (kStandoff + kOverlap) * outward;
  b.add(part, rod(bar_centre - 0.5 * length * direction, bar_centre + 0.5 * length * direction, kBarRadius));
}

// A door or drawer front on a carcass whose front face is at x = face_x, covering y0..y1 and
// z0..z1 less the gap to its neighbours.
TriangleMesh front_panel(double face_x, double thickness, const dvec2& y_range, const dvec2& z_range) {
  const double gap = 0.5 * kFrontGap;
  return chamfered_box(dvec3(face_x - kOverlap, y_range.x + gap, z_range.x + gap),
                       dvec3(face_x + thickness, y_range.y - gap, z_range.y - gap), kEasedEdge);
}

// A drawer front with a handle at its centre: a knob, or a horizontal bar a third as wide as the
// front within the common 96-192 mm sizes.
void add_drawer(ObjectBuilder& b, uint32_t front_part, uint32_t handle_part, HandleStyle style, double face_x,
                double thickness, const dvec2& y_range, const dvec2& z_range) {
  b.add(front_part, front_panel(face_x, thickness, y_range, z_range));
  const double bar = std::clamp((y_range.y - y_range.x) / 3.0, 0.096, 0.192);
  add_handle(b, handle_part, style, face_x + thickness,
             dvec2(0.5 * (y_range.x + y_range.y), 0.5 * (z_range.x + z_range.y)), true, bar);
}

}  // namespace

// --- the objects -----------------------------------------------------------------------------

ObjectAsset make_table(uint32_t seed) {
  ObjectBuilder b(seed);
  UniformSource& r = b.random();
  // Dining tables stand 0.72-0.76 m: about 0.3 m above a 0.45 m chair seat.
  const double height = r.between(0.72, 0.76), thickness = r.between(0.025, 0.04);
  const double underside = height - thickness;
  // Round tables seat four at 0.9-1.2 m across; rectangular ones are 1.2-1.9 m long (four to
  // eight places at 0.6 m each) and 0.8-1.0 m deep, so that place settings face each other.
  const bool round = r.next() < 0.3;
  const double length = round ? r.between(0.9, 1.2) : r.between(1.2, 1.9);
  const double depth = round ? length : r.between(0.8, 1.0);

  const uint32_t top = b.add_part("top", wooden(r));
  if (round) {
    b.add(top, rounded_disc(0.5 * length, underside, height, 0.008));
  } else {
    b.add(top, chamfered_box(dvec3(-0.5 * depth, -0.5 * length, underside), dvec3(0.5 * depth, 0.5 * length, height),
                             kEasedEdge));
  }

  // A third of the tables stand on a pedestal (round tops) or a trestle (rectangular ones).
  if (r.next() < 1.0 / 3.0) {
    if (round) {
      // A domed foot, a column and a collar carrying the top.
      const uint32_t base = b.add_part("base", r.next() < 0.6 ? wooden(r) : Finish::BrushedMetal);
      const double foot = r.between(0.22, 0.28), column = r.between(0.04, 0.06);
      b.add(base, lathe_mesh({{0.0, 0.0},
                              {foot, 0.0},
                              {foot, 0.025},
                              {1.8 * column, 0.09},
                              {column, 0.14},
                              {column, underside - 0.05},
                              {2.5 * column, underside - 0.01},
                              {2.5 * column, underside + kOverlap},
                              {0.0, underside + kOverlap}},
                             kDiscSegments));
    } else {
      // At each end an upright on a long foot under a cleat; a stretcher joins the uprights.
      const uint32_t base = b.add_part("base", wooden(r));
      const double end = 0.5 * length - r.between(0.12, 0.2), foot = 0.38 * depth, upright = r.between(0.05, 0.08);
      for (const double side : {-1.0, 1.0}) {
        const double y = side * end;
        b.add(base, chamfered_box(dvec3(-foot, y - 0.035, 0.0), dvec3(foot, y + 0.035, 0.06), kEasedEdge));
        b.add(base, box_mesh(dvec3(-upright, y - 0.03, 0.05), dvec3(upright, y + 0.03, underside - 0.04)));
        b.add(base, box_mesh(dvec3(0.03 - foot, y - 0.03, underside - 0.05),
                             dvec3(foot - 0.03, y + 0.03, underside + kOverlap)));
      }
      const double stretcher = r.between(0.2, 0.35);
      b.add(base, box_mesh(dvec3(-0.02, -end, stretcher), dvec3(0.02, end, stretcher + 0.08)));
    }
    return b.finish();
  }

  const LegStyle style = random_leg_style(r);
  const bool metal = style == LegStyle::Tube;
  const uint32_t base = b.add_part("base", metal ? Finish::BrushedMetal : wooden(r));
  // Steel tube legs are 25-35 mm across, wooden ones 45-70 mm. They stand 5-9 cm in from the
  // edges, leaving knee room; under a round top, on a square whose corners are 0.42 of the
  // diameter out, 8-10 cm in from the rim.
  const double leg_thickness = metal ? r.between(0.025, 0.035) : r.between(0.045, 0.07);
  const double inset = r.between(0.05, 0.09) + 0.5 * leg_thickness;
  const dvec2 half = round ? dvec2(0.3 * length) : dvec2(0.5 * depth - inset, 0.5 * length - inset);
  add_legs(b, base, style, half, underside + kOverlap, leg_thickness);
  // Aprons 80-110 mm deep stiffen the legs; a steel frame uses a 40 mm flat bar.
  add_aprons(b, base, half, leg_thickness, underside + kOverlap, metal ? 0.04 : r.between(0.08, 0.11),
             metal ? 0.01 : 0.022);
  return b.finish();
}

ObjectAsset make_chair(uint32_t seed) {
  ObjectBuilder b(seed);
  UniformSource& r = b.random();
  // Dining chair (sizes as furniture catalogues give them): seat 0.44-0.47 m high, 0.42-0.48 m
  // wide, 0.40-0.46 m deep; back 0.80-0.95 m high, its posts leaning back 3-8 cm at the top.
  const double seat_height = r.between(0.44, 0.47), seat_width = r.between(0.42, 0.48);
  const double seat_depth = r.between(0.4, 0.46);
  const double back_height = r.between(0.8, 0.95), rake = r.between(0.03, 0.08);
  const LegStyle style = random_leg_style(r);
  const bool metal = style == LegStyle::Tube, round_section = metal || style == LegStyle::Turned;
  // Steel tube frames are about 20 mm across, wooden legs 30-40 mm.
  const double leg_thickness = metal ? r.between(0.018, 0.024) : r.between(0.03, 0.04);
  const bool padded = r.next() < 0.45;
  const uint32_t frame = b.add_part("frame", metal ? Finish::BrushedMetal : wooden(r));
  const uint32_t seat = b.add_part("seat", padded ? upholstery(r) : wooden(r));

  // A padded seat is a 5-8 cm cushion whose lower part sinks into its board, as foam does; a
  // plain seat is a 20-30 mm board.
  const double cushion_thickness = padded ? r.between(0.05, 0.08) : 0.0;
  const double board_top = seat_height - 0.8 * cushion_thickness;
  const double board_bottom = board_top - (padded ? 0.02 : r.between(0.02, 0.03));
  b.add(padded ? frame : seat, chamfered_box(dvec3(-0.5 * seat_depth, -0.5 * seat_width, board_bottom),
                                             dvec3(0.5 * seat_depth, 0.5 * seat_width, board_top), kEasedEdge));
  if (padded) {
    b.add(seat, cushion(dvec3(seat_depth, seat_width, cushion_thickness), 5.0,
                        translation(dvec3(0.0, 0.0, board_top + 0.3 * cushion_thickness))));
  }

  // Legs 1 cm in from the seat's edges, with seat rails between them under the board.
  const dvec2 half = 0.5 * dvec2(seat_depth, seat_width) - dvec2(0.5 * leg_thickness + 0.01);
  const double rail_height = metal ? 0.03 : r.between(0.06, 0.08);
  add_legs(b, frame, style, half, board_bottom + kOverlap, leg_thickness);
  add_aprons(b, frame, half, leg_thickness, board_bottom + kOverlap, rail_height, metal ? 0.01 : 0.02);
  if (r.next() < 0.5) {
    // An H-stretcher low between the legs.
    const double z = r.between(0.12, 0.2);
    for (const double side : {-1.0, 1.0}) {
      b.add(frame, rod(dvec3(-half.x, side * half.y, z), dvec3(half.x, side * half.y, z), 0.3 * leg_thickness));
    }
    b.add(frame, rod(dvec3(0.0, -half.y, z), dvec3(0.0, half.y, z), 0.3 * leg_thickness));
  }

  // The back posts carry on from the rear legs, from the bottom of the seat rails to the top,
  // leaning back; every part of the back follows their line.
  const double post_bottom = board_bottom - rail_height;
  const auto post_x = [&](double z) { return -half.x - rake * (z - post_bottom) / (back_height - post_bottom); };
  const auto on_post_line = [&](double y, double z) { return dvec3(post_x(z), y, z); };
  for (const double side : {-1.0, 1.0}) {
    b.add(frame, post(style, on_post_line(side * half.y, post_bottom), on_post_line(side * half.y, back_height),
                      leg_thickness));
  }
  // Rails stop 1 cm below the posts' tops, so that no two top faces lie in one plane.
  const double rail_top = back_height - 0.01, back_bottom = seat_height + 0.12;
  const auto add_back_rail = [&](double z0, double z1, double thickness) {
    b.add(frame, leaning_board(on_post_line(0.0, z0), on_post_line(0.0, z1), dvec2(0.5 * thickness, half.y)));
  };
  const uint32_t back_style = r.choice(3);
  if (back_style == 0) {
    // Two or three horizontal rails, 4-7 cm high, from the top down.
    const double height = r.between(0.04, 0.07), pitch = height + r.between(0.06, 0.1);
    const int count = std::min(2 + static_cast<int>(r.choice(2)), static_cast<int>((rail_top - back_bottom) / pitch));
    for (int k = 0; k < count; ++k) add_back_rail(rail_top - k * pitch - height, rail_top - k * pitch, 0.02);
  } else if (back_style == 1) {
    // A top rail and a lower rail with three to five slats (flat) or spindles (round) between.
    const double top_rail = r.between(0.06, 0.09), lower = seat_height + r.between(0.1, 0.16);
    add_back_rail(rail_top - top_rail, rail_top, 0.022);
    add_back_rail(lower, lower + 0.04, 0.022);
    const int count = 3 + static_cast<int>(r.choice(3));
    const double slat_width = r.between(0.025, 0.045);
    const double z0 = lower + 0.04 - kOverlap, z1 = rail_top - top_rail + kOverlap;
    for (int k = 0; k < count; ++k) {
      const double y = -half.y + 2.0 * half.y * (k + 1) / (count + 1);
      if (round_section) {
        b.add(frame, rod(on_post_line(y, z0), on_post_line(y, z1), 0.008));
      } else {
        b.add(frame, leaning_board(on_post_line(y, z0), on_post_line(y, z1), dvec2(0.007, 0.5 * slat_width)));
      }
    }
  } else {
    // An upholstered pad on a board between the posts.
    const uint32_t back = b.add_part("back", upholstery(r));
    const double pad = std::min(r.between(0.22, 0.32), rail_top - 0.02 - back_bottom);
    const double pad_thickness = r.between(0.04, 0.06), centre = rail_top - 0.02 - 0.5 * pad;
    const double lean = std::atan2(rake, back_height - post_bottom);
    b.add(back,
          cushion(dvec3(pad, 2.0 * half.y, pad_thickness), 4.0, leaning_cushion(on_post_line(0.0, centre), lean)));
    const dvec3 behind(-0.5 * pad_thickness, 0.0, 0.0);
    b.add(frame, leaning_board(on_post_line(0.0, centre - 0.5 * pad) + behind,
                               on_post_line(0.0, centre + 0.5 * pad) + behind, dvec2(0.006, half.y)));
  }
  return b.finish();
}

ObjectAsset make_stool(uint32_t seed) {
  ObjectBuilder b(seed);
  UniformSource& r = b.random();
  // Seat heights by use: 0.45 m at a table, 0.65 m at a 0.9 m kitchen counter, 0.75 m at a
  // 1.05 m bar (the seat 0.25-0.3 m below the counter leaves room for the thighs).
  static const double kSeatHeights[] = {0.45, 0.65, 0.75};
  const double height = kSeatHeights[r.choice(3)] + r.between(-0.01, 0.02);
  const bool round = r.next() < 0.65, padded = r.next() < 0.35, metal = r.next() < 0.4;
  const int leg_count = round && r.next() < 0.5 ? 3 : 4;
  // Seats 0.30-0.38 m across; a padded one 5-7 cm thick, a wooden one 30-45 mm.
  const double seat_half = r.between(0.15, 0.18) + (round ? 0.01 : 0.0);
  const double thickness = padded ? r.between(0.05, 0.07) : r.between(0.03, 0.045);
  const double underside = height - thickness;
  const uint32_t seat = b.add_part("seat", padded ? upholstery(r) : wooden(r));
  const uint32_t legs = b.add_part("legs", metal ? Finish::BrushedMetal : wooden(r));
  if (round) {
    b.add(seat, rounded_disc(seat_half, underside, height, padded ? 0.5 * thickness : 0.008));
  } else {
    b.add(seat, chamfered_box(dvec3(-seat_half, -seat_half, underside), dvec3(seat_half, seat_half, height),
                              padded ? 0.015 : kEasedEdge));
  }

  // Splayed legs: joined under the seat 3/4 of the way out, their feet spread to 0.32-0.40 m
  // so the stool does not tip. Steel tubes are 22-28 mm across; wooden legs taper from 34-44 mm.
  const double leg_radius = metal ? r.between(0.011, 0.014) : r.between(0.017, 0.022);
  const double foot_radius = metal ? leg_radius : 0.7 * leg_radius;
  const double leg_top = underside + kOverlap, footprint = r.between(0.16, 0.2);
  std::vector<dvec2> directions;
  double widest = 0.0;  // the largest x or y component of a leg's direction
  for (int k = 0; k < leg_count; ++k) {
    const double angle = 2.0 * kPi * k / leg_count + (leg_count == 4 ? 0.25 * kPi : 0.0);
    directions.emplace_back(std::cos(angle), std::sin(angle));
    widest = std::max({widest, std::abs(directions.back().x), std::abs(directions.back().y)});
  }
  const double spread = footprint / widest, attached = 0.75 * seat_half * (round ? 1.0 : std::sqrt(2.0));
  const auto leg_centre = [&](const dvec2& direction, double z) {
    return dvec3(direction * (spread + (attached - spread) * z / leg_top), z);
  };
  for (const dvec2& direction : directions) {
    const TriangleMesh upright =
        lathe_mesh({{0.0, 0.0}, {foot_radius, 0.0}, {leg_radius, leg_top}, {0.0, leg_top}}, kRoundSegments);
    b.add(legs, sheared(upright, leg_centre(direction, 0.0), leg_centre(direction, leg_top)));
  }
  // A tall stool has a foot rest 0.45 m below the seat, where a sitter's feet rest: a ring on
  // three legs (on four it would stick out past the feet), else rungs. A low one may have rungs.
  const bool tall = height > 0.6;
  if (tall || r.next() < 0.6) {
    const double z = tall ? height - 0.45 : r.between(0.14, 0.2);
    if (tall && leg_count == 3) {
      b.add(legs, ring(glm::length(dvec2(leg_centre(directions[0], z))), metal ? 0.01 : 0.012, z));
    } else {
      for (int k = 0; k < leg_count; ++k) {
        b.add(legs,
              rod(leg_centre(directions[k], z), leg_centre(directions[(k + 1) % leg_count], z), 0.5 * leg_radius));
      }
    }
  }
  return b.finish();
}

ObjectAsset make_desk(uint32_t seed) {
  ObjectBuilder b(seed);
  UniformSource& r = b.random();
  // Desks are 0.73-0.76 m high (EN 527-1 gives 0.74 m for fixed-height desks), 1.1-1.6 m wide
  // and 0.6-0.75 m deep; the top is 25-35 mm thick.
  const double height = r.between(0.73, 0.76), width = r.between(1.1, 1.6), depth = r.between(0.6, 0.75);
  const double underside = height - r.between(0.025, 0.035);
  const uint32_t top = b.add_part("top", wooden(r));
  b.add(top, chamfered_box(dvec3(-0.5 * depth, -0.5 * width, underside), dvec3(0.5 * depth, 0.5 * width, height),
                           kEasedEdge));

  // 0: a drawer pedestal at one end and two legs at the other; 1: four legs with drawers in the
  // front apron; 2: two panel ends with a drawer box hung under the top.
  const uint32_t layout = r.choice(3);
  const LegStyle style = layout == 1 ? random_leg_style(r) : (r.next() < 0.5 ? LegStyle::Square : LegStyle::Tapered);
  const uint32_t frame = b.add_part("frame", style == LegStyle::Tube ? Finish::BrushedMetal : wooden(r));
  const uint32_t drawers = b.add_part("drawers", wooden(r));
  const uint32_t handles = b.add_part("handles", Finish::BrushedMetal);
  const HandleStyle handle = r.next() < 0.7 ? HandleStyle::Bar : HandleStyle::Knob;
  constexpr double kFront = 0.018;                  // drawer fronts are 18 mm boards
  const double side = r.next() < 0.5 ? -1.0 : 1.0;  // the end with the drawers
  const double half_depth = 0.5 * depth, half_width = 0.5 * width;
  // The y range from `near` to `far` in from the edge at the drawer end.
  const auto from_end = [&](double near, double far) {
    return side > 0.0 ? dvec2(half_width - far, half_width - near) : dvec2(near - half_width, far - half_width);
  };

  if (layout == 0) {
    // A pedestal 0.40-0.45 m wide of two or three drawers over a recessed plinth.
    const double plinth = 0.06, face = half_depth - 0.03 - kFront;
    const dvec2 span = from_end(0.02, 0.02 + r.between(0.4, 0.45));
    b.add(frame, box_mesh(dvec3(0.02 - half_depth, span.x, plinth), dvec3(face, span.y, underside + kOverlap)));
    b.add(frame,
          box_mesh(dvec3(0.04 - half_depth, span.x + 0.02, 0.0), dvec3(face - 0.03, span.y - 0.02, plinth + kOverlap)));
    const int count = 2 + static_cast<int>(r.choice(2));
    const double pitch = (underside - plinth) / count;
    for (int k = 0; k < count; ++k) {
      add_drawer(b, drawers, handles, handle, face, kFront, span, dvec2(plinth + k * pitch, plinth + (k + 1) * pitch));
    }
    // Two legs at the far end, a rail between them and a modesty panel at the back.
    const double leg_thickness = r.between(0.04, 0.05), y = -side * (half_width - 0.05), x = half_depth - 0.05;
    for (const double end : {-1.0, 1.0}) {
      b.add(frame, leg(style, dvec2(end * x, y), underside + kOverlap, leg_thickness));
    }
    b.add(frame, box_mesh(dvec3(-x, y - 0.01, underside - 0.08), dvec3(x, y + 0.01, underside + kOverlap)));
    const double panel_y = side > 0.0 ? span.x : span.y;
    b.add(frame, box_mesh(dvec3(0.04 - half_depth, std::min(y, panel_y), underside - 0.35),
                          dvec3(0.058 - half_depth, std::max(y, panel_y), underside + kOverlap)));
  } else if (layout == 1) {
    // Steel tube legs are 30-40 mm across, wooden ones 45-60 mm; the apron is 11-13 cm deep to
    // take the drawers.
    const double leg_thickness = style == LegStyle::Tube ? r.between(0.03, 0.04) : r.between(0.045, 0.06);
    const dvec2 half = dvec2(half_depth, half_width) - dvec2(0.03 + 0.5 * leg_thickness);
    const double apron = r.between(0.11, 0.13);
    add_legs(b, frame, style, half, underside + kOverlap, leg_thickness);
    add_aprons(b, frame, half, leg_thickness, underside + kOverlap, apron, 0.02);
    const double face = apron_faces(half, leg_thickness).x;
    const dvec2 z_range(underside - apron + 0.01, underside - 0.005);
    const double drawer_width = r.between(0.35, 0.45);
    if (r.next() < 0.5) {
      add_drawer(b, drawers, handles, handle, face, kFront, dvec2(-0.5, 0.5) * drawer_width, z_range);
    } else {  // one beside each front leg
      const double inner = half.y - 0.5 * leg_thickness - 0.02;
      for (const double end : {-1.0, 1.0}) {
        const dvec2 span = end > 0.0 ? dvec2(inner - drawer_width, inner) : dvec2(-inner, drawer_width - inner);
        add_drawer(b, drawers, handles, handle, face, kFront, span, z_range);
      }
    }
  } else {
    // Panel ends 25-40 mm thick, a modesty panel at the back and a drawer box under the top.
    const double panel = r.between(0.025, 0.04), inner = half_width - 0.02 - panel;
    for (const double end : {-1.0, 1.0}) {
      const double outer = end * (half_width - 0.02);
      b.add(frame,
            chamfered_box(dvec3(0.02 - half_depth, std::min(outer, end * inner), 0.0),
                          dvec3(half_depth - 0.02, std::max(outer, end * inner), underside + kOverlap), kEasedEdge));
    }
    b.add(frame, box_mesh(dvec3(0.05 - half_depth, -inner - kOverlap, underside - 0.4),
                          dvec3(0.068 - half_depth, inner + kOverlap, underside + kOverlap)));
    const double face = half_depth - 0.04 - kFront;
    const dvec2 span = from_end(0.02 + panel - kOverlap, 0.02 + panel + r.between(0.4, 0.5));
    const dvec2 z_range(underside - 0.13, underside);
    b.add(frame, box_mesh(dvec3(0.1 - half_depth, span.x, z_range.x), dvec3(face, span.y, underside + kOverlap)));
    add_drawer(b, drawers, handles, handle, face, kFront, span, z_range);
  }
  return b.finish();
}

ObjectAsset make_cabinet(uint32_t seed) {
  ObjectBuilder b(seed);
  UniformSource& r = b.random();
  // A row of fronts across the cabinet: `across` doors or drawers, `height` metres tall (0: a
  // share of what the fixed rows leave).
  struct Row {
    double height;
    int across;
    bool drawers;
  };
  std::vector<Row> rows;  // from the top down
  double height = 0.0, width = 0.0, depth = 0.0, base = 0.0;
  const uint32_t kind = r.choice(3);
  if (kind == 0) {
    // A bedside cabinet level with a mattress top: 0.62-0.70 m high, 0.42-0.55 m wide,
    // 0.35-0.42 m deep; two or three drawers, or a drawer over a door.
    height = r.between(0.62, 0.7), width = r.between(0.42, 0.55), depth = r.between(0.35, 0.42);
    base = r.between(0.08, 0.16);
    if (r.next() < 0.5) {
      rows.assign(2 + r.choice(2), Row{0.0, 1, true});
    } else {
      rows = {{0.15, 1, true}, {0.0, 1, false}};
    }
  } else if (kind == 1) {
    // A sideboard: 0.75-0.90 m high, 0.9-1.1 m wide, 0.40-0.48 m deep; two or three doors,
    // perhaps under a row of drawers.
    height = r.between(0.75, 0.9), width = r.between(0.9, 1.1), depth = r.between(0.4, 0.48);
    base = r.between(0.08, 0.18);
    const int across = width < 1.0 ? 2 : 3;
    if (r.next() < 0.5) rows.push_back({0.15, across, true});
    rows.push_back({0.0, across, false});
  } else {
    // A cupboard: 1.5-1.95 m high, 0.6-1.0 m wide, 0.40-0.55 m deep; one or two tall doors,
    // perhaps over a row of drawers.
    height = r.between(1.5, 1.95), width = r.between(0.6, 1.0), depth = r.between(0.4, 0.55);
    base = r.between(0.08, 0.12);
    const int across = width > 0.75 ? 2 : 1;
    rows.push_back({0.0, across, false});
    if (r.next() < 0.5) rows.push_back({0.2, across, true});
  }

  const uint32_t carcass = b.add_part("carcass", wooden(r));
  const uint32_t fronts = b.add_part("fronts", wooden(r));
  const uint32_t handles = b.add_part("handles", Finish::BrushedMetal);
  const HandleStyle handle = r.next() < 0.65 ? HandleStyle::Bar : HandleStyle::Knob;
  constexpr double kDoor = 0.019;  // doors are 19 mm boards
  const double half_width = 0.5 * width, back = -0.5 * depth, face = 0.5 * depth - kDoor;

  // On tapered legs or a plinth recessed 3 cm, as a kick space.
  if (r.next() < 0.5) {
    const double leg_thickness = r.between(0.035, 0.045);
    add_legs(b, carcass, LegStyle::Tapered, dvec2(0.5 * depth, half_width) - dvec2(0.03 + 0.5 * leg_thickness),
             base + kOverlap, leg_thickness);
  } else {
    b.add(carcass,
          box_mesh(dvec3(back + 0.02, 0.03 - half_width, 0.0), dvec3(face - 0.03, half_width - 0.03, base + kOverlap)));
  }
  // The carcass, maybe under a top board overhanging the sides and the front by 1-2 cm.
  double fronts_top = height;
  if (r.next() < 0.5) {
    const double overhang = r.between(0.01, 0.02), board = r.between(0.02, 0.03);
    fronts_top = height - board;
    b.add(carcass, chamfered_box(dvec3(back, -half_width - overhang, fronts_top),
                                 dvec3(0.5 * depth + overhang, half_width + overhang, height), kEasedEdge));
  }
  b.add(carcass, box_mesh(dvec3(back, -half_width, base), dvec3(face, half_width, fronts_top + kOverlap)));

  double fixed = 0.0;
  int shared = 0;
  for (const Row& row : rows) {
    if (row.height > 0.0) {
      fixed += row.height;
    } else {
      ++shared;
    }
  }
  const double share = (fronts_top - base - fixed) / shared;
  double row_top = fronts_top;
  for (const Row& row : rows) {
    const dvec2 z_range(row_top - (row.height > 0.0 ? row.height : share), row_top);
    row_top = z_range.x;
    const double cell = width / row.across;
    for (int k = 0; k < row.across; ++k) {
      const dvec2 span(-half_width + k * cell, -half_width + (k + 1) * cell);
      if (row.drawers) {
        add_drawer(b, fronts, handles, handle, face, kDoor, span, z_range);
        continue;
      }
      b.add(fronts, front_panel(face, kDoor, span, z_range));
      // The handle 45 mm from the edge nearer the middle (the opening edge of a pair of doors),
      // near the top of a low door and at about 1 m, where the hand is, on a tall one.
      const double centre = 0.5 * (span.x + span.y), edge = centre > 1e-6 ? span.x + 0.045 : span.y - 0.045;
      const double z = z_range.y < 1.1 ? z_range.y - 0.09 : std::clamp(1.0, z_range.x + 0.2, z_range.y - 0.2);
      add_handle(b, handles, handle, face + kDoor, dvec2(edge, z), false, r.between(0.128, 0.192));
    }
  }
  return b.finish();
}

ObjectAsset make_shelf(uint32_t seed) {
  ObjectBuilder b(seed);
  UniformSource& r = b.random();
  // Bookcases are 0.9-1.9 m high, 0.7-1.0 m wide and 0.25-0.35 m deep (paperbacks are 0.11 m
  // deep, large art books 0.3 m), their shelves 0.28-0.38 m apart: a 0.24 m book and a hand.
  const double height = r.between(0.9, 1.9), width = r.between(0.7, 1.0), depth = r.between(0.25, 0.35);
  const double pitch = r.between(0.28, 0.38), board = r.between(0.018, 0.025);
  const bool posts = r.next() < 0.35;  // steel posts carrying boards, else a panel bookcase
  const uint32_t frame = b.add_part("frame", posts ? Finish::BrushedMetal : wooden(r));
  const uint32_t boards = b.add_part("boards", wooden(r));
  const double half_depth = 0.5 * depth, half_width = 0.5 * width;

  if (posts) {
    // Four 25 mm posts, boards from 8-12 cm above the floor to the top, maybe an X-brace behind.
    const double post = 0.0125, bottom = r.between(0.08, 0.12);
    const dvec2 half(half_depth - post, half_width - post);
    // The posts stop 3 mm under the top board's top, so no two top faces lie in one plane.
    add_legs(b, frame, r.next() < 0.5 ? LegStyle::Square : LegStyle::Tube, half, height - 0.003, 2.0 * post);
    const int gaps = std::max(2, static_cast<int>(std::lround((height - board - bottom) / pitch)));
    for (int k = 0; k <= gaps; ++k) {
      const double z = bottom + (height - board - bottom) * k / gaps;
      b.add(boards,
            chamfered_box(dvec3(-half_depth, -half_width, z), dvec3(half_depth, half_width, z + board), kEasedEdge));
    }
    if (r.next() < 0.5) {
      const double x = -half_depth - 0.003;
      for (const double end : {-1.0, 1.0}) {
        b.add(frame, rod(dvec3(x, -end * half.y, bottom), dvec3(x, end * half.y, height - board), 0.004));
      }
    }
    return b.finish();
  }

  // Two sides under a top board, a kick board at the front, maybe a 6 mm back panel, and the
  // shelves between the sides from the bottom board up.
  const double plinth = r.between(0.06, 0.1), inner = half_width - board + kOverlap;
  for (const double side : {-1.0, 1.0}) {
    const double outer = side * half_width, inside = side * (half_width - board);
    b.add(frame, chamfered_box(dvec3(-half_depth, std::min(outer, inside), 0.0),
                               dvec3(half_depth, std::max(outer, inside), height - board + kOverlap), kEasedEdge));
  }
  b.add(frame, chamfered_box(dvec3(-half_depth, -half_width, height - board), dvec3(half_depth, half_width, height),
                             kEasedEdge));
  b.add(frame,
        box_mesh(dvec3(half_depth - 0.02 - board, -inner, 0.0), dvec3(half_depth - 0.02, inner, plinth + kOverlap)));
  const double back_panel = r.next() < 0.6 ? 0.006 : 0.0;
  if (back_panel > 0.0) {
    b.add(frame, box_mesh(dvec3(-half_depth, -inner, plinth),
                          dvec3(-half_depth + back_panel, inner, height - board + kOverlap)));
  }
  const int gaps = std::max(2, static_cast<int>(std::lround((height - board - plinth) / pitch)));
  for (int k = 0; k < gaps; ++k) {
    const double z = plinth + (height - board - plinth) * k / gaps;
    b.add(boards, chamfered_box(dvec3(-half_depth + back_panel, -inner, z), dvec3(half_depth - 0.01, inner, z + board),
                                kEasedEdge));
  }
  return b.finish();
}

ObjectAsset make_sofa(uint32_t seed) {
  ObjectBuilder b(seed);
  UniformSource& r = b.random();
  // Sofa (catalogue norms): 1.6-2.25 m wide with two or three seats, 0.85-0.95 m deep, seat
  // 0.42-0.46 m high on 12-16 cm cushions, arms 0.58-0.66 m, back 0.75-0.85 m.
  const double width = r.between(1.6, 2.25), depth = r.between(0.85, 0.95);
  const double seat_height = r.between(0.42, 0.46), seat_cushion = r.between(0.12, 0.16);
  const double arm_height = r.between(0.58, 0.66), back_top = r.between(0.75, 0.85);
  const bool rolled_arms = r.next() < 0.4;
  const double arm_width = rolled_arms ? r.between(0.16, 0.2) : r.between(0.12, 0.2);
  const int seats = width > 1.95 ? 3 : 2;
  const double inner = width - 2.0 * arm_width, seat_width = inner / seats;
  const double back_depth = r.between(0.15, 0.2), leg_height = r.between(0.08, 0.16);
  const Finish cover = upholstery(r);
  const uint32_t frame = b.add_part("frame", cover);
  const uint32_t cushions = b.add_part("cushions", cover);
  const LegStyle leg_style = r.next() < 0.6 ? LegStyle::Tapered : LegStyle::Tube;
  const uint32_t legs = b.add_part("legs", leg_style == LegStyle::Tube ? Finish::BrushedMetal : wooden(r));

  // The seat cushions rest 1 cm sunk in the deck of the base; the base and back are padded
  // blocks with 2 cm soft edges.
  constexpr double kSoftEdge = 0.02;
  const double half_depth = 0.5 * depth, front_of_back = back_depth - half_depth;
  const double deck = seat_height - seat_cushion + 0.01;
  b.add(frame, chamfered_box(dvec3(-half_depth, -0.5 * inner - kOverlap, leg_height),
                             dvec3(half_depth, 0.5 * inner + kOverlap, deck), kSoftEdge));
  b.add(frame, chamfered_box(dvec3(-half_depth, -0.5 * inner - kOverlap, deck - kOverlap),
                             dvec3(front_of_back, 0.5 * inner + kOverlap, back_top), kSoftEdge));
  for (const double side : {-1.0, 1.0}) {
    const double outer = side * 0.5 * width, inside = side * 0.5 * inner;
    const double y0 = std::min(outer, inside), y1 = std::max(outer, inside);
    if (rolled_arms) {
      // A block under a roll as wide as the arm, running front to back.
      const double roll = 0.5 * arm_width;
      b.add(frame,
            chamfered_box(dvec3(-half_depth, y0, leg_height), dvec3(half_depth, y1, arm_height - roll), kSoftEdge));
      b.add(frame,
            transformed(cylinder_mesh(roll, -half_depth, half_depth, 2 * kRoundSegments),
                        translation(dvec3(0.0, 0.5 * (y0 + y1), arm_height - roll)) * rotation_about_y(0.5 * kPi)));
    } else {
      b.add(frame, chamfered_box(dvec3(-half_depth, y0, leg_height), dvec3(half_depth, y1, arm_height), kSoftEdge));
    }
  }

  // Seat cushions from the back to the front edge, back cushions leaning 12-18 degrees on the back
  // with their feet sunk 3 cm into the seat cushions and their tops near the back's top.
  const double lean = r.between(12.0, 18.0) * kPi / 180.0, back_cushion = r.between(0.14, 0.18);
  const double foot = seat_height - 0.03;
  const double back_height =
      (back_top + r.between(-0.02, 0.03) - foot - back_cushion * std::sin(lean)) / std::cos(lean);
  const dvec3 up_the_back(-std::sin(lean), 0.0, std::cos(lean)), out_of_the_back(std::cos(lean), 0.0, std::sin(lean));
  const double seat_depth = half_depth - front_of_back;
  for (int k = 0; k < seats; ++k) {
    const double y = -0.5 * inner + (k + 0.5) * seat_width;
    const dvec3 size(seat_depth, seat_width - 0.005, seat_cushion);  // 5 mm apart
    const dvec3 seat_centre(0.5 * (front_of_back + half_depth), y, deck + 0.5 * seat_cushion - 0.01);
    b.add(cushions, cushion(size, 6.0, translation(seat_centre)));
    const dvec3 back_centre =
        dvec3(front_of_back, y, foot) + 0.5 * back_height * up_the_back + 0.5 * back_cushion * out_of_the_back;
    b.add(cushions,
          cushion(dvec3(back_height, seat_width - 0.005, back_cushion), 4.0, leaning_cushion(back_centre, lean)));
  }

  // Legs under the corners, and under the middle of a three-seater's front and back.
  const double leg_thickness = r.between(0.035, 0.05);
  const dvec2 half = dvec2(half_depth, 0.5 * width) - dvec2(0.04 + 0.5 * leg_thickness);
  add_legs(b, legs, leg_style, half, leg_height + kOverlap, leg_thickness);
  if (seats == 3) {
    for (const double x : {-half.x, half.x}) {
      b.add(legs, leg(leg_style, dvec2(x, 0.0), leg_height + kOverlap, leg_thickness));
    }
  }
  return b.finish();
}

ObjectAsset make_bed(uint32_t seed) {
  ObjectBuilder b(seed);
  UniformSource& r = b.random();
  // European mattress sizes: 0.9, 1.4, 1.6 or 1.8 m wide, 2.0 m long, 18-25 cm thick.
  static const double kMattressWidths[] = {0.9, 1.4, 1.6, 1.8};
  const double mattress_width = kMattressWidths[r.choice(4)], mattress_length = 2.0;
  const double mattress_thickness = r.between(0.18, 0.25);
  // Rails 30-50 mm thick, 15-25 cm high, on 10-20 cm legs; the mattress sits 8 cm down in the
  // frame, its top 0.35-0.6 m high; the headboard stands 0.95-1.2 m.
  const double rail = r.between(0.03, 0.05), rail_height = r.between(0.15, 0.25), leg_height = r.between(0.1, 0.2);
  const double headboard = r.between(0.04, 0.08), headboard_height = r.between(0.95, 1.2);
  const bool upholstered = r.next() < 0.3;  // a padded divan with its rails down to the floor
  const bool footboard = !upholstered && r.next() < 0.4;
  const double width = mattress_width + 2.0 * rail + 0.02, length = mattress_length + 0.02 + headboard + rail;
  const double half_width = 0.5 * width, head = -0.5 * length, foot = 0.5 * length;
  const double rail_top = leg_height + rail_height, mattress_bottom = rail_top - 0.08;
  const double mattress_top = mattress_bottom + mattress_thickness;
  const uint32_t frame = b.add_part("frame", upholstered ? upholstery(r) : wooden(r));
  const uint32_t mattress = b.add_part("mattress", Finish::Fabric);
  const uint32_t duvet = b.add_part("duvet", Finish::Fabric);
  const uint32_t pillows = b.add_part("pillows", Finish::Fabric);

  const double edge = upholstered ? 0.02 : kEasedEdge, rails_bottom = upholstered ? 0.0 : leg_height;
  b.add(frame,
        chamfered_box(dvec3(head, -half_width, 0.0), dvec3(head + headboard, half_width, headboard_height), edge));
  for (const double side : {-1.0, 1.0}) {
    const double outer = side * half_width, inside = side * (half_width - rail);
    b.add(frame, chamfered_box(dvec3(head + headboard - kOverlap, std::min(outer, inside), rails_bottom),
                               dvec3(foot - rail + kOverlap, std::max(outer, inside), rail_top), edge));
  }
  if (footboard) {
    b.add(frame, chamfered_box(dvec3(foot - rail, -half_width, 0.0),
                               dvec3(foot, half_width, mattress_top + r.between(-0.05, 0.08)), edge));
  } else {
    b.add(frame, chamfered_box(dvec3(foot - rail, -half_width, rails_bottom), dvec3(foot, half_width, rail_top), edge));
    if (!upholstered) {  // the headboard carries the head end, two legs the foot
      const double leg_thickness = r.between(0.05, 0.07);
      for (const double side : {-1.0, 1.0}) {
        b.add(frame, leg(LegStyle::Square, dvec2(foot - 0.5 * leg_thickness, side * (half_width - 0.5 * leg_thickness)),
                         leg_height + kOverlap, leg_thickness));
      }
    }
  }

  // Mattress: a boxy cushion. Duvet: a soft quilt 5-8 cm thick over the foot two thirds,
  // 3 cm wider than the mattress each side and over its foot end.
  const double mattress_centre = 0.5 * (head + headboard + foot - rail);
  b.add(mattress, cushion(dvec3(mattress_length, mattress_width, mattress_thickness), 10.0,
                          translation(dvec3(mattress_centre, 0.0, mattress_bottom + 0.5 * mattress_thickness))));
  const double duvet_length = 0.65 * mattress_length + 0.03, duvet_thickness = r.between(0.05, 0.08);
  const double duvet_foot = mattress_centre + 0.5 * mattress_length + 0.03;
  const dvec3 duvet_centre(duvet_foot - 0.5 * duvet_length, 0.0, mattress_top + 0.5 * duvet_thickness - 0.015);
  b.add(duvet, cushion(dvec3(duvet_length, mattress_width + 0.06, duvet_thickness), 3.0, translation(duvet_centre)));

  // Pillows 50 x 70 cm (narrower two abreast on a 1.4 m bed), 12-16 cm thick, propped 12-18
  // degrees against the headboard.
  const int count = mattress_width < 1.2 ? 1 : 2;
  const double pillow_width = std::min(0.7, (mattress_width - 0.1) / count - 0.03), pillow_depth = 0.5;
  const double pillow_thickness = r.between(0.12, 0.16), tilt = r.between(12.0, 18.0) * kPi / 180.0;
  const dvec3 centre(head + headboard + 0.02 + 0.5 * pillow_depth * std::cos(tilt), 0.0,
                     mattress_top - 0.02 + 0.5 * pillow_thickness + 0.5 * pillow_depth * std::sin(tilt));
  for (int k = 0; k < count; ++k) {
    const double y = count == 1 ? 0.0 : (k == 0 ? -0.5 : 0.5) * (pillow_width + 0.03);
    b.add(pillows, cushion(dvec3(pillow_depth, pillow_width, pillow_thickness), 2.5,
                           translation(centre + dvec3(0.0, y, 0.0)) * rotation_about_y(tilt)));
  }
  return b.finish();
}

}  // namespace matgeom::builtin
