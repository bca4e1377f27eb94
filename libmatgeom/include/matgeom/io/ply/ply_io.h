#pragma once
// PLY meshes (ASCII, binary little- and big-endian): the format of Replica's scans. Written by
// hand rather than with OpenMesh: OpenMesh's half-edge mesh drops the non-manifold faces scans
// contain, and the union of a scan's parts must be the whole scan.
#include <optional>
#include <string>

#include "matgeom/mesh.h"

namespace matgeom {

struct PlyReadOptions {
  // Integer face property whose value becomes the triangle's part. Empty: the first present of
  // "part_id" (written by write_ply), "object_id" (Replica), "instance_id", "segment_id".
  std::string face_id_property;
  // Shade the faces smooth up to this angle where the file gives no normals (MissingNormals in
  // matgeom/shading_normals.h); none: flat, as Blender's PLY importer shades them.
  std::optional<double> auto_smooth_deg;
};

// Reads element "vertex" (x y z; nx ny nz, s t / u v / texture_u texture_v, and red green blue /
// diffuse_red diffuse_green diffuse_blue when present: colours are sRGB, an integer over its
// type's largest value (uchar / 255), kept linear in TriangleMesh::colors; faces
// without normals are flat, see PlyReadOptions) and
// element "face" (list "vertex_indices" or "vertex_index"; polygons are fan-triangulated).
// Parts: with write_ply's "comment part <k> <name>" lines, id k is part k of that table;
// otherwise the distinct ids in increasing order become parts 0, 1, ... named "<stem>_<id>",
// the stem being the property name without a trailing "_id" (object_id 7 -> "object_7").
// Without an id property every triangle is in part 0 named "default".
// Throws std::runtime_error starting with the path and naming the problem (not PLY, truncated,
// index out of range, non-finite vertex, no faces, unsupported property type...).
TriangleMesh read_ply(const std::string& path, const PlyReadOptions& options = {});

// Binary little-endian PLY with positions, normals, UVs (s, t) and colours (uchar red green blue,
// sRGB) when present, and the part of
// each face as "part_id" with the part names in comments. Written to a temporary file and
// renamed, so a failed write leaves nothing behind.
void write_ply(const TriangleMesh& mesh, const std::string& path);

}  // namespace matgeom
