// The example scan is laid out as a Replica scan (one part per object, named by its id, vertex
// colours, no UVs), its objects stand where a room's objects stand, and it survives being written
// in Replica's layout and read back by the PLY reader.
#include "matgeom/builtin/example_scan.h"

#include <algorithm>

#include <catch2/catch.hpp>

#include "matgeom/io/ply/ply_io.h"
#include "matgeom/mesh_parts.h"
#include "support/replica_ply.h"
#include "support/temp_dir.h"

using namespace matgeom;

namespace {

Bounds3 part_bounds(const TriangleMesh& scan, const char* name) {
  for (const MeshPart& part : split_parts(scan))
    if (part.name == name) return mesh_bounds(part.mesh);
  FAIL("no part " << name);
  return {};
}

}  // namespace

TEST_CASE("The example scan is a room of objects in vertex colours, one part per object id", "[geom]") {
  const TriangleMesh scan = example_scan();
  validate_mesh(scan, "example scan");
  CHECK(scan.part_names == std::vector<std::string>{kExampleScanFloor, kExampleScanWalls, kExampleScanCeiling,
                                                    kExampleScanTable, kExampleScanVase, kExampleScanChair,
                                                    kExampleScanCabinet});
  CHECK(scan.uvs.empty());
  CHECK(scan.tangents.empty());
  CHECK(scan.normals.size() == scan.vertex_count());
  REQUIRE(scan.colors.size() == scan.vertex_count());
  for (const glm::vec3& c : scan.colors) CHECK((c.x > 0.0f && c.x < 1.0f && c.y > 0.0f && c.z > 0.0f));
  // Every object stands inside the room, on the floor or on the table.
  const Bounds3 room = part_bounds(scan, kExampleScanWalls);
  for (const char* object : {kExampleScanTable, kExampleScanChair, kExampleScanCabinet, kExampleScanVase}) {
    const Bounds3 b = part_bounds(scan, object);
    CHECK(b.lower.x > room.lower.x);
    CHECK(b.upper.x < room.upper.x);
    CHECK(b.lower.y > room.lower.y);
    CHECK(b.upper.y < room.upper.y);
    CHECK(b.upper.z < room.upper.z);
  }
  CHECK(part_bounds(scan, kExampleScanTable).lower.z == Approx(0.0).margin(1e-6));
  CHECK(part_bounds(scan, kExampleScanVase).lower.z == Approx(part_bounds(scan, kExampleScanTable).upper.z).margin(1e-5));
  // The chair and the cabinet stand clear of the table.
  const Bounds3 table = part_bounds(scan, kExampleScanTable);
  for (const char* object : {kExampleScanChair, kExampleScanCabinet}) {
    const Bounds3 b = part_bounds(scan, object);
    CHECK((b.lower.x > table.upper.x || b.upper.x < table.lower.x || b.lower.y > table.upper.y || b.upper.y < table.lower.y));
  }
}

TEST_CASE("The example scan written as Replica writes scans reads back part by part, colours to the byte", "[geom]") {
  TempDir dir;
  const TriangleMesh scan = example_scan();
  write_replica_ply(scan, dir.file("mesh_semantic.ply"));
  const TriangleMesh read = read_ply(dir.file("mesh_semantic.ply"));
  CHECK(read.part_names == scan.part_names);  // object_1 ... object_7, in id order
  CHECK(read.positions == scan.positions);
  CHECK(read.triangles == scan.triangles);
  CHECK(read.triangle_parts == scan.triangle_parts);
  REQUIRE(read.colors.size() == scan.colors.size());
  // A byte of sRGB is at most 1/510 of the encoded range off, a little more in linear terms.
  float worst = 0.0f;
  for (size_t v = 0; v < scan.colors.size(); ++v)
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(read.colors[v][c] - scan.colors[v][c]));
  CHECK(worst < 0.005f);
}
