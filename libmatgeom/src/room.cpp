#include "matgeom/room.h"

#include <cmath>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include "matbase/pi.h"
#include "matgeom/tangents.h"

namespace matgeom {
namespace {

// Segments of the cyclorama's quarter-circle cove: a chord then sags by R (1 - cos(pi / 64)),
// about 0.1 % of the radius.
constexpr int kCoveSegments = 16;

class RoomBuilder {
 public:
  explicit RoomBuilder(double metres_per_uv) : metres_per_uv_(metres_per_uv) {}

  uint32_t part(const char* name) {
    mesh_.part_names.emplace_back(name);
    return static_cast<uint32_t>(mesh_.part_names.size() - 1);
  }

  // The rectangle o, o + a, o + a + b, o + b, counter-clockwise seen from cross(a, b)'s side, its
  // UVs from `uv` along a and b.
  void add_rectangle(uint32_t part, const glm::dvec3& o, const glm::dvec3& a, const glm::dvec3& b,
                     const glm::dvec2& uv = glm::dvec2(0.0)) {
    const glm::vec3 normal(glm::normalize(glm::cross(a, b)));
    const double du = glm::length(a) / metres_per_uv_, dv = glm::length(b) / metres_per_uv_;
    const uint32_t first = vertex(o, normal, uv);
    vertex(o + a, normal, uv + glm::dvec2(du, 0.0));
    vertex(o + a + b, normal, uv + glm::dvec2(du, dv));
    vertex(o + b, normal, uv + glm::dvec2(0.0, dv));
    quad(part, first, first + 1, first + 2, first + 3);
  }

  // A strip swept along +X from x0 to x1 through the profile's (y, z) points, each with its
  // normal's (y, z) and its distance along the profile.
  void add_swept_profile(uint32_t part, double x0, double x1, const std::vector<glm::dvec2>& points,
                         const std::vector<glm::dvec2>& normals, const std::vector<double>& lengths, size_t first,
                         size_t last) {
    const double u1 = (x1 - x0) / metres_per_uv_;
    uint32_t previous = 0;
    for (size_t k = first; k <= last; ++k) {
      const glm::vec3 normal(0.0f, static_cast<float>(normals[k].x), static_cast<float>(normals[k].y));
      const double v = lengths[k] / metres_per_uv_;
      const uint32_t left = vertex({x0, points[k].x, points[k].y}, normal, {0.0, v});
      vertex({x1, points[k].x, points[k].y}, normal, {u1, v});
      if (k > first) quad(part, previous, previous + 1, left + 1, left);
      previous = left;
    }
  }

  // The mesh turned by `turn_z` about the vertical through `pivot`.
  TriangleMesh finish(const glm::dvec3& pivot, double turn_z) {
    compute_tangents(mesh_);
    if (turn_z != 0.0) {
      const glm::dmat4 turn = glm::translate(glm::dmat4(1.0), pivot) *
                              glm::rotate(glm::dmat4(1.0), turn_z, glm::dvec3(0.0, 0.0, 1.0)) *
                              glm::translate(glm::dmat4(1.0), -pivot);
      transform_mesh(mesh_, turn);
    }
    return std::move(mesh_);
  }

 private:
  uint32_t vertex(const glm::dvec3& p, const glm::vec3& normal, const glm::dvec2& uv) {
    mesh_.positions.emplace_back(p);
    mesh_.normals.push_back(normal);
    mesh_.uvs.emplace_back(uv);
    return static_cast<uint32_t>(mesh_.positions.size() - 1);
  }
  void quad(uint32_t part, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
    mesh_.triangles.emplace_back(a, b, c);
    mesh_.triangles.emplace_back(a, c, d);
    mesh_.triangle_parts.insert(mesh_.triangle_parts.end(), 2, part);
  }

