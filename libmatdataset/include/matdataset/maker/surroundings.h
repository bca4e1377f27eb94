#pragma once
// What stands around an object in make_dataset's frames (docs/make_dataset.md, "Surroundings"):
// nothing (the object alone in empty space), a floor it rests on, optionally with walls (a box
// room or a cyclorama's backdrop) and a ceiling, each surface in a material drawn per variant
// (the room is sized by the object's camera grid so that every camera is inside it), other
// objects on that floor, or the scan the object came from, the scan's other parts in their own
// colours and materials.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <variant>
#include <string>
#include <vector>

#include "matbase/document/document_node.h"
#include "matdataset/maker/drawn_number.h"
#include "matdataset/maker/material_candidate.h"
#include "matdataset/maker/seed_stream.h"
#include "matgeom/camera_grid.h"
#include "matgeom/mesh.h"
#include "matgeom/room.h"

namespace matdataset {

enum class SurroundingsKind { None, Floor, Distractors, Scan };

// Other objects on the floor around the target (`kind: distractors`): a number of them per frame,
// each one of the configuration's objects in a material drawn per variant, at a drawn size, gap
// and turn, their footprints apart from the target's and each other's.
struct DistractorsConfig {
  DrawnNumber count{2.0, 4.0};  // per frame, whole numbers
  // Built-ins or mesh files; none listed: every built-in object but the target's own.
  std::vector<std::variant<matrender::MeshFile, matrender::BuiltinObject>> objects;
  std::vector<MaterialCandidate> materials;  // drawn per variant for each distractor
  DrawnNumber scale{0.4, 1.0};  // a distractor's bounding sphere radius over the target's
  DrawnNumber gap{0.1, 1.5};    // between its footprint and the target's, in the target's footprint radii
  // A frame's draw is kept when the target shows at least this fraction of the pixels it shows
  // without distractors; otherwise it is drawn again, up to `tries` draws in all.
  double visible_fraction = 0.5;
  int tries = 8;
};

// The object back in the scan it came from (`kind: scan`): the object's mesh file is the scan,
// some of its parts the target, every other part the room, in the scan's own colours or materials.
struct ScanConfig {
  std::vector<std::string> target;  // part names; Replica's object 7 is "object_7"
  // A view where the room hides more of the target than this leaves (of the pixels the target
  // shows without it) is named as hidden: a scan has nothing to draw again.
  double visible_fraction = 0.5;
};

struct SurroundingsConfig {
  SurroundingsKind kind = SurroundingsKind::None;
  std::vector<MaterialCandidate> floor_materials;
  matgeom::RoomWalls walls = matgeom::RoomWalls::None;
  std::vector<MaterialCandidate> wall_materials;  // the walls' and the ceiling's
  bool ceiling = false;
  // The floor's half width (the walls' distance from the grid's centre) in camera grid radii;
  // none: 50 for a floor alone (its edge a hair under the horizon), 1.5 for a room.
  std::optional<double> size;
  DistractorsConfig distractors;  // kind: distractors
  ScanConfig scan;                // kind: scan
  bool present() const { return kind != SurroundingsKind::None; }
  // A room made to measure stands around the object (a floor, walls, a ceiling): every kind but a scan.
  bool made_room() const { return kind == SurroundingsKind::Floor || kind == SurroundingsKind::Distractors; }
  double room_size() const { return size ? *size : walls == matgeom::RoomWalls::None ? 50.0 : 1.5; }
};

// The configuration's `surroundings` (top-level or an object's): `none`, or a mapping with `kind`,
// `floor_materials`, `walls`, `wall_materials`, `ceiling`, `size` and, for distractors,
// `distractors`; or `kind: scan` with `target` and `visible_fraction`. Fails at the key at fault: a floor without
// materials, walls without theirs, a ceiling on anything but a box, a room too small to hold the
// cameras, a distractor that is no built-in or mesh file, a scan without a target.
// Whether the scan has the target's parts is checked where it is read (dataset_checks.h).
SurroundingsConfig read_surroundings(const matbase::DocumentNode& node, const std::filesystem::path& base);

// A variant's draw: the floor's and the walls' materials. A library candidate spelled without
// its ":seed" gets a seed drawn too, so every variant may have a floor of its own.
struct DrawnSurroundings {
  std::optional<MaterialCandidate> floor;
  std::optional<MaterialCandidate> walls;
};
// One of `candidates`, drawn from `draws` (two numbers); a library material without its ":seed"
// gets a seed drawn.
MaterialCandidate drawn_candidate(const std::vector<MaterialCandidate>& candidates, SeedStream& draws);

// Drawn from the configuration's seed and the variant's indices alone, so a shard or a resumed
// run draws the same.
DrawnSurroundings draw_surroundings(const SurroundingsConfig& config, uint64_t seed, size_t object, size_t variant);

// The height of the floor under an object of surface `object` (world space) framed by `grid`: its
// lowest point, or the grid's centre if that is lower.
double floor_height(const matgeom::TriangleMesh& object, const matgeom::CameraGridSpec& grid);

// The room around an object of surface `object` (world space) seen by the camera grid `grid`:
// the floor at the object's lowest point under the grid's centre, the walls and the ceiling
// room_size() grid radii from it, the cyclorama's backdrop facing the grid's middle azimuth, UVs
// at the paper's texel density for the object's area (matgeom::target_texel_density over a
// 4096-pixel tile), so maps without a physical size have the object's scale.
matgeom::RoomSpec surroundings_room(const SurroundingsConfig& config, const matgeom::TriangleMesh& object,
                                    const matgeom::CameraGridSpec& grid);

// The room as a scene file's "room" object spells it (docs/scene_format.md), as JSON text.
std::string room_scene_json(const matgeom::RoomSpec& room);

// "none", "floor", "distractors", "scan".
const char* surroundings_kind_name(SurroundingsKind kind);
// "none", "box", "cyclorama".
const char* walls_name(matgeom::RoomWalls walls);

}  // namespace matdataset
