#include "matrender/scene.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "lights/light_checks.h"
#include "matgeom/shading_normals.h"
#include "matgeom/tangents.h"
#include "matrender/scene_limits.h"
#include "scene/scene_data.h"

namespace matrender {

Scene::Scene() : data_(std::make_unique<SceneData>()) {}
Scene::~Scene() = default;
Scene::Scene(Scene&&) noexcept = default;
Scene& Scene::operator=(Scene&&) noexcept = default;

uint32_t Scene::add_material(Material material) {
  data_->material_shading.emplace_back(material);
  data_->materials.push_back(std::move(material));
  return static_cast<uint32_t>(data_->materials.size() - 1);
}

const Material& Scene::material(uint32_t id) const { return data_->materials.at(id); }
size_t Scene::material_count() const { return data_->materials.size(); }

namespace {

// Throws std::invalid_argument unless every one of `parts` parts gets an existing material.
void check_part_materials(const std::string& what, uint32_t parts, const std::vector<uint32_t>& part_materials,
                          size_t material_count) {
  if (part_materials.size() < parts)
    throw std::invalid_argument(what + ": uses " + std::to_string(parts) + " parts but " +
                                std::to_string(part_materials.size()) + " materials were given");
  for (uint32_t id : part_materials)
    if (id >= material_count)
      throw std::invalid_argument(what + ": material id " + std::to_string(id) + " does not exist");
}

// A moved mesh's arrays: its geometry as added under its transform.
void place_moved_mesh(MeshData& m) {
  matgeom::TriangleMesh placed;
  placed.positions = m.as_added->positions;
  placed.normals = m.as_added->normals;
  placed.tangents = m.as_added->tangents;
  matgeom::transform_mesh(placed, m.as_added->transform);
  m.positions = std::move(placed.positions);
  m.normals = std::move(placed.normals);
  m.tangents = std::move(placed.tangents);
}

// Normal maps need tangents; a mesh with UVs but none gets MikkTSpace ones the first time one of
// its materials has a normal map. A flat mesh (no normals) first gets one vertex per corner with
// its face normal, so that the frame is built on the normal it is shaded with. A moved mesh gets
// them on its geometry as added, then is placed again.
void add_tangents_if_needed(MeshData& m, const std::vector<Material>& materials) {
  bool needs_tangents = false;
  for (uint32_t id : m.part_materials) needs_tangents |= materials[id].normal_map != nullptr;
  if (!needs_tangents || !m.tangents.empty() || m.uvs.empty()) return;
  if (m.as_added) {
    std::swap(m.positions, m.as_added->positions);
    std::swap(m.normals, m.as_added->normals);
  }
  matgeom::TriangleMesh with_tangents;
  with_tangents.positions = m.positions;
  with_tangents.normals = m.normals;
  with_tangents.uvs = m.uvs;
  with_tangents.triangles = m.triangles;
  if (with_tangents.normals.empty()) with_tangents = matgeom::flat_shaded(with_tangents);
  matgeom::compute_tangents(with_tangents);
  m.positions = std::move(with_tangents.positions);
  m.normals = std::move(with_tangents.normals);
  m.uvs = std::move(with_tangents.uvs);
  m.triangles = std::move(with_tangents.triangles);
  m.tangents = std::move(with_tangents.tangents);
  if (m.as_added) {
    m.as_added->positions = m.positions;
    m.as_added->normals = m.normals;
    m.as_added->tangents = m.tangents;
    place_moved_mesh(m);
    m.changed = true;  // its vertices were split: the BVH's copy is replaced too
  }
}

// Some triangle spans an area (in the float positions rays will meet).
bool has_area(const matgeom::TriangleMesh& mesh) {
  for (const glm::uvec3& t : mesh.triangles) {
    const glm::vec3 p0 = mesh.positions[t.x];
    if (glm::cross(mesh.positions[t.y] - p0, mesh.positions[t.z] - p0) != glm::vec3(0.0f)) return true;
  }
  return false;
}

uint32_t parts_used(const MeshData& m) {
  uint32_t parts = 1;
  for (uint32_t part : m.triangle_parts) parts = std::max(parts, part + 1);
  return parts;
}

}  // namespace

uint32_t Scene::add_mesh(const matgeom::TriangleMesh& mesh, const std::vector<uint32_t>& part_materials,
                         const MeshOptions& options) {
  if (data_->committed) throw std::logic_error("Scene::add_mesh: the scene is already committed");
  const std::string what = "mesh " + std::to_string(data_->meshes.size());
  matgeom::validate_mesh(mesh, what);
  if (mesh.triangles.empty()) throw std::invalid_argument(what + ": has no triangles");
  for (size_t v = 0; v < mesh.positions.size(); ++v)
    if (!within_scene_limit(mesh.positions[v])) check_scene_point(mesh.positions[v], what + ": vertex " + std::to_string(v));
  if (!has_area(mesh))
    throw std::invalid_argument(what + ": every one of its " + std::to_string(mesh.triangles.size()) +
                                " triangles has zero area (its vertices are collinear or coincide), so nothing would render");
  check_part_materials(what, mesh.part_count(), part_materials, data_->materials.size());
  if (!(options.shadow_terminator_geometry_offset >= 0.0f && options.shadow_terminator_geometry_offset <= 1.0f))
    throw std::invalid_argument(what + ": shadow terminator geometry offset must be in [0, 1]");

  MeshData m;
  m.positions = mesh.positions;
  m.normals = mesh.normals;
  m.uvs = mesh.uvs;
  m.tangents = mesh.tangents;
  m.colors = mesh.colors;
  m.triangles = mesh.triangles;
  m.triangle_parts = mesh.triangle_parts;
  m.part_materials = part_materials;
  m.shadow_terminator_geometry_offset = options.shadow_terminator_geometry_offset;
  add_tangents_if_needed(m, data_->materials);
  data_->triangle_count += m.triangles.size();
  data_->meshes.push_back(std::move(m));
  return static_cast<uint32_t>(data_->meshes.size() - 1);
}

void Scene::set_part_materials(uint32_t mesh, const std::vector<uint32_t>& part_materials) {
  if (mesh >= data_->meshes.size())
    throw std::invalid_argument("Scene::set_part_materials: mesh " + std::to_string(mesh) + " does not exist");
  MeshData& m = data_->meshes[mesh];
  check_part_materials("mesh " + std::to_string(mesh), parts_used(m), part_materials, data_->materials.size());
  m.part_materials = part_materials;
  add_tangents_if_needed(m, data_->materials);
}

void Scene::set_mesh_transform(uint32_t mesh, const glm::dmat4& transform) {
  if (mesh >= data_->meshes.size())
    throw std::invalid_argument("Scene::set_mesh_transform: mesh " + std::to_string(mesh) + " does not exist");
  const std::string what = "mesh " + std::to_string(mesh);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(transform[c][r])) throw std::invalid_argument(what + ": the transform is not finite");
  if (!(std::abs(glm::determinant(glm::dmat3(transform))) > 0.0))
    throw std::invalid_argument(what + ": the transform flattens the mesh (its determinant is 0)");
  MeshData& m = data_->meshes[mesh];
  if (!m.as_added) m.as_added = MeshData::AsAdded{m.positions, m.normals, m.tangents, glm::dmat4(1.0)};
  for (size_t v = 0; v < m.as_added->positions.size(); ++v) {
    const glm::dvec3 world(transform * glm::dvec4(glm::dvec3(m.as_added->positions[v]), 1.0));
    if (!within_scene_limit(world)) check_scene_point(world, what + ": moved vertex " + std::to_string(v));
  }
  m.as_added->transform = transform;
  place_moved_mesh(m);
  m.changed = true;
  data_->committed = false;
}