  double metres_per_uv_;
  TriangleMesh mesh_;
};

// The floor from the front edge (y = c.y - w) to the cove, the cove and the backdrop up to the
// height: the cyclorama's profile in (y, z), with its inward normals and lengths along it.
void add_cyclorama(RoomBuilder& room, const RoomSpec& spec, uint32_t floor, uint32_t walls) {
  const glm::dvec3& c = spec.floor_center;
  const double w = spec.half_width, r = spec.cove_radius;
  std::vector<glm::dvec2> points = {{c.y - w, c.z}}, normals = {{0.0, 1.0}};
  std::vector<double> lengths = {0.0};
  const glm::dvec2 cove_center(c.y + w - r, c.z + r);
  for (int k = 0; k <= kCoveSegments; ++k) {
    const double t = 0.5 * matbase::kPi * k / kCoveSegments;
    points.push_back(cove_center + r * glm::dvec2(std::sin(t), -std::cos(t)));
    normals.emplace_back(-std::sin(t), std::cos(t));
    lengths.push_back(lengths.back() + glm::length(points.back() - points[points.size() - 2]));
  }
  points.emplace_back(c.y + w, c.z + spec.height);
  normals.emplace_back(-1.0, 0.0);
  lengths.push_back(lengths.back() + (spec.height - r));
  room.add_swept_profile(floor, c.x - w, c.x + w, points, normals, lengths, 0, 1);
  room.add_swept_profile(walls, c.x - w, c.x + w, points, normals, lengths, 1, points.size() - 1);
}

}  // namespace

std::optional<std::string> room_spec_problem(const RoomSpec& spec) {
  const glm::dvec3& c = spec.floor_center;
  if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z)) return "the floor's centre is not finite";
  if (!std::isfinite(spec.turn_z)) return "the room's turn is not finite";
  for (const auto& [value, name] : {std::pair{spec.half_width, "half width"}, std::pair{spec.height, "height"},
                                    std::pair{spec.metres_per_uv, "metres per UV unit"}})
    if (!(std::isfinite(value) && value > 0.0)) return fmt::format("the room's {} is {}, not a positive length", name, value);
  if (spec.ceiling && spec.walls != RoomWalls::Box) return "a ceiling needs the box's walls to stand on";
  if (spec.walls == RoomWalls::Cyclorama &&
      !(std::isfinite(spec.cove_radius) && spec.cove_radius > 0.0 && spec.cove_radius <= spec.height &&
        spec.cove_radius <= 2.0 * spec.half_width))
    return fmt::format("the cyclorama's cove radius {} is not a length of at most the height ({}) and the room's width ({})",
                       spec.cove_radius, spec.height, 2.0 * spec.half_width);
  return std::nullopt;
}

TriangleMesh room_mesh(const RoomSpec& spec) {
  if (const std::optional<std::string> problem = room_spec_problem(spec)) throw std::invalid_argument("room: " + *problem);
  RoomBuilder room(spec.metres_per_uv);
  const glm::dvec3& c = spec.floor_center;
  const double w = spec.half_width, h = spec.height;
  const uint32_t floor = room.part(kRoomFloorPart);
  if (spec.walls == RoomWalls::Cyclorama) {
    add_cyclorama(room, spec, floor, room.part(kRoomWallsPart));
    return room.finish(c, spec.turn_z);
  }
  const glm::dvec3 x(2.0 * w, 0.0, 0.0), y(0.0, 2.0 * w, 0.0), up(0.0, 0.0, h);
  const glm::dvec3 low = c - glm::dvec3(w, w, 0.0);  // the floor's corner at -X, -Y
  room.add_rectangle(floor, low, x, y, {0.0, 0.0});
  if (spec.walls == RoomWalls::Box) {
    // Each wall's u runs on from the last's, around the room counter-clockwise seen from above.
    const uint32_t walls = room.part(kRoomWallsPart);
    const double side = 2.0 * w / spec.metres_per_uv;
    room.add_rectangle(walls, low + y, x, up, {0.0, 0.0});               // back (+Y), facing -Y
    room.add_rectangle(walls, low + x + y, -y, up, {side, 0.0});         // right (+X), facing -X
    room.add_rectangle(walls, low + x, -x, up, {2.0 * side, 0.0});       // front (-Y), facing +Y
    room.add_rectangle(walls, low, y, up, {3.0 * side, 0.0});            // left (-X), facing +X
    if (spec.ceiling) room.add_rectangle(room.part(kRoomCeilingPart), low + up, y, x);  // facing -Z
  }
  return room.finish(c, spec.turn_z);
}

}  // namespace matgeom
