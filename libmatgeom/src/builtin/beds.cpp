// Beds: a frame, a mattress, pillows.
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

ObjectAsset make_bed(uint32_t seed) {
  ObjectBuilder b(seed);
  matbase::UniformSource& r = b.random();
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
