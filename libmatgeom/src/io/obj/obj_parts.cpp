#include "io/obj/obj_parts.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <set>
#include <utility>

#include <glm/glm.hpp>

#include "matbase/text.h"
#include "matgeom/shading_normals.h"

namespace matgeom::obj {

// ---------------------------------------------------------------------------------------------
// Parts

PartTable parts_by_material(const ObjFile& file) {
  std::set<int> used;
  for (const tinyobj::shape_t& shape : file.shapes) {
    used.insert(shape.mesh.material_ids.begin(), shape.mesh.material_ids.end());
  }
  PartTable table;
  std::map<int, uint32_t> part_of_material;
  for (const int material : used) {
    if (material < 0) continue;
    part_of_material[material] = static_cast<uint32_t>(table.names.size());
    table.names.push_back(file.materials[static_cast<size_t>(material)].name);
    table.materials.push_back(material);
  }
  if (used.count(-1) != 0) {
    part_of_material[-1] = static_cast<uint32_t>(table.names.size());
    table.names.push_back("default");
    table.materials.push_back(-1);
  }
  for (const tinyobj::shape_t& shape : file.shapes) {
    std::vector<uint32_t>& parts = table.face_parts.emplace_back();
    for (const int material : shape.mesh.material_ids) parts.push_back(part_of_material[material]);
  }
  return table;
}

PartTable parts_by_group(const ObjFile& file) {
  PartTable table;
  std::map<std::string, uint32_t> part_of_name;
  for (const tinyobj::shape_t& shape : file.shapes) {
    std::vector<uint32_t>& parts = table.face_parts.emplace_back();
    if (shape.mesh.material_ids.empty()) continue;
    // Blender trims names; tinyobjloader keeps what follows "o " up to the end of the line.
    const std::string trimmed = matbase::trim(shape.name);
    const std::string name = trimmed.empty() ? "default" : trimmed;
    const auto [found, inserted] =
        part_of_name.emplace(name, static_cast<uint32_t>(table.names.size()));
    if (inserted) {
      table.names.push_back(name);
      table.materials.push_back(shape.mesh.material_ids.front());
    }
    parts.assign(shape.mesh.material_ids.size(), found->second);
  }
  return table;
}

// ---------------------------------------------------------------------------------------------
// Geometry

namespace {

glm::vec3 obj_to_blender(const std::vector<tinyobj::real_t>& xyz, int index) {
  const size_t i = 3 * static_cast<size_t>(index);
  return {xyz[i], -xyz[i + 2], xyz[i + 1]};
}

class MeshAssembler {
 public:
  explicit MeshAssembler(const ObjFile& file) : attrib_(file.attrib) {
    for (const tinyobj::shape_t& shape : file.shapes) {
      for (const tinyobj::index_t& corner : shape.mesh.indices) {
        with_uvs_ = with_uvs_ || corner.texcoord_index >= 0;
      }
    }
  }

  // Triangles that repeat a position have no surface and are dropped (as read_gltf drops
  // triangles that repeat a vertex).
  void add_triangle(const tinyobj::index_t* corners, uint32_t part, bool smooth) {
    const int a = corners[0].vertex_index, b = corners[1].vertex_index, c = corners[2].vertex_index;
    if (a == b || b == c || c == a) return;
    // One statement each: vertices are numbered in corner order.
    const uint32_t first = vertex(corners[0]);
    const uint32_t second = vertex(corners[1]);
    const uint32_t third = vertex(corners[2]);
    assembled_.mesh.triangles.emplace_back(first, second, third);
    assembled_.mesh.triangle_parts.push_back(part);
    assembled_.smooth.push_back(smooth);
  }

  AssembledMesh take() { return std::move(assembled_); }

 private:
  // One vertex per distinct (v, vt, vn) triple, numbered in order of first use.
  uint32_t vertex(const tinyobj::index_t& corner) {
    const std::array<int, 3> key = {corner.vertex_index, corner.texcoord_index,
                                    corner.normal_index};
    const auto [found, inserted] =
        vertex_of_corner_.emplace(key, static_cast<uint32_t>(assembled_.mesh.positions.size()));
    if (inserted) add_vertex(corner);
    return found->second;
  }

  void add_vertex(const tinyobj::index_t& corner) {
    TriangleMesh& mesh = assembled_.mesh;
    mesh.positions.push_back(obj_to_blender(attrib_.vertices, corner.vertex_index));
    assembled_.file_positions.push_back(static_cast<uint32_t>(corner.vertex_index));
    // Corners without a texture coordinate in a file that has them get (0, 0).
    if (with_uvs_) {
      const size_t t = 2 * static_cast<size_t>(std::max(corner.texcoord_index, 0));
      mesh.uvs.push_back(corner.texcoord_index < 0
                             ? glm::vec2(0.0f)
                             : glm::vec2(attrib_.texcoords[t], attrib_.texcoords[t + 1]));
    }
    glm::vec3 normal(0.0f);
    if (corner.normal_index >= 0) normal = obj_to_blender(attrib_.normals, corner.normal_index);
    // Blender normalises custom normals. Those of unit length to float precision are kept bit
    // for bit so that written files read back exactly; a zero normal counts as missing.
    const double length = glm::length(glm::dvec3(normal));
    if (std::abs(length - 1.0) > 1e-6 && length > 0.0) {
      normal = glm::vec3(glm::dvec3(normal) / length);
    }
    mesh.normals.push_back(normal);
    assembled_.normal_missing.push_back(!(length > 0.0));
  }

  const tinyobj::attrib_t& attrib_;
  bool with_uvs_ = false;
  std::map<std::array<int, 3>, uint32_t> vertex_of_corner_;
  AssembledMesh assembled_;
};

}  // namespace

AssembledMesh assemble_mesh(const ObjFile& file, const PartTable& parts) {
  MeshAssembler assembler(file);
  for (size_t s = 0; s < file.shapes.size(); ++s) {
    const tinyobj::mesh_t& mesh = file.shapes[s].mesh;
    for (size_t face = 0; face < parts.face_parts[s].size(); ++face) {
      const bool smooth = face < mesh.smoothing_group_ids.size() && mesh.smoothing_group_ids[face] != 0;
      assembler.add_triangle(&mesh.indices[3 * face], parts.face_parts[s][face], smooth);
    }
  }
  return assembler.take();
}

void complete_normals(AssembledMesh& assembled, std::optional<double> auto_smooth_deg) {
  MissingNormals missing;
  missing.vertex_missing = assembled.normal_missing;
  missing.smooth = assembled.smooth;
  missing.file_vertex = assembled.file_positions;
  missing.auto_smooth_deg = auto_smooth_deg;
  complete_missing_normals(assembled.mesh, missing);
}

}  // namespace matgeom::obj
