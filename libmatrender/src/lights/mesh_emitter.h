#pragma once
// Emissive triangles as a light (Cycles 3.4 samples them too: kernel/light/triangle.h, with the
// mesh's MIS on by default). One emitter per mesh holds the triangles whose part's material
// emits; next-event estimation picks one in proportion to its area times its material's emission
// factor (textures may only darken it: they are looked up at the sampled point), then a point
// uniformly on it, so the pdf by area is that triangle's share over its area. Emission is the
// same from both sides. Rays that hit an emitting triangle take its emission weighed by MIS with
// that pdf (path_tracer.cpp).
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "lights/light_sample.h"
#include "lights/light_type.h"
#include "sampling/piecewise_constant.h"

namespace matrender {

class SceneData;

class MeshEmitter {
 public:
  // The emitter of mesh `mesh` of `scene`, which must outlive it; none when no part emits.
  static std::optional<MeshEmitter> of_mesh(const SceneData& scene, uint32_t mesh);

  static constexpr LightType type() { return LightType::Area; }
  static constexpr bool visible_to_camera() { return true; }  // the camera sees the surface itself

  std::optional<LightSample> sample(const glm::vec3& p, const ReceivingDirections& receiving, glm::vec2 u) const;
  // Solid-angle pdf of sample() drawing the point at distance t along wi on mesh triangle
  // `triangle` (0 for a triangle that does not emit).
  float pdf(const glm::vec3& p, const glm::vec3& wi, float t, uint32_t triangle) const;
  // Light selection's weight at p (light_importance.h), over the emitting triangles' bounding
  // sphere, emitting to every side.
  float importance(const glm::vec3& p, const ReceivingDirections& receiving) const;
  uint32_t mesh() const { return mesh_; }

 private:
  MeshEmitter() = default;

  const SceneData* scene_ = nullptr;
  uint32_t mesh_ = 0;
  std::vector<uint32_t> triangles_;             // mesh triangle of each cell of the distribution
  std::shared_ptr<const std::vector<int32_t>> cell_of_triangle_;  // -1 where a triangle does not emit
  std::shared_ptr<const PiecewiseConstant1D> choice_;  // over triangles_, by area times emission
  std::vector<float> areas_;
  glm::vec3 center_{0.0f};
  float radius_ = 0.0f;
  float power_ = 0.0f;  // sum of area times emission factor (channel mean)
};

}  // namespace matrender
