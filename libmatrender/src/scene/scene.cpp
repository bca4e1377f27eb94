#include "matrender/scene.h"

#include <chrono>
#include <stdexcept>
#include <string>

#include "matgeom/tangents.h"
#include "scene/scene_data.h"

namespace matrender {

Scene::Scene() : data_(std::make_unique<SceneData>()) {}
Scene::~Scene() = default;
Scene::Scene(Scene&&) noexcept = default;
Scene& Scene::operator=(Scene&&) noexcept = default;

uint32_t Scene::add_material(Material material) {
  data_->materials.push_back(std::move(material));
  return static_cast<uint32_t>(data_->materials.size() - 1);
}

const Material& Scene::material(uint32_t id) const { return data_->materials.at(id); }
size_t Scene::material_count() const { return data_->materials.size(); }

uint32_t Scene::add_mesh(const matgeom::TriangleMesh& mesh, const std::vector<uint32_t>& part_materials,
                         const MeshOptions& options) {
  if (data_->committed) throw std::logic_error("Scene::add_mesh: the scene is already committed");
  const std::string what = "mesh " + std::to_string(data_->meshes.size());
  matgeom::validate_mesh(mesh, what);
  if (mesh.triangles.empty()) throw std::invalid_argument(what + ": has no triangles");
  const uint32_t parts = mesh.part_count();
  if (part_materials.size() < parts)
    throw std::invalid_argument(what + ": uses " + std::to_string(parts) + " parts but " +
                                std::to_string(part_materials.size()) + " materials were given");
  for (uint32_t id : part_materials)
    if (id >= data_->materials.size())
      throw std::invalid_argument(what + ": material id " + std::to_string(id) + " does not exist");
  if (!(options.shadow_terminator_geometry_offset >= 0.0f && options.shadow_terminator_geometry_offset <= 1.0f))
    throw std::invalid_argument(what + ": shadow terminator geometry offset must be in [0, 1]");

  MeshData m;
  m.positions = mesh.positions;
  m.normals = mesh.normals;
  m.uvs = mesh.uvs;
  m.tangents = mesh.tangents;
  m.triangles = mesh.triangles;
  m.triangle_parts = mesh.triangle_parts;
  m.part_materials = part_materials;
  m.shadow_terminator_geometry_offset = options.shadow_terminator_geometry_offset;
  bool needs_tangents = false;
  for (uint32_t id : part_materials) needs_tangents |= data_->materials[id].normal_map != nullptr;
  if (needs_tangents && m.tangents.empty() && !m.uvs.empty()) {
    matgeom::TriangleMesh with_tangents = mesh;
    matgeom::compute_tangents(with_tangents);
    m.tangents = std::move(with_tangents.tangents);
    if (m.normals.empty()) m.normals = std::move(with_tangents.normals);
  }
  data_->triangle_count += m.triangles.size();
  data_->meshes.push_back(std::move(m));
  return static_cast<uint32_t>(data_->meshes.size() - 1);
}

void Scene::add_light(const Light& light) { data_->lights.push_back(light); }
void Scene::clear_lights() { data_->lights.clear(); }
const std::vector<Light>& Scene::lights() const { return data_->lights; }

void Scene::set_background(const glm::vec3& radiance) { data_->background = radiance; }
glm::vec3 Scene::background() const { return data_->background; }

void Scene::commit() {
  if (data_->committed) return;
  const auto start = std::chrono::steady_clock::now();
  for (const MeshData& m : data_->meshes) data_->accel.add_triangle_mesh(m.positions, m.triangles);
  data_->accel.commit();
  data_->build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  data_->committed = true;
}

bool Scene::committed() const { return data_->committed; }
size_t Scene::triangle_count() const { return data_->triangle_count; }
double Scene::bvh_build_seconds() const { return data_->build_seconds; }
const SceneData& Scene::data() const { return *data_; }

}  // namespace matrender
