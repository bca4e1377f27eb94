#pragma once
// What a committed scene holds: geometry in the layout shading needs, materials, lamps and the
// Embree BVH over the geometry.
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "accel/embree_scene.h"
#include "bsdf/principled.h"
#include "lights/world_light.h"
#include "matrender/background.h"
#include "matrender/lamp.h"
#include "matrender/material.h"

namespace matrender {

struct MeshData {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;   // empty = flat shading
  std::vector<glm::vec2> uvs;       // empty = no UVs (texture lookups at (0, 0))
  std::vector<glm::vec4> tangents;  // empty = no normal mapping possible
  std::vector<glm::vec3> colors;    // linear RGB per vertex; empty = none (Material::vertex_colors)
  std::vector<glm::uvec3> triangles;
  std::vector<uint32_t> triangle_parts;  // empty = part 0
  std::vector<uint32_t> part_materials;  // material id of each part
  float shadow_terminator_geometry_offset = 0.1f;  // MeshOptions
  // Whether rays see the mesh (Scene::set_mesh_enabled): a hidden mesh neither occludes nor emits.
  bool enabled = true;
  // A mesh Scene::set_mesh_transform moved: its vertices, normals and tangents as added, and the
  // transform the arrays above hold them under, so that where it is never depends on the moves
  // before.
  struct AsAdded {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec4> tangents;
    glm::dmat4 transform{1.0};
  };
  std::optional<AsAdded> as_added;
  bool changed = false;  // moved or shown or hidden since the BVH was built
};

// What shading reads of a material at every hit, made once when the material is added (its
// parameter table holds strided values beside their textures): the inputs before any texture,
// and whether a texture varies any of them.
struct MaterialShading {
  explicit MaterialShading(const Material& material) : untextured(material), textured(material.textured()) {}
  PrincipledInputs untextured;
  bool textured;
};

class SceneData {
 public:
  std::vector<Material> materials;
  std::vector<MaterialShading> material_shading;  // of each material, in the same order
  std::vector<MeshData> meshes;
  std::vector<Lamp> lamps;
  Background background = glm::vec3(0.0f);
  WorldLight world = UniformBackground(glm::vec3(0.0f));  // prepared from background
  EmbreeScene accel;
  bool committed = false;
  bool built = false;  // the BVH was built once: commit() then updates the meshes that changed
  double build_seconds = 0.0;
  size_t triangle_count = 0;
  // The box around every vertex of every mesh, set by commit (empty, lower above upper, without
  // meshes): nothing a ray can hit lies outside it.
  glm::vec3 vertex_lower{std::numeric_limits<float>::infinity()};
  glm::vec3 vertex_upper{-std::numeric_limits<float>::infinity()};
};

}  // namespace matrender
