#pragma once
// A set for an object to stand in: a floor under it and, optionally, walls around it (a box's
// four sides, or a cyclorama: a photo studio's backdrop, the floor curving up into one back wall
// with no corner to catch the eye) and a ceiling. Every face looks into the room, so cameras
// inside it see the front of each surface; UVs are in metres divided by metres_per_uv, the same
// length on every surface, so a material keeps one scale across the floor and the walls.
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "matgeom/mesh.h"

namespace matgeom {

enum class RoomWalls { None, Box, Cyclorama };

struct RoomSpec {
  glm::dvec3 floor_center{0.0};  // the floor's height, and the point of it the room is centred on
  double half_width = 1.0;       // metres from the centre to each wall (or to the floor's edges)
  double height = 1.0;           // of the walls (and the ceiling) above the floor
  RoomWalls walls = RoomWalls::None;
  bool ceiling = false;          // a box's lid; refused with other walls
  // The cyclorama's backdrop stands at +Y; the cove joining it to the floor has this radius
  // (metres), at most the height and the room's width.
  double cove_radius = 0.25;
  double metres_per_uv = 1.0;
  // The room turned about the vertical through floor_center (radians, counter-clockwise seen from
  // above): where the cyclorama's backdrop stands.
  double turn_z = 0.0;
};

// The parts, by name, in this order where present: "floor", "walls", "ceiling".
inline constexpr const char* kRoomFloorPart = "floor";
inline constexpr const char* kRoomWallsPart = "walls";
inline constexpr const char* kRoomCeilingPart = "ceiling";

// What is wrong with `spec` (a size that is not finite and positive, a ceiling without a box's
// walls, a cove larger than the backdrop), as a sentence; nothing when it is fine.
std::optional<std::string> room_spec_problem(const RoomSpec& spec);

// The room's surfaces: normals facing the inside (smooth along the cove), UVs and tangents.
// Throws std::invalid_argument with room_spec_problem's sentence.
TriangleMesh room_mesh(const RoomSpec& spec);

}  // namespace matgeom
