#include "builtin/joinery.h"

#include <algorithm>

namespace matgeom::builtin {

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

}  // namespace matgeom::builtin
