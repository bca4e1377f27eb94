#pragma once
// A small room as a scanner delivers one (Replica's mesh_semantic.ply): one mesh, one part per
// scanned object named by its instance id ("object_<id>", as the PLY reader names Replica's
// object_id), the surface in vertex colours with no UVs and no materials. Made here so that
// examples and tests can put an object back in its scan without downloading one.
#include <string>

#include "matgeom/mesh.h"

namespace matgeom {

// The parts of the example scan: a 3.5 x 3.5 x 2.4 m room (floor, walls, ceiling) with a table at
// its centre, a vase on the table, a chair beside it and a cabinet against a wall.
inline constexpr const char* kExampleScanFloor = "object_1";
inline constexpr const char* kExampleScanWalls = "object_2";
inline constexpr const char* kExampleScanCeiling = "object_3";
inline constexpr const char* kExampleScanTable = "object_4";
inline constexpr const char* kExampleScanVase = "object_5";
inline constexpr const char* kExampleScanChair = "object_6";
inline constexpr const char* kExampleScanCabinet = "object_7";

// The example scan: +Z up, the floor at z = 0 centred on the origin, vertex normals and linear
// vertex colours (each object's colour, darker toward the floor as a scan's baked light is).
TriangleMesh example_scan();

}  // namespace matgeom
