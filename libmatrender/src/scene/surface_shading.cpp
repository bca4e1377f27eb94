#include "scene/surface_shading.h"

#include <cmath>

#include "bsdf/shading_frame.h"
#include "util/finite.h"

namespace matrender {
namespace {

// Unit vector or `fallback` when v has no usable length.
glm::vec3 normalize_or(const glm::vec3& v, const glm::vec3& fallback) {
  const float len2 = glm::dot(v, v);
  if (!(len2 > 1e-30f) || !std::isfinite(len2)) return fallback;
  return v * (1.0f / std::sqrt(len2));
}

// The normal map's texel at uv as a tangent-space direction, n_ts = 2 rgb - 1 (Cycles' Normal
// Map node), renormalised; (0, 0, 1) for a texel that gives no direction.
glm::vec3 tangent_space_normal(const Material& material, glm::vec2 uv) {
  const glm::vec3 rgb(material.normal_map->sample(material.normal_map_uv_transform.apply(uv)));
  return normalize_or(2.0f * rgb - glm::vec3(1.0f), glm::vec3(0.0f, 0.0f, 1.0f));
}

// Cycles' Normal Map node in tangent space: n = normalize(x T + y sign (N x T) + z N), then
// strength mixes between N and n.
glm::vec3 apply_normal_map(const Material& material, const glm::vec3& n_ts, const glm::vec3& normal,
                           const glm::vec4& tangent) {
  const glm::vec3 t = normalize_or(glm::vec3(tangent) - glm::dot(glm::vec3(tangent), normal) * normal,
                                   glm::vec3(0.0f));
  if (t == glm::vec3(0.0f)) return normal;
  const glm::vec3 b = (tangent.w < 0.0f ? -1.0f : 1.0f) * glm::cross(normal, t);
  const glm::vec3 mapped = normalize_or(n_ts.x * t + n_ts.y * b + n_ts.z * normal, normal);
  return normalize_or(normal + (mapped - normal) * material.normal_strength, normal);
}

// The textured parameters at uv, each at its own placement (uv_transform), in table order;
// parameters sharing one image and placement (a packed metallic-roughness texture) take one
// lookup. The image the alpha comes from gives its colour unpremultiplied (texture.h).
void look_up_textures(const Material& material, glm::vec2 uv, float footprint, PrincipledInputs& inputs) {
  const ParameterValue& alpha = material[MaterialParameter::Alpha];
  const Texture* alpha_source = alpha.channel == 3 ? alpha.texture.get() : nullptr;
  const ParameterValue* looked_up = nullptr;
  glm::vec4 texel(0.0f);
  for (const matmaterial::MaterialParameterInfo& info : matmaterial::kMaterialParameters) {
    const ParameterValue& p = material[info.id];
    if (!p.texture) continue;
    if (!looked_up || p.texture != looked_up->texture || !(p.uv_transform == looked_up->uv_transform)) {
      texel = p.texture->sample(p.uv_transform.apply(uv), p.texture.get() == alpha_source,
                                footprint * p.uv_transform.stretch);
      looked_up = &p;
    }
    inputs.set(info.id, info.kind == matmaterial::ParameterKind::Color ? p.value * glm::vec3(texel)
                                                                 : glm::vec3(p.value.x * texel[p.channel]));
  }
}

// The UV width a ray cone of `cone_width` covers where it meets the triangle: the cone's width
// over the cosine of incidence (stretched along the surface), times the triangle's UV-to-world
// length ratio sqrt(UV area / world area) (Akenine-Moller et al. 2021, "Improved Shader and
// Texture Level of Detail Using Ray Cones", eq. 8; the cosine bounded at 0.01, 100x stretch).
float uv_footprint(const MeshData& mesh, const glm::uvec3& tri, const glm::vec3& ng, const glm::vec3& wo,
                   float cone_width) {
  const glm::vec3 p0 = mesh.positions[tri.x], p1 = mesh.positions[tri.y], p2 = mesh.positions[tri.z];
  const glm::vec2 t0 = mesh.uvs[tri.x], t1 = mesh.uvs[tri.y], t2 = mesh.uvs[tri.z];
  const float world_area = glm::length(glm::cross(p1 - p0, p2 - p0));
  const glm::vec2 e1 = t1 - t0, e2 = t2 - t0;
  const float uv_area = std::abs(e1.x * e2.y - e1.y * e2.x);
  if (!(world_area > 0.0f) || !(uv_area > 0.0f)) return 0.0f;
  const float footprint = cone_width / std::max(std::abs(glm::dot(ng, wo)), 0.01f) * std::sqrt(uv_area / world_area);
  return std::isfinite(footprint) ? footprint : 0.0f;
}

}  // namespace

SurfacePoint shade_surface(const SceneData& scene, const RayHit& hit, const glm::vec3& wo, float cone_width) {
  const MeshData& mesh = scene.meshes[hit.mesh];
  const glm::uvec3 tri = mesh.triangles[hit.triangle];
  const float b1 = hit.u, b2 = hit.v, b0 = 1.0f - hit.u - hit.v;
  const glm::vec3 p0 = mesh.positions[tri.x], p1 = mesh.positions[tri.y], p2 = mesh.positions[tri.z];

  const uint32_t part = mesh.triangle_parts.empty() ? 0 : mesh.triangle_parts[hit.triangle];
  const uint32_t material_index = mesh.part_materials[part];
  const Material& material = scene.materials[material_index];
  const MaterialShading& shading = scene.material_shading[material_index];
  SurfacePoint sp(shading.untextured);
  sp.part = static_cast<int32_t>(part);
  sp.mesh = hit.mesh;
  sp.material = material_index;
  // Interpolating the vertices is more precise than origin + t dir.
  sp.position = b0 * p0 + b1 * p1 + b2 * p2;
  const glm::vec3 ng_front = normalize_or(glm::cross(p1 - p0, p2 - p0), wo);
  const bool backfacing = glm::dot(ng_front, wo) < 0.0f;
  const float facing_sign = backfacing ? -1.0f : 1.0f;
  sp.geometric_normal = facing_sign * ng_front;
  sp.front_face = !backfacing;

  // The front-side smooth normal; normal mapping happens on the front side, then everything
  // is flipped toward the viewer (surfaces are two-sided).
  glm::vec3 n_front = ng_front;
  if (!mesh.normals.empty()) {
    n_front = normalize_or(b0 * mesh.normals[tri.x] + b1 * mesh.normals[tri.y] + b2 * mesh.normals[tri.z],
                           ng_front);
  }

  // Only textures read the UV.
  const bool textured_parameters = shading.textured;
  const bool textured = textured_parameters || material.normal_map;
  if (textured && !mesh.uvs.empty()) sp.uv = b0 * mesh.uvs[tri.x] + b1 * mesh.uvs[tri.y] + b2 * mesh.uvs[tri.z];
  if (!std::isfinite(sp.uv.x) || !std::isfinite(sp.uv.y)) sp.uv = glm::vec2(0.0f);

  sp.smooth_normal = facing_sign * n_front;
  if (material.normal_map) sp.tangent_space_normal = tangent_space_normal(material, sp.uv);
  if (material.normal_map && !mesh.tangents.empty()) {
    const glm::vec4 tangent =
        b0 * mesh.tangents[tri.x] + b1 * mesh.tangents[tri.y] + b2 * mesh.tangents[tri.z];
    n_front = apply_normal_map(material, sp.tangent_space_normal, n_front, tangent);
  }
  glm::vec3 n = facing_sign * n_front;
  if (!is_finite(n)) n = sp.geometric_normal;
  sp.shading_normal = ensure_valid_reflection(sp.geometric_normal, wo, n);

  if (textured_parameters) {
    const float footprint =
        cone_width > 0.0f && !mesh.uvs.empty() ? uv_footprint(mesh, tri, sp.geometric_normal, wo, cone_width) : 0.0f;
    look_up_textures(material, sp.uv, footprint, sp.inputs);
  }
  if (material.vertex_colors && !mesh.colors.empty()) {
    const glm::vec3 color = b0 * mesh.colors[tri.x] + b1 * mesh.colors[tri.y] + b2 * mesh.colors[tri.z];
    sp.inputs.set(MaterialParameter::BaseColor, sp.inputs.color(MaterialParameter::BaseColor) * color);
  }
  return sp;
}

std::optional<PrincipledInputs> constant_inputs(const Material& material) {
  if (material.textured() || material.vertex_colors) return std::nullopt;
  return PrincipledInputs(material);
}

}  // namespace matrender
