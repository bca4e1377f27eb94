// Soft furnishings and small decorations: a scatter cushion, a table lamp, a book and a standing
// photo frame, of the sizes and materials of ordinary household items. The render cameras look
// from the +x half of the sphere, so objects with a front (the frame) face +x.
#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "builtin/object_builder.h"
#include "builtin/objects.h"
#include "builtin/shapes.h"

namespace matgeom::builtin {
namespace {

constexpr int kAround = 48;  // segments around turned parts

glm::dmat4 translation(const glm::dvec3& offset) { return glm::translate(glm::dmat4(1.0), offset); }
glm::dmat4 rotation(double angle, const glm::dvec3& axis) { return glm::rotate(glm::dmat4(1.0), angle, axis); }

const glm::dvec3 kAxisX(1.0, 0.0, 0.0), kAxisY(0.0, 1.0, 0.0), kAxisZ(0.0, 0.0, 1.0);

// A prism spanning y0..y1 whose cross-section in the xz plane is the convex polygon `outline`
// ((x, z) points, counter-clockwise seen from -y). Flat faces with split normals.
TriangleMesh slab_mesh(const std::vector<glm::dvec2>& outline, double y0, double y1) {
  TriangleMesh mesh;
  const auto at = [](const glm::dvec2& p, double y) { return glm::dvec3(p.x, y, p.y); };
  const auto vertex = [&](const glm::dvec3& position, const glm::dvec3& normal) {
    mesh.positions.emplace_back(position);
    mesh.normals.emplace_back(normal);
    return static_cast<uint32_t>(mesh.positions.size() - 1);
  };
  const uint32_t corners = static_cast<uint32_t>(outline.size());
  // Caps as fans: the outline winds counter-clockwise about -y, so the back cap reverses it.
  for (const bool front : {true, false}) {
    const uint32_t first = static_cast<uint32_t>(mesh.positions.size());
    for (const glm::dvec2& p : outline) vertex(at(p, front ? y0 : y1), glm::dvec3(0.0, front ? -1.0 : 1.0, 0.0));
    for (uint32_t k = 1; k + 1 < corners; ++k) {
      if (front) {
        mesh.triangles.emplace_back(first, first + k, first + k + 1);
      } else {
        mesh.triangles.emplace_back(first, first + k + 1, first + k);
      }
    }
  }
  // One quad per edge, facing right of the counter-clockwise walk.
  for (uint32_t k = 0; k < corners; ++k) {
    const glm::dvec2 a = outline[k], b = outline[(k + 1) % corners];
    const glm::dvec2 d = glm::normalize(b - a);
    const glm::dvec3 normal(d.y, 0.0, -d.x);
    const uint32_t a0 = vertex(at(a, y0), normal), b0 = vertex(at(b, y0), normal);
    const uint32_t b1 = vertex(at(b, y1), normal), a1 = vertex(at(a, y1), normal);
    mesh.triangles.emplace_back(a0, b1, b0);
    mesh.triangles.emplace_back(a0, a1, b1);
  }
  return mesh;
}

// Four bars of width `border` mitred at the corners, round the rectangle of `size` (x, z) centred
// at `centre`, spanning y0..y1: a picture frame's moulding or a mount board's border.
TriangleMesh mitred_border(const glm::dvec2& centre, const glm::dvec2& size, double border, double y0, double y1) {
  const glm::dvec2 lo = centre - 0.5 * size, hi = centre + 0.5 * size;
  const glm::dvec2 inner_lo = lo + glm::dvec2(border), inner_hi = hi - glm::dvec2(border);
  const std::vector<std::vector<glm::dvec2>> bars = {
      {{lo.x, lo.y}, {hi.x, lo.y}, {inner_hi.x, inner_lo.y}, {inner_lo.x, inner_lo.y}},  // bottom
      {{hi.x, lo.y}, {hi.x, hi.y}, {inner_hi.x, inner_hi.y}, {inner_hi.x, inner_lo.y}},  // right
      {{hi.x, hi.y}, {lo.x, hi.y}, {inner_lo.x, inner_hi.y}, {inner_hi.x, inner_hi.y}},  // top
      {{lo.x, hi.y}, {lo.x, lo.y}, {inner_lo.x, inner_lo.y}, {inner_lo.x, inner_hi.y}},  // left
  };
  TriangleMesh mesh;
  for (const auto& bar : bars) append_part(mesh, slab_mesh(bar, y0, y1), 0);
  return mesh;
}

// A round cord of `radius` along the rectangle |x| = half.x, |y| = half.y in the plane z = 0,
// mitred at the corners: the piping sewn into a cushion's seam.
TriangleMesh rectangle_cord_mesh(const glm::dvec2& half, double radius, int sides) {
  const std::array<glm::dvec2, 4> corners = {
      {{half.x, -half.y}, {half.x, half.y}, {-half.x, half.y}, {-half.x, -half.y}}};
  // In the mitre plane through a corner the cross-section stretches along the diagonal, so the
  // tube keeps its radius along both edges; both edges compute it alike, so the corners weld.
  const auto mitre_point = [&](int corner, int side) {
    const glm::dvec2 c = corners[corner];
    const double angle = 2.0 * kPi * side / sides;
    const glm::dvec2 diagonal(c.x > 0.0 ? 1.0 : -1.0, c.y > 0.0 ? 1.0 : -1.0);
    return glm::dvec3(c + radius * std::cos(angle) * diagonal, radius * std::sin(angle));
  };
  TriangleMesh mesh;
  const uint32_t n = static_cast<uint32_t>(sides);
  for (int edge = 0; edge < 4; ++edge) {
    const int next = (edge + 1) % 4;
    const glm::dvec2 along = glm::normalize(corners[next] - corners[edge]);
    const glm::dvec3 outward(along.y, -along.x, 0.0);  // corners run counter-clockwise seen from +z
    const uint32_t first = static_cast<uint32_t>(mesh.positions.size());
    for (const int corner : {edge, next})
      for (int side = 0; side < sides; ++side) {
        const double angle = 2.0 * kPi * side / sides;
        mesh.positions.emplace_back(mitre_point(corner, side));
        mesh.normals.emplace_back(std::cos(angle) * outward + std::sin(angle) * kAxisZ);
      }
    // d(along) x d(angle) points outward, so (start, end, end + 1 step) winds counter-clockwise.
    for (uint32_t k = 0; k < n; ++k) {
      const uint32_t a = first + k, b = first + n + k, c = first + n + (k + 1) % n, d = first + (k + 1) % n;
      mesh.triangles.emplace_back(a, b, c);
      mesh.triangles.emplace_back(a, c, d);
    }
  }
  return mesh;
}

// Appends `samples` points of the arc of `radius` about `centre` from angle `from` to `to`
// (radians in the (r, z) plane), excluding the start.
void append_arc(std::vector<ProfilePoint>& profile, ProfilePoint centre, double radius, double from, double to,
                int samples) {
  for (int k = 1; k <= samples; ++k) {
    const double angle = from + (to - from) * k / samples;
    profile.push_back({centre.r + radius * std::cos(angle), centre.z + radius * std::sin(angle)});
  }
}

// A bead round the z axis: the circle of `radius` about (r, z) revolved in `segments`, walked
// counter-clockwise so that the material is on its left. Trims the edges of a lamp shade.
TriangleMesh bead_mesh(double r, double z, double radius, int segments) {
  std::vector<ProfilePoint> circle = {{r + radius, z}};
  append_arc(circle, {r, z}, radius, 0.0, 2.0 * kPi, 10);  // 36-degree steps: smooth, under the crease angle
  circle.back() = circle.front();  // the loop closes on exactly its first point
  return lathe_mesh(circle, segments);
}

// A horizontal rod of `radius` from the z axis out to `length`, at `azimuth` and height z.
TriangleMesh spoke_mesh(double radius, double length, double azimuth, double z) {
  const glm::dmat4 place = translation({0.0, 0.0, z}) * rotation(azimuth, kAxisZ) * rotation(0.5 * kPi, kAxisY);
  return transformed(cylinder_mesh(radius, 0.0, length, 12), place);
}

// Pieces gathered before they are placed, as (part, mesh).
using Pieces = std::vector<std::pair<uint32_t, TriangleMesh>>;

// Adds the pieces, moved together so that they rest on z = 0 centred on the z axis.
void add_on_floor_centred(ObjectBuilder& builder, const Pieces& pieces) {
  glm::dvec3 lower(std::numeric_limits<double>::infinity()), upper(-std::numeric_limits<double>::infinity());
  for (const auto& piece : pieces) {
    const Bounds3 bounds = mesh_bounds(piece.second);
    lower = glm::min(lower, bounds.lower);
    upper = glm::max(upper, bounds.upper);
  }
  const glm::dmat4 place = translation({-0.5 * (lower.x + upper.x), -0.5 * (lower.y + upper.y), -lower.z});
  for (const auto& [part, mesh] : pieces) builder.add(part, transformed(mesh, place));
}

}  // namespace

ObjectAsset make_pillow(uint32_t seed) {
  ObjectBuilder b(seed);
  matbase::UniformSource& r = b.random();
  // A square scatter cushion of 40-60 cm filled to 12-18 cm, or an oblong lumbar cushion of about
  // 30 x 50 cm, flatter.
  const bool lumbar = r.next() < 0.25;
  const double length = lumbar ? r.between(0.48, 0.58) : r.between(0.4, 0.6);
  const double breadth = lumbar ? r.between(0.28, 0.34) : length;
  const double thickness = lumbar ? r.between(0.1, 0.14) : r.between(0.12, 0.18);
  // Higher powers fill the corners: a plump feather cushion rather than a soft, slack one.
  const double edge_power = r.between(1.8, 3.2);
  const uint32_t cover = b.add_part("cover", Finish::Fabric);
  const glm::dmat4 lift = translation({0.0, 0.0, 0.5 * thickness});  // cushion_mesh is centred on z = 0
  // An even resolution puts a row of samples on the centre line, the lowest point, so it lands on 0.
  b.add(cover, transformed(cushion_mesh({length, breadth, thickness}, edge_power, 32), lift));
  // Half of them have a piped seam: a 4-6 mm cord in a fabric of its own, often contrasting.
  if (r.next() < 0.5) {
    const uint32_t piping = b.add_part("piping", Finish::Fabric);
    b.add(piping, transformed(rectangle_cord_mesh({0.5 * length, 0.5 * breadth}, r.between(0.004, 0.006), 12), lift));
  }
  return b.finish();
}

ObjectAsset make_lamp(uint32_t seed) {
  ObjectBuilder b(seed);
  matbase::UniformSource& r = b.random();
  // Either a ceramic urn body with a short metal neck, or a slim metal stem on a round plinth.
  const bool urn = r.next() < 0.4;
  const Finish plinth_finish = std::array<Finish, 3>{Finish::BrushedMetal, Finish::Wood, Finish::Concrete}[r.choice(3)];
  const uint32_t base = b.add_part("base", urn ? Finish::Ceramic : plinth_finish);
  const uint32_t stem = b.add_part("stem", Finish::BrushedMetal);  // with the socket, harp and finial
  const uint32_t shade = b.add_part("shade", r.next() < 0.7 ? Finish::Fabric : Finish::Paper);

  double base_top = 0.0, socket_bottom = 0.0, rod_radius = 0.0;
  if (urn) {
    // A solid of revolution 20-26 cm tall: a foot ring, a belly of 15-20 cm across, a neck.
    base_top = r.between(0.2, 0.26);
    const double foot_radius = r.between(0.045, 0.055), belly_radius = r.between(0.075, 0.1);
    const double neck_radius = r.between(0.02, 0.028), foot_height = 0.012, neck_height = 0.02;
    const double body_bottom_radius = 0.85 * foot_radius;
    const double bulge = belly_radius - 0.5 * (body_bottom_radius + neck_radius);
    std::vector<ProfilePoint> profile = {{0.0, 0.0}, {foot_radius, 0.0}, {foot_radius, foot_height}};
    constexpr int kBodySamples = 20;
    for (int k = 0; k <= kBodySamples; ++k) {
      const double t = static_cast<double>(k) / kBodySamples;
      const double radius = body_bottom_radius + (neck_radius - body_bottom_radius) * t + bulge * std::sin(kPi * t);
      profile.push_back({radius, foot_height + (base_top - neck_height - foot_height) * t});
    }
    profile.push_back({neck_radius, base_top});
    profile.push_back({0.0, base_top});
    b.add(base, lathe_mesh(profile, kAround));
    socket_bottom = base_top + r.between(0.03, 0.05);
    rod_radius = r.between(0.01, 0.013);
  } else {
    // A plinth 12-17 cm across and 2-3.5 cm high with a rounded top edge, heavy enough to stand.
    const double radius = r.between(0.06, 0.085), edge = 0.006;
    base_top = r.between(0.02, 0.035);
    std::vector<ProfilePoint> profile = {{0.0, 0.0}, {radius, 0.0}, {radius, base_top - edge}};
    append_arc(profile, {radius - edge, base_top - edge}, edge, 0.0, 0.5 * kPi, 4);
    profile.push_back({0.0, base_top});
    b.add(base, lathe_mesh(profile, kAround));
    socket_bottom = base_top + r.between(0.2, 0.3);
    rod_radius = r.between(0.006, 0.01);
  }
  // The rod sinks a few millimetres into the base; an E27 socket about 3 cm across and 5.5 cm tall.
  b.add(stem, cylinder_mesh(rod_radius, base_top - 0.004, socket_bottom, 24));
  const double socket_radius = 0.016, socket_top = socket_bottom + 0.055;
  b.add(stem, cylinder_mesh(socket_radius, socket_bottom, socket_top, 24));

  // The shade: a drum or a tapered empire shade 26-40 cm across at the bottom, its lower edge at
  // about the socket so that the bulb is hidden from the side. Finer around than the small parts.
  const int shade_segments = 64;
  const double bottom_radius = r.between(0.13, 0.2);
  const double top_radius = bottom_radius * (r.next() < 0.5 ? r.between(0.85, 1.0) : r.between(0.55, 0.7));
  const double shade_bottom = socket_bottom + r.between(0.0, 0.03), shade_top = shade_bottom + r.between(0.16, 0.24);
  const double wall = 0.002;
  // A closed ring: up the outside, in over the top edge, down the inside, out under the bottom.
  b.add(shade, lathe_mesh({{bottom_radius, shade_bottom},
                           {top_radius, shade_top},
                           {top_radius - wall, shade_top},
                           {bottom_radius - wall, shade_bottom},
                           {bottom_radius, shade_bottom}},
                          shade_segments));
  // Rolled trims over both edges.
  const double trim = 0.0025;
  b.add(shade, bead_mesh(bottom_radius - 0.5 * wall, shade_bottom + trim, trim, shade_segments));
  b.add(shade, bead_mesh(top_radius - 0.5 * wall, shade_top - trim, trim, shade_segments));

  // The harp: a saddle under the socket, two legs and an arch up to the shade's spider, whose
  // washer carries a ball finial; three spokes hold the spider in the shade's top ring.
  const double harp_half_width = 0.04, wire = 0.0018;
  const double arch_centre = shade_top - 0.006 - harp_half_width;
  b.add(stem, box_mesh({-harp_half_width - wire, -0.004, socket_bottom - 0.005},
                       {harp_half_width + wire, 0.004, socket_bottom}));
  for (const double side : {-1.0, 1.0}) {
    b.add(stem, transformed(cylinder_mesh(wire, socket_bottom - 0.004, arch_centre, 12),
                            translation({side * harp_half_width, 0.0, 0.0})));
  }
  b.add(stem,
        transformed(torus_arc_mesh(harp_half_width, wire, 0.0, kPi, 24, 12), translation({0.0, 0.0, arch_centre})));
  const double washer_top = shade_top - 0.002;
  b.add(stem, cylinder_mesh(0.012, washer_top - 0.005, washer_top, 24));
  for (int k = 0; k < 3; ++k) {
    b.add(stem, spoke_mesh(wire, top_radius - wall, 0.5 * kPi + 2.0 * kPi * k / 3.0, washer_top - 0.0025));
  }
  const double ball = r.between(0.009, 0.012), ball_centre = washer_top + 0.004 + 0.9 * ball;
  b.add(stem, cylinder_mesh(0.004, washer_top - 0.001, ball_centre, 12));
  std::vector<ProfilePoint> ball_profile = {{0.0, ball_centre - ball}};
  append_arc(ball_profile, {0.0, ball_centre}, ball, -0.5 * kPi, 0.5 * kPi, 12);
  ball_profile.back() = {0.0, ball_centre + ball};  // exactly on the axis
  b.add(stem, lathe_mesh(ball_profile, 24));
  return b.finish();
}

ObjectAsset make_book(uint32_t seed) {
  ObjectBuilder b(seed);
  matbase::UniformSource& r = b.random();
  // Trimmed page sizes (width x height) of common formats: mass-market and trade paperbacks,
  // demy and royal hardbacks, a large-format art book.
  static const std::array<glm::dvec2, 5> kFormats = {
      {{0.11, 0.178}, {0.135, 0.216}, {0.138, 0.216}, {0.156, 0.234}, {0.21, 0.28}}};
  const glm::dvec2 format = kFormats[r.choice(5)];
  const glm::dvec2 page = format * r.between(0.97, 1.03);  // publishers trim a little differently
  const bool hardcover = r.next() < 0.6;
  const double block = r.between(0.014, 0.045);  // the page block: some 150-600 pages
  // Hardback boards are 2-3 mm greyboard overhanging the pages by 2.5-4 mm; a paperback's card
  // cover is flush with them.
  const double board = hardcover ? r.between(0.0022, 0.003) : 0.0006;
  const double square = hardcover ? r.between(0.0025, 0.004) : 0.0;
  const double thickness = block + 2.0 * board;
  const double cover_width = page.x + square, cover_height = page.y + 2.0 * square;
  const Finish cover_finish =
      hardcover ? std::array<Finish, 3>{Finish::Fabric, Finish::Leather, Finish::Paper}[r.choice(3)] : Finish::Paper;
  const uint32_t cover = b.add_part("cover", cover_finish);
  const uint32_t pages = b.add_part("pages", Finish::Paper);

  // The spine runs along y at x = spine; the fore-edge faces -x.
  const double spine = 0.5 * cover_width;
  const glm::dvec2 lo(-0.5 * cover_width, -0.5 * cover_height), hi(spine, 0.5 * cover_height);
  b.add(cover, box_mesh({lo, 0.0}, {hi, board}));
  b.add(cover, box_mesh({lo, thickness - board}, {hi, thickness}));
  if (hardcover) {
    // A rounded spine: a cylinder across the book's thickness, flattened so that it bulges out by
    // 15-25 % of the thickness.
    const double roundness = r.between(0.3, 0.5);
    const glm::dmat4 place = translation({spine, 0.0, 0.5 * thickness}) *
                             glm::scale(glm::dmat4(1.0), glm::dvec3(roundness, 1.0, 1.0)) *
                             rotation(-0.5 * kPi, kAxisX);  // z axis onto y
    b.add(cover, transformed(cylinder_mesh(0.5 * thickness, lo.y, hi.y, 32), place));
  } else {
    b.add(cover, box_mesh({spine, lo.y, 0.0}, {spine + board, hi.y, thickness}));
  }
  // The page block reaches into the spine and stops `square` short of the boards' other edges (a
  // paperback's by half a millimetre, so the cut pages do not share faces with the cover).
  const double inset = hardcover ? square : 0.0005;
  b.add(pages, box_mesh({lo.x + inset, -0.5 * page.y + (hardcover ? 0.0 : inset), board},
                        {spine, 0.5 * page.y - (hardcover ? 0.0 : inset), thickness - board}));
  return b.finish();
}

ObjectAsset make_picture_frame(uint32_t seed) {
  ObjectBuilder b(seed);
  matbase::UniformSource& r = b.random();
  // Photo sizes 13 x 18, 15 x 20, 18 x 24 and 20 x 25 cm, portrait or, for the larger ones (so
  // the frame stands at least 15 cm tall), landscape.
  static const std::array<glm::dvec2, 4> kPhotos = {{{0.13, 0.18}, {0.15, 0.2}, {0.18, 0.24}, {0.2, 0.25}}};
  glm::dvec2 photo = kPhotos[r.choice(4)];
  if (photo.x >= 0.18 && r.next() < 0.5) photo = {photo.y, photo.x};
  const bool mounted = r.next() < 0.5;  // a mount board round the photo
  const double mount_border = r.between(0.02, 0.04);
  const bool metal = r.next() < 0.3;
  // Wooden mouldings 1.5-4 cm wide, slim metal profiles of about 1 cm.
  const double bar = metal ? r.between(0.008, 0.012) : r.between(0.015, 0.04);
  const double depth = metal ? r.between(0.01, 0.014) : r.between(0.012, 0.02);

  const Finish frame_finish = metal ? Finish::BrushedMetal : (r.next() < 0.6 ? Finish::Wood : Finish::PaintedWood);
  const uint32_t frame = b.add_part("frame", frame_finish);
  const uint32_t picture = b.add_part("picture", Finish::Paper);
  const uint32_t mount = mounted ? b.add_part("mount", Finish::Paper) : 0;
  // Hardboard, a velvet-covered or a card back.
  const Finish back_finish = std::array<Finish, 3>{Finish::Wood, Finish::Fabric, Finish::Paper}[r.choice(3)];
  const uint32_t back = b.add_part("back", back_finish);

  // Built facing -y with the bottom edge on z = 0 and the front at y = 0. The rebate behind the
  // moulding takes the picture 4 mm back (room for glass), then the back board, 2 mm proud.
  const double tuck = 0.004;  // how far the picture and boards reach under the moulding
  const glm::dvec2 opening = mounted ? photo + glm::dvec2(2.0 * mount_border) : photo - glm::dvec2(2.0 * tuck);
  const glm::dvec2 outer = opening + glm::dvec2(2.0 * bar);
  const glm::dvec2 centre(0.0, 0.5 * outer.y);
  const double picture_front = 0.004, picture_back = 0.005, back_rear = depth + 0.002;
  Pieces pieces;
  pieces.emplace_back(frame, mitred_border(centre, outer, bar, 0.0, depth));
  const glm::dvec2 picture_half = 0.5 * opening + glm::dvec2(tuck);
  const auto sheet = [&](const glm::dvec2& half, double y0, double y1) {
    return box_mesh({centre.x - half.x, y0, centre.y - half.y}, {centre.x + half.x, y1, centre.y + half.y});
  };
  pieces.emplace_back(picture, sheet(picture_half, picture_front, picture_back));
  if (mounted) {
    // 1.5 mm board overlapping the photo's edges by 3 mm; its border covers the rest.
    const double window_overlap = 0.003;
    pieces.emplace_back(mount, mitred_border(centre, 2.0 * picture_half, mount_border + tuck + window_overlap,
                                             picture_front - 0.0015, picture_front));
  }
  pieces.emplace_back(back, sheet(0.5 * opening + glm::dvec2(1.5 * tuck), picture_back, back_rear));

  // Leaning back 10-18 degrees about its bottom edge, it stands on the moulding's back edge and
  // on a strut hinged at 55-65 % of its height and splayed a further 20-28 degrees.
  const double tilt = glm::radians(r.between(10.0, 18.0));
  const glm::dmat4 lean = rotation(-tilt, kAxisX);  // the top goes toward +y
  for (auto& piece : pieces) piece.second = transformed(piece.second, lean);
  const double floor = -depth * std::sin(tilt);  // where the moulding's back edge now stands
  const glm::dvec4 hinge = lean * glm::dvec4(0.0, back_rear, r.between(0.55, 0.65) * outer.y, 1.0);
  const double splay = tilt + glm::radians(r.between(20.0, 28.0));
  const double strut_thickness = 0.003, strut_width = r.between(0.025, 0.035);
  // The strut's side, in (y, z): its top cut square to it, its foot cut level with the floor.
  const glm::dvec2 down(std::sin(splay), -std::cos(splay)), across(std::cos(splay), std::sin(splay));
  const glm::dvec2 top_front(hinge.y, hinge.z), top_back = top_front + strut_thickness * across;
  const auto to_floor = [&](const glm::dvec2& p) { return p + (p.y - floor) / std::cos(splay) * down; };
  const std::vector<glm::dvec2> strut_side = {top_front, to_floor(top_front), to_floor(top_back), top_back};
  // slab_mesh draws it in (x, z) and extrudes along y; a quarter turn about z makes x into y.
  pieces.emplace_back(back, transformed(slab_mesh(strut_side, -0.5 * strut_width, 0.5 * strut_width),
                                        rotation(0.5 * kPi, kAxisZ)));

  // Turned to face +x, toward the render cameras.
  for (auto& piece : pieces) piece.second = transformed(piece.second, rotation(0.5 * kPi, kAxisZ));
  add_on_floor_centred(b, pieces);
  return b.finish();
}

}  // namespace matgeom::builtin
