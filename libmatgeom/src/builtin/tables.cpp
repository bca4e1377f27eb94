// Tables and desks: a top on legs and rails, a desk with drawers or a pedestal.
// Sizes follow common catalogue and standard dimensions (seat, table and desk heights, mattress
// sizes), quoted where they are used. Every object faces +x (the side the paper's camera grid
// looks from), its width along y.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "builtin/joinery.h"
#include "builtin/objects.h"

namespace matgeom::builtin {

ObjectAsset make_table(uint32_t seed) {
  ObjectBuilder b(seed);
  matbase::UniformSource& r = b.random();
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

ObjectAsset make_desk(uint32_t seed) {
  ObjectBuilder b(seed);
  matbase::UniformSource& r = b.random();
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

}  // namespace matgeom::builtin
