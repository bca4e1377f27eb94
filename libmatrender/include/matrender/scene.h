#pragma once
// A renderable scene: triangle meshes with one material per part, lamps and a background.
// The BVH is built by commit(); materials, which material each part uses, lamps and the
// background can all change afterwards without rebuilding it (one object, many material
// variants, one BVH), and the same scene renders from any number of cameras. Meshes can be moved,
// hidden and shown after it, and the next commit() rebuilds the BVH. Nothing may change while a
// render of the scene runs.
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "matgeom/mesh.h"
#include "matrender/background.h"
#include "matrender/lamp.h"
#include "matrender/material.h"

namespace matrender {

class SceneData;  // internal: geometry, materials and the Embree scene

struct MeshOptions {
  // Cycles' per-object Shading > Shadow Terminator > Geometry Offset (default 0.1): shadow rays
  // of smooth-shaded triangles near the light's terminator start from the smooth surface the
  // vertex normals describe instead of the flat triangle, so coarse meshes do not show their
  // facets in the shadow line. 0 turns it off; meshes without normals never use it.
  float shadow_terminator_geometry_offset = 0.1f;
};

class Scene {
 public:
  Scene();
  ~Scene();
  Scene(Scene&&) noexcept;
  Scene& operator=(Scene&&) noexcept;

  uint32_t add_material(Material material);
  const Material& material(uint32_t id) const;
  size_t material_count() const;

  // Adds a copy of `mesh`. part_materials[k] is the material id of part k and must cover every
  // part id the mesh uses. Throws std::invalid_argument for an invalid mesh or material id or a
  // vertex beyond kMaxSceneCoordinate (matrender/scene_limits.h), and std::logic_error after
  // commit().
  uint32_t add_mesh(const matgeom::TriangleMesh& mesh, const std::vector<uint32_t>& part_materials,
                    const MeshOptions& options = {});

  // Which material each part of mesh `mesh` (an id add_mesh returned) uses, before or after
  // commit(). Throws std::invalid_argument for an unknown mesh or material id, or when a part
  // the mesh uses gets no material.
  void set_part_materials(uint32_t mesh, const std::vector<uint32_t>& part_materials);
  size_t mesh_count() const;
  const std::vector<uint32_t>& part_materials(uint32_t mesh) const;

  // Places mesh `mesh` at `transform` applied to the mesh as it was added (its normals and
  // tangents follow), however it was moved before, so a mesh's place never depends on the
  // order of the moves. And shows or hides it from every ray (a hidden mesh neither occludes nor
  // emits). For a tool that rearranges a scene between renders without building it again; the
  // next commit() (render() calls it) rebuilds the BVH. Throws std::invalid_argument for an
  // unknown mesh, a transform that is not finite or flattens the mesh, or a vertex it would put
  // beyond kMaxSceneCoordinate.
  void set_mesh_transform(uint32_t mesh, const glm::dmat4& transform);
  void set_mesh_enabled(uint32_t mesh, bool enabled);
  bool mesh_enabled(uint32_t mesh) const;

  // Throws std::invalid_argument, naming the light and the reason, for one single precision
  // cannot render as given (non-finite or negative values, a position beyond the scene limit, an
  // area or emission that does not fit a float).
  void add_lamp(const Lamp& light);
  void clear_lamps();
  const std::vector<Lamp>& lamps() const;

  // What camera rays that miss see and what lights the scene from every direction: a uniform
  // radiance or an environment map (matrender/background.h). An environment map's sampling
  // density is built here, once for every render. Throws std::invalid_argument for a negative or
  // non-finite radiance, strength or rotation, a missing image, or a map too bright for floats.
  void set_background(const Background& background);
  const Background& background() const;

  // Builds the BVH (Embree, build quality high). Idempotent; render() calls it when needed.
  void commit();
  bool committed() const;

  size_t triangle_count() const;
  double bvh_build_seconds() const;

  const SceneData& data() const;  // for the integrator and tests

 private:
  std::unique_ptr<SceneData> data_;
};

}  // namespace matrender
