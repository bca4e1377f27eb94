#pragma once
// Per-vertex tangent frames for tangent-space normal maps.
#include "matgeom/mesh.h"

namespace matgeom {

// Fills mesh.tangents following MikkTSpace's construction (Mikkelsen 2008): per-triangle
// tangents from the UV gradients, accumulated per vertex with the corner angle as weight,
// Gram-Schmidt orthogonalised against the vertex normal, w = handedness of the bitangent.
// Requires uvs; computes area-weighted normals first if the mesh has none. Degenerate UVs give
// an arbitrary tangent orthogonal to the normal (never NaN).
void compute_tangents(TriangleMesh& mesh);

// Area-weighted vertex normals (fills mesh.normals).
void compute_vertex_normals(TriangleMesh& mesh);

}  // namespace matgeom
