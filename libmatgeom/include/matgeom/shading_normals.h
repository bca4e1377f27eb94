#pragma once
// Shading normals for the faces a mesh file gives none, as Blender 3.4 shades them: a face is
// flat or smooth, a smooth face takes at each corner the corner-angle-weighted mean of the face
// normals around the vertex, and Auto Smooth splits that mean at sharp edges.
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "matgeom/mesh.h"

namespace matgeom {

// Auto Smooth's angle lies in (0, kMaxAutoSmoothDeg] degrees: at 180 no edge is sharp.
constexpr double kMaxAutoSmoothDeg = 180.0;

// What a reader knows of the normals its file left out.
struct MissingNormals {
  // Per vertex: the file gives no normal for it. Empty: none is given.
  std::vector<bool> vertex_missing;
  // Per triangle: the face is shaded smooth (OBJ's "s 1"). Empty: every face is flat, which is
  // what Blender's importers give faces without normals unless the file says otherwise.
  std::vector<bool> smooth;
  // Per vertex: the vertex of the file it is a copy of (the reader splits one file vertex into
  // several at UV seams; Blender keeps it one vertex with several corners). Empty: itself.
  std::vector<uint32_t> file_vertex;
  // Blender's Auto Smooth (Shade Smooth, then Auto Smooth at this angle, in degrees): every face
  // with a missing normal is shaded smooth, except across edges where its neighbour meets it at
  // more than this angle. None: the faces keep `smooth`.
  std::optional<double> auto_smooth_deg;
};

// The shading normal of every triangle corner (3 t + k for corner k of triangle t), unit length,
// as Blender 3.4 computes normals for a mesh without custom normals (BKE_mesh_normals_loop_split):
// a flat triangle's corners take its face normal; a smooth triangle's corner takes the sum of the
// face normals around its file vertex, each weighted by the triangle's angle at that corner (the
// weight that makes the sum independent of how a planar polygon is triangulated). Without Auto
// Smooth every face around the vertex counts, flat ones too, as in Blender's vertex normals; with
// it, only the faces reached from the triangle around the vertex without crossing a sharp edge: one
// whose two faces meet at more than the angle, a boundary, an edge with more than two faces, an
// edge of a flat face, or an edge the two faces run along in the same direction (opposite
// windings). A degenerate triangle's face normal is +Z, which no ray sees.
std::vector<glm::vec3> blender_corner_normals(const TriangleMesh& mesh, const MissingNormals& missing);

// Fills in mesh.normals for the vertices `missing` names from blender_corner_normals, giving a
// vertex whose corners need different normals one copy per normal (positions, UVs and, when
// present, tangents copied). A mesh where no normal is given and every face is flat keeps no
// normals at all: that is flat shading (mesh.h), without tripling the vertices of a scan.
// Given normals are kept as they are.
void complete_missing_normals(TriangleMesh& mesh, const MissingNormals& missing);

// Per vertex: the first vertex at exactly the same position, for MissingNormals::file_vertex of
// a format that splits vertices at seams without saying which are one (glTF).
std::vector<uint32_t> vertices_by_position(const TriangleMesh& mesh);

// The mesh with one vertex per triangle corner, each with its face normal: flat shading made
// explicit, for what needs per-vertex normals (tangent frames for a normal map).
TriangleMesh flat_shaded(const TriangleMesh& mesh);

}  // namespace matgeom
