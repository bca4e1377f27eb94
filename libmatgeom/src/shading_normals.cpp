#include "matgeom/shading_normals.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <stdexcept>
#include <unordered_map>
#include <utility>

#include "triangle_area.h"

namespace matgeom {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A triangle's unit normal and its angle at each corner; a degenerate triangle has no normal
// (+Z stands in) and weighs nothing in a smooth vertex's mean.
struct FaceFrame {
  glm::dvec3 normal{0.0, 0.0, 1.0};
  std::array<double, 3> angles{};
  bool degenerate = true;
};

std::vector<FaceFrame> face_frames(const TriangleMesh& mesh) {
  std::vector<FaceFrame> frames(mesh.triangle_count());
  for (size_t t = 0; t < frames.size(); ++t) {
    const glm::uvec3& triangle = mesh.triangles[t];
    const std::array<glm::dvec3, 3> p = {glm::dvec3(mesh.positions[triangle[0]]), glm::dvec3(mesh.positions[triangle[1]]),
                                         glm::dvec3(mesh.positions[triangle[2]])};
    const glm::dvec3 area = area_vector(p[0], p[1], p[2]);
    const double length = glm::length(area);
    if (!(length > 0.0) || !std::isfinite(length)) continue;
    frames[t].normal = area / length;
    frames[t].degenerate = false;
    for (int k = 0; k < 3; ++k) frames[t].angles[k] = corner_angle(p[k], p[(k + 1) % 3], p[(k + 2) % 3]);
  }
  return frames;
}

// The shape of the question, checked once: per-vertex and per-triangle arrays of the right size.
void check_sizes(const TriangleMesh& mesh, const MissingNormals& missing) {
  const auto sized = [](size_t size, size_t expected) { return size == 0 || size == expected; };
  if (!sized(missing.vertex_missing.size(), mesh.vertex_count()) || !sized(missing.file_vertex.size(), mesh.vertex_count()) ||
      !sized(missing.smooth.size(), mesh.triangle_count()))
    throw std::invalid_argument("blender_corner_normals: MissingNormals' arrays do not match the mesh");
  if (missing.auto_smooth_deg && !(*missing.auto_smooth_deg > 0.0 && *missing.auto_smooth_deg <= kMaxAutoSmoothDeg))
    throw std::invalid_argument("blender_corner_normals: the Auto Smooth angle must be in (0, 180] degrees");
}

class CornerNormals {
 public:
  CornerNormals(const TriangleMesh& mesh, const MissingNormals& missing)
      : mesh_(mesh), missing_(missing), frames_(face_frames(mesh)) {
    uint32_t largest = 0;
    for (size_t v = 0; v < mesh.vertex_count(); ++v) largest = std::max(largest, file_vertex(static_cast<uint32_t>(v)));
    file_vertex_count_ = mesh.vertex_count() == 0 ? 0 : static_cast<size_t>(largest) + 1;
  }

  std::vector<glm::vec3> compute() const {
    return missing_.auto_smooth_deg ? with_auto_smooth(std::cos(*missing_.auto_smooth_deg * kPi / 180.0))
                                    : with_vertex_normals();
  }

 private:
  uint32_t file_vertex(uint32_t v) const { return missing_.file_vertex.empty() ? v : missing_.file_vertex[v]; }
  uint32_t corner_file_vertex(size_t t, int k) const { return file_vertex(mesh_.triangles[t][k]); }
  bool smooth(size_t t) const {
    return missing_.auto_smooth_deg || (!missing_.smooth.empty() && missing_.smooth[t]);
  }

  static glm::vec3 unit(const glm::dvec3& sum, const glm::dvec3& fallback) {
    const double length = glm::length(sum);
    return glm::vec3(length > 0.0 && std::isfinite(length) ? sum / length : fallback);
  }

  // Blender's vertex normals: every face around the vertex, weighted by its corner angle.
  std::vector<glm::vec3> with_vertex_normals() const {
    std::vector<glm::dvec3> sums(file_vertex_count_, glm::dvec3(0.0));
    for (size_t t = 0; t < frames_.size(); ++t) {
      if (frames_[t].degenerate) continue;
      for (int k = 0; k < 3; ++k) sums[corner_file_vertex(t, k)] += frames_[t].angles[k] * frames_[t].normal;
    }
    std::vector<glm::vec3> normals(3 * frames_.size());
    for (size_t t = 0; t < frames_.size(); ++t) {
      for (int k = 0; k < 3; ++k) {
        normals[3 * t + k] = smooth(t) ? unit(sums[corner_file_vertex(t, k)], frames_[t].normal) : glm::vec3(frames_[t].normal);
      }
    }
    return normals;
  }

  // An edge between two file vertices, and the faces along it.
  struct EdgeFaces {
    uint32_t count = 0;
    uint32_t first = 0, second = 0;
    bool same_direction = false;  // the two faces run along it the same way
  };

