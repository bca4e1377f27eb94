#include "matdataset/maker/surroundings.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <nlohmann/json.hpp>

#include "matbase/file/input_file.h"
#include "matbase/pi.h"
#include "matgeom/builtin/builtin_objects.h"
#include "matdataset/maker/seed_stream.h"
#include "matgeom/uv/uv_pass.h"

namespace matdataset {
namespace {

namespace fs = std::filesystem;
using matbase::DocumentNode;

// Larger than this, the floor's far edge would strain single precision for a small object.
constexpr double kMaxRoomSize = 1000.0;
// The walls stand at least this many grid radii out, so no camera is outside the room.
constexpr double kMinRoomSize = 1.1;
// Library seeds drawn for candidates without one, below this: names stay short.
constexpr uint64_t kDrawnSeeds = 100000;
// Keeps the surroundings' draw apart from every other draw made from the same indices.
constexpr uint64_t kSurroundingsSalt = 0x5355'5252'4f55'4e44ull;  // "SURROUND"
// One tile of the UV pass: texels a side (matgeom::UvPassOptions::tile_resolution's default).
constexpr double kTilePixels = 4096.0;

std::vector<MaterialCandidate> read_candidates(const DocumentNode& list, const fs::path& base) {
  std::vector<MaterialCandidate> candidates;
  for (const DocumentNode& item : list.items("a list of materials")) candidates.push_back(read_material_candidate(item, base));
  if (candidates.empty()) list.fail("an empty list: give at least one material");
  return candidates;
}

}  // namespace

MaterialCandidate drawn_candidate(const std::vector<MaterialCandidate>& candidates, SeedStream& stream) {
  const MaterialCandidate& chosen = candidates[stream.next() % candidates.size()];
  const auto* spec = std::get_if<matmaterial::LibraryMaterialSpec>(&chosen.source);
  const uint64_t drawn_seed = stream.next() % kDrawnSeeds;  // drawn whatever is chosen, so draws stay in step
  if (!spec || chosen.seed_given) return chosen;
  matmaterial::LibraryMaterialSpec seeded = *spec;
  seeded.seed = static_cast<uint32_t>(drawn_seed);
  MaterialCandidate candidate = library_candidate(seeded, chosen.spelled);
  candidate.seed_given = true;
  return candidate;
}

namespace {

DistractorsConfig read_distractors(const DocumentNode& node, const fs::path& base) {
  DistractorsConfig config;
  node.expect_keys({"count", "objects", "materials", "scale", "gap", "visible_fraction", "tries"});
  if (const std::optional<DocumentNode> n = node.find("count")) config.count = read_drawn_number(*n, 1.0, 64.0, false);
  if (config.count.low != std::floor(config.count.low) || config.count.high != std::floor(config.count.high))
    node.required("count").fail("expected whole numbers");
  if (const std::optional<DocumentNode> objects = node.find("objects")) {
    const std::vector<std::string> builtins = matgeom::builtin_object_names();
    for (const DocumentNode& item : objects->items("a list of built-in objects or {mesh: FILE}")) {
      if (item.is_text()) {
        config.objects.push_back(matrender::BuiltinObject{builtins[item.choice(builtins)], 0});
        continue;
      }
      item.expect_keys({"mesh"});
      const DocumentNode mesh = item.required("mesh");
      const fs::path path = fs::path(mesh.text()).is_absolute() ? fs::path(mesh.text()) : base / mesh.text();
      try {
        matbase::require_input_file(path.string());
      } catch (const std::exception& e) {
        mesh.fail(e.what());
      }
      config.objects.push_back(matrender::MeshFile{path.lexically_normal().string(), {}});
    }
    if (config.objects.empty()) objects->fail("an empty list: give at least one object, or leave `objects` out");
  }
  if (!node.has("materials")) node.fail("distractors need `materials`: the materials drawn for them");
  config.materials = read_candidates(node.required("materials"), base);
  if (const std::optional<DocumentNode> n = node.find("scale")) config.scale = read_drawn_number(*n, 0.01, 100.0, false);
  if (const std::optional<DocumentNode> n = node.find("gap")) config.gap = read_drawn_number(*n, 0.0, 100.0, false);
  if (const std::optional<DocumentNode> n = node.find("visible_fraction")) config.visible_fraction = n->unit_interval();
  if (const std::optional<DocumentNode> n = node.find("tries")) config.tries = n->integer_in(1, 1000);
  return config;
}

}  // namespace

SurroundingsConfig read_surroundings(const DocumentNode& node, const fs::path& base) {
  SurroundingsConfig config;
  if (node.is_word("none")) return config;
  if (!node.is_mapping()) node.fail_expected("`none` or a mapping with `kind: floor`, `distractors` or `scan`");
  constexpr std::array kKinds = {SurroundingsKind::None, SurroundingsKind::Floor, SurroundingsKind::Distractors,
                                 SurroundingsKind::Scan};
  config.kind = kKinds[node.required("kind").choice({"none", "floor", "distractors", "scan"})];
  if (config.kind == SurroundingsKind::None) {
    if (node.members().size() > 1) node.fail("`kind: none` takes no other keys");
    return config;
  }
  if (config.kind == SurroundingsKind::Scan) {
    node.expect_keys({"kind", "target", "visible_fraction"});
    if (!node.has("target")) node.fail("`kind: scan` needs `target`: the scan's parts that are the object");
    const DocumentNode target = node.required("target");
    for (const DocumentNode& part : target.items("a list of the scan's part names"))
      config.scan.target.push_back(part.text());
    if (config.scan.target.empty()) target.fail("an empty list: name at least one of the scan's parts");
    if (const std::optional<DocumentNode> n = node.find("visible_fraction")) config.scan.visible_fraction = n->unit_interval();
    return config;
  }
  node.expect_keys({"kind", "floor_materials", "walls", "wall_materials", "ceiling", "size", "distractors"});
  if (!node.has("floor_materials")) node.fail("a floor needs `floor_materials`: the materials drawn for it");
  config.floor_materials = read_candidates(node.required("floor_materials"), base);
  if (const std::optional<DocumentNode> walls = node.find("walls")) {
    constexpr std::array kWalls = {matgeom::RoomWalls::None, matgeom::RoomWalls::Box, matgeom::RoomWalls::Cyclorama};
    config.walls = kWalls[walls->choice({"none", "box", "cyclorama"})];
  }
  const std::optional<DocumentNode> wall_materials = node.find("wall_materials");
  if (config.walls == matgeom::RoomWalls::None && wall_materials)
    wall_materials->fail("there are no walls (`walls: none`) to put these on");
  if (config.walls != matgeom::RoomWalls::None) {
    if (!wall_materials) node.fail("walls need `wall_materials`: the materials drawn for them");
    config.wall_materials = read_candidates(*wall_materials, base);
  }
  if (const std::optional<DocumentNode> ceiling = node.find("ceiling")) {
    config.ceiling = ceiling->boolean();
    if (config.ceiling && config.walls != matgeom::RoomWalls::Box)
      ceiling->fail("a ceiling stands on a box room's walls (`walls: box`)");
  }
  if (const std::optional<DocumentNode> size = node.find("size"))
    config.size = size->number_in(kMinRoomSize, kMaxRoomSize);
  const std::optional<DocumentNode> distractors = node.find("distractors");
  if (config.kind == SurroundingsKind::Distractors) {
    if (!distractors) node.fail("`kind: distractors` needs `distractors`: at least their `materials`");
    config.distractors = read_distractors(*distractors, base);
  } else if (distractors) {
    distractors->fail("distractors stand around the target only with `kind: distractors`");
  }
  return config;
}

DrawnSurroundings draw_surroundings(const SurroundingsConfig& config, uint64_t seed, size_t object, size_t variant) {
  DrawnSurroundings drawn;
  if (config.kind == SurroundingsKind::None || config.kind == SurroundingsKind::Scan) return drawn;
  uint64_t h = splitmix64(seed ^ kSurroundingsSalt);
  for (const size_t index : {object, variant}) h = splitmix64(h ^ static_cast<uint64_t>(index));
  SeedStream stream(h);
  drawn.floor = drawn_candidate(config.floor_materials, stream);
  if (config.walls != matgeom::RoomWalls::None) drawn.walls = drawn_candidate(config.wall_materials, stream);
  return drawn;
}

double floor_height(const matgeom::TriangleMesh& object, const matgeom::CameraGridSpec& grid) {
  double lowest = grid.center.z;
  for (const glm::vec3& p : object.positions) lowest = std::min(lowest, static_cast<double>(p.z));
  return lowest;
}

matgeom::RoomSpec surroundings_room(const SurroundingsConfig& config, const matgeom::TriangleMesh& object,
                                    const matgeom::CameraGridSpec& grid) {
  const double lowest = floor_height(object, grid);
  matgeom::RoomSpec room;
  room.floor_center = glm::dvec3(grid.center.x, grid.center.y, lowest);
  room.half_width = config.room_size() * grid.radius;
  room.height = grid.center.z - lowest + config.room_size() * grid.radius;
  room.walls = config.walls;
  room.ceiling = config.ceiling;
  room.cove_radius = 0.3 * std::min(room.height, room.half_width);
  const double area = matgeom::surface_area(object);
  room.metres_per_uv = area > 0.0 ? kTilePixels / matgeom::target_texel_density(area) : 1.0;
  // The backdrop (at +Y before the turn) behind the object as the middle camera sees it.
  room.turn_z = 0.5 * (grid.theta_min + grid.theta_max) + 0.5 * matbase::kPi;
  return room;
}

std::string room_scene_json(const matgeom::RoomSpec& room) {
  const glm::dvec3& c = room.floor_center;
  nlohmann::ordered_json json = {{"floor_center", {c.x, c.y, c.z}},
                                 {"half_width", room.half_width},
                                 {"height", room.height},
                                 {"walls", walls_name(room.walls)},
                                 {"ceiling", room.ceiling},
                                 {"cove_radius", room.cove_radius},
                                 {"metres_per_uv", room.metres_per_uv},
                                 {"turn_z_deg", room.turn_z * 180.0 / matbase::kPi}};
  return json.dump();
}

const char* surroundings_kind_name(SurroundingsKind kind) {
  switch (kind) {
    case SurroundingsKind::Floor: return "floor";
    case SurroundingsKind::Distractors: return "distractors";
    case SurroundingsKind::Scan: return "scan";
    case SurroundingsKind::None:
    default: return "none";
  }
}

const char* walls_name(matgeom::RoomWalls walls) {
  switch (walls) {
    case matgeom::RoomWalls::Box: return "box";
    case matgeom::RoomWalls::Cyclorama: return "cyclorama";
    case matgeom::RoomWalls::None:
    default: return "none";
  }
}

}  // namespace matdataset
