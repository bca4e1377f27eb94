#include "matgeom/builtin/example_scan.h"

#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "matgeom/builtin/builtin_objects.h"
#include "matgeom/mesh_parts.h"
#include "matgeom/room.h"

namespace matgeom {
namespace {

constexpr double kRoomHalfWidth = 1.75;
constexpr double kRoomHeight = 2.4;

// One scanned object: `mesh` as a single part named `name`, without UVs or tangents (a scan has
// none), coloured `color` times a gradient from 0.75 at the floor to 1 at the ceiling.
MeshPart scanned(TriangleMesh mesh, const char* name, const glm::vec3& color) {
  mesh.uvs.clear();
  mesh.tangents.clear();
  mesh.triangle_parts.clear();
  mesh.part_names = {name};
  mesh.colors.clear();
  for (const glm::vec3& p : mesh.positions)
    mesh.colors.push_back(color * (0.75f + 0.25f * glm::clamp(p.z / static_cast<float>(kRoomHeight), 0.0f, 1.0f)));
  MeshPart part;
  part.name = name;
  part.mesh = std::move(mesh);
  return part;
}

// Built-in object `name` turned `turn_deg` about +Z and moved to `at` (its base at at.z).
TriangleMesh placed_builtin(const char* name, const glm::dvec3& at, double turn_deg) {
  TriangleMesh mesh = make_builtin_object(name).mesh;
  transform_mesh(mesh, glm::rotate(glm::translate(glm::dmat4(1.0), at), glm::radians(turn_deg), glm::dvec3(0, 0, 1)));
  return mesh;
}

}  // namespace

TriangleMesh example_scan() {
  RoomSpec spec;
  spec.half_width = kRoomHalfWidth;
  spec.height = kRoomHeight;
  spec.walls = RoomWalls::Box;
  spec.ceiling = true;
  std::vector<MeshPart> room = split_parts(room_mesh(spec));  // floor, walls, ceiling
  const TriangleMesh table = placed_builtin("table", glm::dvec3(0.0), 0.0);
  const double table_top = mesh_bounds(table).upper.z;
  std::vector<MeshPart> parts = {
      scanned(room[0].mesh, kExampleScanFloor, {0.30f, 0.20f, 0.12f}),
      scanned(room[1].mesh, kExampleScanWalls, {0.70f, 0.68f, 0.62f}),
      scanned(room[2].mesh, kExampleScanCeiling, {0.80f, 0.80f, 0.78f}),
      scanned(table, kExampleScanTable, {0.45f, 0.30f, 0.18f}),
      scanned(placed_builtin("vase", glm::dvec3(0.0, 0.0, table_top), 0.0), kExampleScanVase, {0.20f, 0.35f, 0.60f}),
      scanned(placed_builtin("chair", glm::dvec3(0.9, 0.1, 0.0), 90.0), kExampleScanChair, {0.55f, 0.12f, 0.10f}),
      scanned(placed_builtin("cabinet", glm::dvec3(-1.1, 1.15, 0.0), 0.0), kExampleScanCabinet, {0.62f, 0.58f, 0.50f}),
  };
  return merge_parts(parts);
}

}  // namespace matgeom
