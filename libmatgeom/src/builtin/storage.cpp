// Storage: cabinets with doors and drawers, open shelves.
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

ObjectAsset make_cabinet(uint32_t seed) {
  ObjectBuilder b(seed);
  matbase::UniformSource& r = b.random();
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
  matbase::UniformSource& r = b.random();
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

}  // namespace matgeom::builtin
