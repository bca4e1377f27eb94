// Seating: chairs, stools and sofas.
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

ObjectAsset make_chair(uint32_t seed) {
  ObjectBuilder b(seed);
  matbase::UniformSource& r = b.random();
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
  matbase::UniformSource& r = b.random();
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

ObjectAsset make_sofa(uint32_t seed) {
  ObjectBuilder b(seed);
  matbase::UniformSource& r = b.random();
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

}  // namespace matgeom::builtin
