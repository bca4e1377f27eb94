#pragma once
// Joinery: the legs, rails, fronts and handles that furniture is put together from, and the
// finishes it is given.
#include <array>
#include <cstdint>
#include <vector>

#include "builtin/furniture_solids.h"
#include "builtin/materials.h"
#include "builtin/object_builder.h"
#include "matbase/uniform_source.h"

namespace matgeom::builtin {

inline Finish wooden(matbase::UniformSource& random) { return random.next() < 0.65 ? Finish::Wood : Finish::PaintedWood; }
inline Finish upholstery(matbase::UniformSource& random) { return random.next() < 0.7 ? Finish::Fabric : Finish::Leather; }

enum class LegStyle { Square, Tapered, Turned, Tube };

inline LegStyle random_leg_style(matbase::UniformSource& random) { return static_cast<LegStyle>(random.choice(4)); }

// A turned leg, as on a lathe: a plain cylindrical block at the top where the rails join, a bead,
// a baluster narrowing to a slim ankle and a small foot. Shape as (radius, height) fractions.
std::vector<ProfilePoint> turned_leg_profile(double radius, double height);

// A leg standing on the floor at `at`, up to `top_z`; `thickness` is its width at the top.
TriangleMesh leg(LegStyle style, const dvec2& at, double top_z, double thickness);

// A plain post of the leg's section from `bottom` to `top` (a chair's back post, leaning).
TriangleMesh post(LegStyle style, const dvec3& bottom, const dvec3& top, double thickness);

// The four corners (+-half.x, +-half.y).
std::array<dvec2, 4> corners(const dvec2& half);

// Four legs with their centres at the corners (+-half.x, +-half.y), up to `top_z`.
void add_legs(ObjectBuilder& b, uint32_t part, LegStyle style, const dvec2& half, double top_z, double thickness);

// Where the outer faces of aprons between legs of `leg_thickness` centred at +-half lie: set back
// 5 mm from the legs' outer faces, as a joiner sets rails so the leg's edge stays crisp.
inline dvec2 apron_faces(const dvec2& half, double leg_thickness) { return half + dvec2(0.5 * leg_thickness - 0.005); }

// The four rails (aprons) between legs centred at +-half, from `top_z - height` to `top_z`.
void add_aprons(ObjectBuilder& b, uint32_t part, const dvec2& half, double leg_thickness, double top_z, double height,
                double thickness);

enum class HandleStyle { Bar, Knob };

// A mushroom knob along +z, 25 mm deep with a 28 mm head on a 12 mm neck, as sold for cabinets.
std::vector<ProfilePoint> knob_profile();

// A handle on a front whose face is at x = face_x, centred at (y, z): a bar pull (a 10 mm bar
// 28 mm proud on two posts) lying along y if `horizontal`, along z otherwise, or a knob.
void add_handle(ObjectBuilder& b, uint32_t part, HandleStyle style, double face_x, const dvec2& centre, bool horizontal,
                double length);

// A door or drawer front on a carcass whose front face is at x = face_x, covering y0..y1 and
// z0..z1 less the gap to its neighbours.
TriangleMesh front_panel(double face_x, double thickness, const dvec2& y_range, const dvec2& z_range);

// A drawer front with a handle at its centre: a knob, or a horizontal bar a third as wide as the
// front within the common 96-192 mm sizes.
void add_drawer(ObjectBuilder& b, uint32_t front_part, uint32_t handle_part, HandleStyle style, double face_x,
                double thickness, const dvec2& y_range, const dvec2& z_range);

}  // namespace matgeom::builtin
