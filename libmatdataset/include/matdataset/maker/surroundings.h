#pragma once
// What stands around an object in make_dataset's frames (docs/make_dataset.md, "Surroundings"):
// nothing (the object alone in empty space), or a floor it rests on, optionally with walls (a box
// room or a cyclorama's backdrop) and a ceiling, each surface in a material drawn per variant. The
// room is sized by the object's camera grid so that every camera is inside it.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "matbase/document/document_node.h"
#include "matdataset/maker/material_candidate.h"
#include "matgeom/camera_grid.h"
#include "matgeom/mesh.h"
#include "matgeom/room.h"

namespace matdataset {

enum class SurroundingsKind { None, Floor };

struct SurroundingsConfig {
  SurroundingsKind kind = SurroundingsKind::None;
  std::vector<MaterialCandidate> floor_materials;
  matgeom::RoomWalls walls = matgeom::RoomWalls::None;
  std::vector<MaterialCandidate> wall_materials;  // the walls' and the ceiling's
  bool ceiling = false;
  // The floor's half width (the walls' distance from the grid's centre) in camera grid radii;
  // none: 50 for a floor alone (its edge a hair under the horizon), 1.5 for a room.
  std::optional<double> size;
  double room_size() const { return size ? *size : walls == matgeom::RoomWalls::None ? 50.0 : 1.5; }
};

// The configuration's `surroundings` (top-level or an object's): `none`, or a mapping with `kind`,
// `floor_materials`, `walls`, `wall_materials`, `ceiling` and `size`. Fails at the key at fault:
// a floor without materials, walls without theirs, a ceiling on anything but a box, a room too
// small to hold the cameras.
SurroundingsConfig read_surroundings(const matbase::DocumentNode& node, const std::filesystem::path& base);

// A variant's draw: the floor's and the walls' materials. A library candidate spelled without
// its ":seed" gets a seed drawn too, so every variant may have a floor of its own.
struct DrawnSurroundings {
  std::optional<MaterialCandidate> floor;
  std::optional<MaterialCandidate> walls;
};
// Drawn from the configuration's seed and the variant's indices alone, so a shard or a resumed
// run draws the same.
DrawnSurroundings draw_surroundings(const SurroundingsConfig& config, uint64_t seed, size_t object, size_t variant);

// The room around an object of surface `object` (world space) seen by the camera grid `grid`:
// the floor at the object's lowest point under the grid's centre, the walls and the ceiling
// room_size() grid radii from it, the cyclorama's backdrop facing the grid's middle azimuth, UVs
// at the paper's texel density for the object's area (matgeom::target_texel_density over a
// 4096-pixel tile), so maps without a physical size have the object's scale.
matgeom::RoomSpec surroundings_room(const SurroundingsConfig& config, const matgeom::TriangleMesh& object,
                                    const matgeom::CameraGridSpec& grid);

// The room as a scene file's "room" object spells it (docs/scene_format.md), as JSON text.
std::string room_scene_json(const matgeom::RoomSpec& room);

// "none", "floor".
const char* surroundings_kind_name(SurroundingsKind kind);
// "none", "box", "cyclorama".
const char* walls_name(matgeom::RoomWalls walls);

}  // namespace matdataset
