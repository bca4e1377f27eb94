#include "matgeom/tangents.h"

#include <cmath>
#include <stdexcept>
#include <vector>

#include "triangle_area.h"

namespace matgeom {
namespace {

// Corners are processed in double precision: the per-face UV gradients divide small differences
// and float would lose the exact axis alignment of simple layouts.
struct Corner {
  glm::dvec3 position;
  glm::dvec2 uv;
};

// Any unit vector perpendicular to the unit vector n (Duff et al. 2017, "Building an
// Orthonormal Basis, Revisited"): used where the UVs give no direction.
glm::dvec3 any_perpendicular(const glm::dvec3& n) {
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z);
  const double b = n.x * n.y * a;
  return glm::dvec3(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
}

// The component of v perpendicular to the unit vector n, normalised; zero if none is left.
glm::dvec3 unit_projection_onto_plane(const glm::dvec3& v, const glm::dvec3& n) {
  const glm::dvec3 in_plane = v - n * glm::dot(n, v);
  const double length = glm::length(in_plane);
  return length > 0.0 ? in_plane / length : glm::dvec3(0.0);
}

glm::dvec3 unit_or_default(const glm::dvec3& v, const glm::dvec3& fallback) {
  const double length = glm::length(v);
  return length > 0.0 ? v / length : fallback;
}

// The direction in which u grows across one triangle (the first column of the inverse of the
// UV-to-position Jacobian), and its orientation: +1 when the UV triangle winds like the
// triangle itself (bitangent = +N x T), -1 when it is mirrored, 0 when the UVs are degenerate.
struct FaceTangent {
  glm::dvec3 tangent{0.0};
  int orientation = 0;
};

FaceTangent face_tangent(const Corner& c0, const Corner& c1, const Corner& c2) {
  const glm::dvec3 e1 = c1.position - c0.position;
  const glm::dvec3 e2 = c2.position - c0.position;
  const glm::dvec2 d1 = c1.uv - c0.uv;
  const glm::dvec2 d2 = c2.uv - c0.uv;
  const double uv_area = d1.x * d2.y - d2.x * d1.y;
  // Collinear UVs leave only rounding noise in uv_area; the relative test (the sine of the UV
  // corner angle) rejects them whatever the texture scale.
  const double scale = glm::length(d1) * glm::length(d2);
  FaceTangent face;
  if (!(std::abs(uv_area) > 1e-9 * scale)) return face;
  face.orientation = uv_area > 0.0 ? 1 : -1;
  // dP/du = (e1 dv2 - e2 dv1) / uv_area; only its direction is needed, so the division is
  // replaced by the sign, which keeps nearly degenerate faces finite.
  face.tangent = (e1 * d2.y - e2 * d1.y) * static_cast<double>(face.orientation);
  return face;
}

}  // namespace

void compute_vertex_normals(TriangleMesh& mesh) {
  validate_mesh(mesh, "compute_vertex_normals");
  std::vector<glm::dvec3> sums(mesh.vertex_count(), glm::dvec3(0.0));
  for (const glm::uvec3& triangle : mesh.triangles) {
    // The unnormalised cross product weights each face by its area, so zero-area faces add
    // nothing and slivers barely count.
    const glm::dvec3 weighted_normal = area_vector(glm::dvec3(mesh.positions[triangle[0]]),
                                                   glm::dvec3(mesh.positions[triangle[1]]),
                                                   glm::dvec3(mesh.positions[triangle[2]]));
    for (int corner = 0; corner < 3; ++corner) sums[triangle[corner]] += weighted_normal;
  }
  mesh.normals.resize(mesh.vertex_count());
  for (size_t v = 0; v < sums.size(); ++v) {
    mesh.normals[v] = glm::vec3(unit_or_default(sums[v], glm::dvec3(0.0, 0.0, 1.0)));
  }
}

void compute_tangents(TriangleMesh& mesh) {
  validate_mesh(mesh, "compute_tangents");
  const size_t vertex_count = mesh.vertex_count();
  if (mesh.uvs.size() != vertex_count) {
    throw std::invalid_argument("compute_tangents: the mesh needs one uv per vertex");
  }
  if (mesh.normals.size() != vertex_count) compute_vertex_normals(mesh);

  std::vector<glm::dvec3> normals(vertex_count);
  for (size_t v = 0; v < vertex_count; ++v) {
    normals[v] = unit_or_default(glm::dvec3(mesh.normals[v]), glm::dvec3(0.0, 0.0, 1.0));
  }

  struct TriangleFrame {
    FaceTangent face;
    double angles[3];
  };
  std::vector<TriangleFrame> frames;
  frames.reserve(mesh.triangle_count());
  // Angle-weighted handedness per vertex; MikkTSpace would split a vertex whose triangles
  // disagree (a mirror seam), but a vertex here has one tangent, so the majority wins.
  std::vector<double> orientation_votes(vertex_count, 0.0);
  for (const glm::uvec3& triangle : mesh.triangles) {
    Corner corners[3];
    for (int k = 0; k < 3; ++k) {
      corners[k] = {glm::dvec3(mesh.positions[triangle[k]]), glm::dvec2(mesh.uvs[triangle[k]])};
    }
    TriangleFrame frame;
    frame.face = face_tangent(corners[0], corners[1], corners[2]);
    for (int k = 0; k < 3; ++k) {
      frame.angles[k] = corner_angle(corners[k].position, corners[(k + 1) % 3].position,
                                     corners[(k + 2) % 3].position);
      orientation_votes[triangle[k]] += frame.angles[k] * frame.face.orientation;
    }
    frames.push_back(frame);
  }

  std::vector<int> handedness(vertex_count);
  for (size_t v = 0; v < vertex_count; ++v) handedness[v] = orientation_votes[v] < 0.0 ? -1 : 1;

  // MikkTSpace's accumulation: each face's tangent is projected into the tangent plane of the
  // vertex normal, normalised and weighted by the corner angle, so the result does not depend on
  // how the surface around the vertex is triangulated. Only faces of the vertex's handedness
  // take part: across a u-mirror seam the other side's tangents point the opposite way.
  std::vector<glm::dvec3> sums(vertex_count, glm::dvec3(0.0));
  for (size_t t = 0; t < frames.size(); ++t) {
    const TriangleFrame& frame = frames[t];
    if (frame.face.orientation == 0) continue;
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = mesh.triangles[t][k];
      if (frame.face.orientation != handedness[v]) continue;
      sums[v] += frame.angles[k] * unit_projection_onto_plane(frame.face.tangent, normals[v]);
    }
  }

  mesh.tangents.resize(vertex_count);
  for (size_t v = 0; v < vertex_count; ++v) {
    // Gram-Schmidt again: the sum of in-plane vectors is in the plane up to rounding.
    glm::dvec3 tangent = unit_projection_onto_plane(sums[v], normals[v]);
    if (tangent == glm::dvec3(0.0)) tangent = any_perpendicular(normals[v]);
    mesh.tangents[v] = glm::vec4(glm::vec3(tangent), static_cast<float>(handedness[v]));
  }
}

}  // namespace matgeom