  static uint64_t edge_key(uint32_t a, uint32_t b) {
    return (static_cast<uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
  }

  std::unordered_map<uint64_t, EdgeFaces> edge_faces() const {
    std::unordered_map<uint64_t, EdgeFaces> edges;
    edges.reserve(3 * frames_.size());
    for (size_t t = 0; t < frames_.size(); ++t) {
      for (int k = 0; k < 3; ++k) {
        const uint32_t a = corner_file_vertex(t, k), b = corner_file_vertex(t, (k + 1) % 3);
        EdgeFaces& edge = edges[edge_key(a, b)];
        if (edge.count == 0) {
          edge.first = static_cast<uint32_t>(t);
        } else if (edge.count == 1) {
          edge.second = static_cast<uint32_t>(t);
          // The first face's direction along the edge, from its smaller vertex.
          edge.same_direction = first_runs_up(edge.first, a, b) == (a < b);
        }
        ++edge.count;
      }
    }
    return edges;
  }

  // Whether triangle t runs along its edge {a, b} from the smaller vertex to the larger.
  bool first_runs_up(uint32_t t, uint32_t a, uint32_t b) const {
    for (int k = 0; k < 3; ++k) {
      const uint32_t from = corner_file_vertex(t, k), to = corner_file_vertex(t, (k + 1) % 3);
      if (edge_key(from, to) == edge_key(a, b)) return from < to;
    }
    return true;
  }

  bool smooth_edge(const EdgeFaces& edge, double cos_split) const {
    if (edge.count != 2 || edge.same_direction) return false;
    const FaceFrame& f1 = frames_[edge.first];
    const FaceFrame& f2 = frames_[edge.second];
    if (f1.degenerate || f2.degenerate || !smooth(edge.first) || !smooth(edge.second)) return false;
    return glm::dot(f1.normal, f2.normal) >= cos_split;
  }

  // Blender's loop normals with Auto Smooth: the faces around a vertex fall into fans separated by
  // sharp edges, and each corner takes the angle-weighted mean over its fan.
  std::vector<glm::vec3> with_auto_smooth(double cos_split) const {
    const std::unordered_map<uint64_t, EdgeFaces> edges = edge_faces();
    // The corners around each file vertex (compressed rows).
    std::vector<size_t> row_start(file_vertex_count_ + 1, 0);
    for (size_t t = 0; t < frames_.size(); ++t)
      for (int k = 0; k < 3; ++k) ++row_start[corner_file_vertex(t, k) + 1];
    std::partial_sum(row_start.begin(), row_start.end(), row_start.begin());
    std::vector<size_t> corners(3 * frames_.size());
    std::vector<size_t> filled(row_start.begin(), row_start.end() - 1);
    for (size_t t = 0; t < frames_.size(); ++t)
      for (int k = 0; k < 3; ++k) corners[filled[corner_file_vertex(t, k)]++] = 3 * t + static_cast<size_t>(k);

    std::vector<glm::vec3> normals(3 * frames_.size());
    std::vector<size_t> fan;  // union-find over one vertex's corners, by position in its row
    std::unordered_map<uint32_t, size_t> slot_of_triangle;
    std::vector<glm::dvec3> sums;
    for (size_t vertex = 0; vertex < file_vertex_count_; ++vertex) {
      const size_t begin = row_start[vertex], count = row_start[vertex + 1] - begin;
      if (count == 0) continue;
      fan.resize(count);
      std::iota(fan.begin(), fan.end(), size_t{0});
      const auto root = [&](size_t i) {
        while (fan[i] != i) i = fan[i] = fan[fan[i]];
        return i;
      };
      slot_of_triangle.clear();
      for (size_t i = 0; i < count; ++i) slot_of_triangle.emplace(static_cast<uint32_t>(corners[begin + i] / 3), i);
      for (size_t i = 0; i < count; ++i) {
        const size_t t = corners[begin + i] / 3;
        const int k = static_cast<int>(corners[begin + i] % 3);
        // The triangle's two edges at this vertex.
        for (const int other : {(k + 1) % 3, (k + 2) % 3}) {
          const EdgeFaces& edge = edges.at(edge_key(static_cast<uint32_t>(vertex), corner_file_vertex(t, other)));
          if (!smooth_edge(edge, cos_split)) continue;
          const uint32_t neighbour = edge.first == t ? edge.second : edge.first;
          const auto found = slot_of_triangle.find(neighbour);
          if (found != slot_of_triangle.end()) fan[root(i)] = root(found->second);
        }
      }
      sums.assign(count, glm::dvec3(0.0));
      for (size_t i = 0; i < count; ++i) {
        const size_t corner = corners[begin + i];
        const FaceFrame& frame = frames_[corner / 3];
        if (!frame.degenerate) sums[root(i)] += frame.angles[corner % 3] * frame.normal;
      }
      for (size_t i = 0; i < count; ++i) {
        const size_t corner = corners[begin + i];
        const FaceFrame& frame = frames_[corner / 3];
        normals[corner] = smooth(corner / 3) ? unit(sums[root(i)], frame.normal) : glm::vec3(frame.normal);
      }
    }
    return normals;
  }

  const TriangleMesh& mesh_;
  const MissingNormals& missing_;
  std::vector<FaceFrame> frames_;
  size_t file_vertex_count_ = 0;
};

bool any_of(const std::vector<bool>& flags, bool value) {
  return std::find(flags.begin(), flags.end(), value) != flags.end();
}

// Appends a copy of vertex v (every per-vertex array) and returns its index.
uint32_t copy_vertex(TriangleMesh& mesh, uint32_t v) {
  const auto index = static_cast<uint32_t>(mesh.positions.size());
  mesh.positions.push_back(mesh.positions[v]);
  mesh.normals.push_back(mesh.normals[v]);
  if (!mesh.uvs.empty()) mesh.uvs.push_back(mesh.uvs[v]);
  if (!mesh.tangents.empty()) mesh.tangents.push_back(mesh.tangents[v]);
  if (!mesh.colors.empty()) mesh.colors.push_back(mesh.colors[v]);
  return index;
}

}  // namespace

std::vector<glm::vec3> blender_corner_normals(const TriangleMesh& mesh, const MissingNormals& missing) {
  validate_mesh(mesh, "blender_corner_normals");
  check_sizes(mesh, missing);
  return CornerNormals(mesh, missing).compute();
}

void complete_missing_normals(TriangleMesh& mesh, const MissingNormals& missing) {
  check_sizes(mesh, missing);
  const bool all_missing = missing.vertex_missing.empty() || !any_of(missing.vertex_missing, false);
  const bool any_smooth = missing.auto_smooth_deg || any_of(missing.smooth, true);
  if (all_missing && !any_smooth) {
    mesh.normals.clear();
    mesh.tangents.clear();  // a tangent frame needs a normal
    return;
  }
  if (!missing.vertex_missing.empty() && !any_of(missing.vertex_missing, true)) return;
  validate_mesh(mesh, "complete_missing_normals");
  const std::vector<glm::vec3> corner_normals = CornerNormals(mesh, missing).compute();
  const size_t original_count = mesh.vertex_count();
  mesh.normals.resize(original_count, glm::vec3(0.0f));
  // The copies made of each vertex so far, by normal; the vertex itself takes its first corner's.
  std::vector<bool> claimed(original_count, false);
  std::unordered_map<uint32_t, std::vector<uint32_t>> copies;
  for (size_t t = 0; t < mesh.triangle_count(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = mesh.triangles[t][k];
      if (!missing.vertex_missing.empty() && !missing.vertex_missing[v]) continue;
      const glm::vec3& normal = corner_normals[3 * t + static_cast<size_t>(k)];
      if (!claimed[v]) {
        claimed[v] = true;
        mesh.normals[v] = normal;
        continue;
      }
      if (mesh.normals[v] == normal) continue;
      std::vector<uint32_t>& made = copies[v];
      const auto same = std::find_if(made.begin(), made.end(), [&](uint32_t c) { return mesh.normals[c] == normal; });
      if (same != made.end()) {
        mesh.triangles[t][k] = *same;
        continue;
      }
      const uint32_t copy = copy_vertex(mesh, v);
      mesh.normals[copy] = normal;
      made.push_back(copy);
      mesh.triangles[t][k] = copy;
    }
  }
}

std::vector<uint32_t> vertices_by_position(const TriangleMesh& mesh) {
  struct PositionHash {
    size_t operator()(const glm::vec3& p) const {
      const std::hash<float> hash;
      return hash(p.x) ^ (hash(p.y) * 31) ^ (hash(p.z) * 1009);
    }
  };
  std::unordered_map<glm::vec3, uint32_t, PositionHash> first_at;
  std::vector<uint32_t> ids(mesh.vertex_count());
  for (size_t v = 0; v < ids.size(); ++v) ids[v] = first_at.emplace(mesh.positions[v], static_cast<uint32_t>(v)).first->second;
  return ids;
}

TriangleMesh flat_shaded(const TriangleMesh& mesh) {
  validate_mesh(mesh, "flat_shaded");
  const std::vector<FaceFrame> frames = face_frames(mesh);
  TriangleMesh flat;
  flat.triangle_parts = mesh.triangle_parts;
  flat.part_names = mesh.part_names;
  for (size_t t = 0; t < mesh.triangle_count(); ++t) {
    const auto first = static_cast<uint32_t>(flat.positions.size());
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = mesh.triangles[t][k];
      flat.positions.push_back(mesh.positions[v]);
      flat.normals.emplace_back(frames[t].normal);
      if (!mesh.uvs.empty()) flat.uvs.push_back(mesh.uvs[v]);
      if (!mesh.colors.empty()) flat.colors.push_back(mesh.colors[v]);
    }
    flat.triangles.emplace_back(first, first + 1, first + 2);
  }
  return flat;
}

}  // namespace matgeom