void Scene::set_mesh_enabled(uint32_t mesh, bool enabled) {
  if (mesh >= data_->meshes.size())
    throw std::invalid_argument("Scene::set_mesh_enabled: mesh " + std::to_string(mesh) + " does not exist");
  MeshData& m = data_->meshes[mesh];
  if (m.enabled == enabled) return;
  m.enabled = enabled;
  data_->committed = false;
}

bool Scene::mesh_enabled(uint32_t mesh) const { return data_->meshes.at(mesh).enabled; }

size_t Scene::mesh_count() const { return data_->meshes.size(); }

const std::vector<uint32_t>& Scene::part_materials(uint32_t mesh) const { return data_->meshes.at(mesh).part_materials; }

void Scene::add_lamp(const Lamp& light) {
  if (const std::optional<std::string> problem = lamp_problem(light))
    throw std::invalid_argument("light " + std::to_string(data_->lamps.size()) + ": " + *problem);
  data_->lamps.push_back(light);
}
void Scene::clear_lamps() { data_->lamps.clear(); }
const std::vector<Lamp>& Scene::lamps() const { return data_->lamps; }

void Scene::set_background(const Background& background) {
  if (const auto* uniform = std::get_if<glm::vec3>(&background))
    for (int c = 0; c < 3; ++c)
      if (!(std::isfinite((*uniform)[c]) && (*uniform)[c] >= 0.0f))
        throw std::invalid_argument("background: a uniform radiance must be finite and >= 0");
  data_->world = prepare_world(background);
  data_->background = background;
}
const Background& Scene::background() const { return data_->background; }

void Scene::commit() {
  if (data_->committed) return;
  const auto start = std::chrono::steady_clock::now();
  for (uint32_t id = 0; id < data_->meshes.size(); ++id) {
    MeshData& m = data_->meshes[id];
    if (!data_->built) data_->accel.add_triangle_mesh(m.positions, m.triangles);
    else if (m.changed) data_->accel.replace_triangle_mesh(id, m.positions, m.triangles);
    data_->accel.set_enabled(id, m.enabled);
    m.changed = false;
  }
  data_->accel.commit();
  data_->built = true;
  data_->build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  data_->vertex_lower = glm::vec3(std::numeric_limits<float>::infinity());
  data_->vertex_upper = glm::vec3(-std::numeric_limits<float>::infinity());
  for (const MeshData& m : data_->meshes) {
    if (!m.enabled) continue;  // no ray meets it
    for (const glm::vec3& p : m.positions) {
      data_->vertex_lower = glm::min(data_->vertex_lower, p);
      data_->vertex_upper = glm::max(data_->vertex_upper, p);
    }
  }
  data_->committed = true;
}

bool Scene::committed() const { return data_->committed; }
size_t Scene::triangle_count() const { return data_->triangle_count; }
double Scene::bvh_build_seconds() const { return data_->build_seconds; }
const SceneData& Scene::data() const { return *data_; }

}  // namespace matrender
