#include "lights/mesh_emitter.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "lights/light_importance.h"
#include "scene/surface_shading.h"
#include "util/channel_average.h"

namespace matrender {
namespace {

// The most a point of `material` can emit, in channel mean: its emission and strength factors
// (textures in [0, 1] can only lower them), 0 for a material that cannot emit.
float emission_bound(const Material& material) {
  const float strength = material[MaterialParameter::EmissionStrength].value.x;
  const float emission = channel_average(material[MaterialParameter::Emission].value);
  return strength > 0.0f && emission > 0.0f ? strength * emission : 0.0f;
}

}  // namespace

std::optional<MeshEmitter> MeshEmitter::of_mesh(const SceneData& scene, uint32_t mesh_index) {
  const MeshData& mesh = scene.meshes[mesh_index];
  std::vector<float> part_bound(mesh.part_materials.size());
  bool any = false;
  for (size_t part = 0; part < part_bound.size(); ++part) {
    part_bound[part] = emission_bound(scene.materials[mesh.part_materials[part]]);
    any = any || part_bound[part] > 0.0f;
  }
  if (!any) return std::nullopt;

  MeshEmitter emitter;
  emitter.scene_ = &scene;
  emitter.mesh_ = mesh_index;
  auto cells = std::make_shared<std::vector<int32_t>>(mesh.triangles.size(), -1);
  std::vector<float> weights;
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    const float bound = part_bound[mesh.triangle_parts.empty() ? 0 : mesh.triangle_parts[t]];
    const glm::uvec3 tri = mesh.triangles[t];
    const glm::vec3 a = mesh.positions[tri.x], b = mesh.positions[tri.y], c = mesh.positions[tri.z];
    const float area = 0.5f * glm::length(glm::cross(b - a, c - a));
    if (!(bound > 0.0f) || !(area > 0.0f)) continue;
    (*cells)[t] = static_cast<int32_t>(emitter.triangles_.size());
    emitter.triangles_.push_back(t);
    emitter.areas_.push_back(area);
    weights.push_back(area * bound);
    emitter.power_ += area * bound;
    lo = glm::min(lo, glm::min(a, glm::min(b, c)));
    hi = glm::max(hi, glm::max(a, glm::max(b, c)));
  }
  if (emitter.triangles_.empty()) return std::nullopt;
  emitter.center_ = 0.5f * (lo + hi);
  emitter.radius_ = 0.5f * glm::length(hi - lo);
  emitter.cell_of_triangle_ = std::move(cells);
  emitter.choice_ = std::make_shared<PiecewiseConstant1D>(weights);
  return emitter;
}

std::optional<LightSample> MeshEmitter::sample(const glm::vec3& p, const ReceivingDirections& /*receiving*/,
                                                       glm::vec2 u) const {
  float choice_pdf;
  size_t cell;
  const float x = choice_->sample(u.x, &choice_pdf, &cell);
  // The rest of u.x within the chosen cell, for the point on its triangle.
  const float within = std::clamp(x * static_cast<float>(triangles_.size()) - static_cast<float>(cell), 0.0f, 1.0f);
  // Uniform on the triangle: b0 = 1 - sqrt(u0), b1 = u1 sqrt(u0) (Osada et al. 2002, eq. 1).
  const float root = std::sqrt(within);
  RayHit hit;
  hit.mesh = mesh_;
  hit.triangle = triangles_[cell];
  hit.u = u.y * root;           // barycentric of vertex 1
  hit.v = root * (1.0f - u.y);  // of vertex 2; vertex 0 gets 1 - root
  const MeshData& mesh = scene_->meshes[mesh_];
  const glm::uvec3 tri = mesh.triangles[hit.triangle];
  const glm::vec3 q = (1.0f - hit.u - hit.v) * mesh.positions[tri.x] + hit.u * mesh.positions[tri.y] +
                      hit.v * mesh.positions[tri.z];
  const glm::vec3 to_light = q - p;
  LightSample s;
  s.distance = glm::length(to_light);
  if (!(s.distance > 0.0f)) return std::nullopt;
  s.wi = to_light / s.distance;
  s.pdf = pdf(p, s.wi, s.distance, hit.triangle);
  if (!(s.pdf > 0.0f) || std::isinf(s.pdf)) return std::nullopt;
  s.radiance = shade_surface(*scene_, hit, -s.wi).emitted();
  if (!(s.radiance.x + s.radiance.y + s.radiance.z > 0.0f)) return std::nullopt;
  return s;
}

float MeshEmitter::pdf(const glm::vec3& /*p*/, const glm::vec3& wi, float t, uint32_t triangle) const {
  const int32_t cell = (*cell_of_triangle_)[triangle];
  if (cell < 0) return 0.0f;
  const MeshData& mesh = scene_->meshes[mesh_];
  const glm::uvec3 tri = mesh.triangles[triangle];
  const glm::vec3 normal = glm::cross(mesh.positions[tri.y] - mesh.positions[tri.x],
                                      mesh.positions[tri.z] - mesh.positions[tri.x]);
  const float cos_light = std::abs(glm::dot(glm::normalize(normal), wi));
  if (!(cos_light > 0.0f)) return 0.0f;
  // The triangle's share of the choice over its area, times the area-to-solid-angle t^2 / cos.
  const float area_pdf = choice_->pdf_of_cell(static_cast<size_t>(cell)) / static_cast<float>(triangles_.size()) /
                         areas_[static_cast<size_t>(cell)];
  return area_pdf * t * t / cos_light;
}

float MeshEmitter::importance(const glm::vec3& p, const ReceivingDirections& receiving) const {
  const glm::vec3 to_center = center_ - p;
  const float distance2 = glm::dot(to_center, to_center);
  const float distance = std::sqrt(distance2);
  const SubtendedCone cone(radius_, distance);
  const float receiving_factor =
      distance > 0.0f ? receiving_bound(receiving, to_center / distance, cone.cos_s, cone.sin_s) : 1.0f;
  return power_ * receiving_factor / std::max(distance2, radius_ * radius_);
}

}  // namespace matrender
