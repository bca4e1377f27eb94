#include "integrator/path_tracer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "accel/ray_offset.h"
#include "bsdf/bsdf.h"
#include "bsdf/principled.h"
#include "bsdf/shading_frame.h"
#include "integrator/shadow_terminator.h"
#include "sampling/warp.h"
#include "util/finite.h"
#include "util/channel_average.h"

namespace matrender {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// Random-number pairs of one path vertex: the lamp (its choice reused for the point on it), the
// BSDF (its lobe choice reused for the direction), and (Russian roulette, a multiscatter walk's
// seed). Pair 0 is the pixel filter's.
struct VertexDimensions {
  uint32_t light, bsdf, roulette;
  explicit VertexDimensions(int bounce)
      : light(1 + 3 * static_cast<uint32_t>(bounce)), bsdf(light + 1), roulette(light + 2) {}
};

float max_component(const glm::vec3& v) { return std::max(v.x, std::max(v.y, v.z)); }

// The seed of a vertex's multiscatter walk: the roulette pair's second number, which nothing
// else uses, as bits.
uint32_t walk_seed(const PixelSampler& sampler, const VertexDimensions& dims) {
  return static_cast<uint32_t>(sampler.get_2d(dims.roulette).y * 0x1p32f);
}

// Where a shadow ray toward unit direction wi starts before the usual ray offset: the hit point,
// lifted toward the smooth surface near the terminator of a smooth-shaded triangle (Cycles'
// shadow_ray_offset; shadow_terminator.h). ng is the geometric normal on the side the ray's lobes
// scatter to. Cycles picks the side from the smooth normal instead; where the two disagree (a
// lamp above the bent shading normal but below the smooth one) its lift crosses the triangle, and
// from inside a closed surface the ray then starts outside it.
glm::vec3 shadow_ray_start(const MeshData& mesh, const RayHit& hit, const SurfacePoint& sp, const glm::vec3& wi,
                           const glm::vec3& ng) {
  const float cutoff = mesh.shadow_terminator_geometry_offset;
  if (mesh.normals.empty() || !(cutoff > 0.0f)) return sp.position;
  const float smooth_dot_l = glm::dot(sp.smooth_normal, wi);
  const float amount = shadow_terminator_offset_amount(std::abs(smooth_dot_l), glm::dot(ng, wi), cutoff);
  if (!(amount > 0.0f)) return sp.position;
  const glm::uvec3 tri = mesh.triangles[hit.triangle];
  const std::array<glm::vec3, 3> v = {mesh.positions[tri.x], mesh.positions[tri.y], mesh.positions[tri.z]};
  const std::array<glm::vec3, 3> n = {mesh.normals[tri.x], mesh.normals[tri.y], mesh.normals[tri.z]};
  const glm::vec3 w(1.0f - hit.u - hit.v, hit.u, hit.v);
  const glm::vec3 lifted = sp.position + amount * smooth_surface_offset(v, n, w, ng);
  return is_finite(lifted) ? lifted : sp.position;
}

}  // namespace

PathSettings::PathSettings(const RenderSettings& settings, float camera_pixel_spread_angle)
    : max_bounces(settings.max_bounces),
      max_diffuse_bounces(settings.max_diffuse_bounces),
      max_glossy_bounces(settings.max_glossy_bounces),
      max_transmission_bounces(settings.max_transmission_bounces),
      max_transparent_bounces(settings.max_transparent_bounces),
      transparent_background(settings.transparent_background),
      clearcoat_estimator(settings.cycles_parity ? ClearcoatEstimator::Cycles34 : ClearcoatEstimator::Integral),
      multiscatter_walk(settings.cycles_parity ? MultiscatterWalk::Cycles34 : MultiscatterWalk::Exact),
      pixel_spread_angle(settings.mipmaps && !settings.cycles_parity ? camera_pixel_spread_angle : 0.0f) {}

PathTracer::PathTracer(const SceneData& scene, const LightSampler& lights, const PathSettings& settings)
    : scene_(scene), lights_(lights), settings_(settings) {
  for (const Material& material : scene.materials) {
    const ParameterValue& alpha = material[MaterialParameter::Alpha];
    if (alpha.texture || alpha.value.x < 1.0f) has_transparency_ = true;
    const std::optional<PrincipledInputs> inputs = constant_inputs(material);
    constant_parameters_.push_back(
        inputs ? std::optional<PrincipledParameters>(PrincipledParameters(*inputs, settings.clearcoat_estimator,
                                                                           settings.multiscatter_walk))
               : std::nullopt);
  }
}

// Inlined into trace()'s two calls: as a call it cost 12 instructions a sample more than the code it
// gathered (callgrind, the vase at 64x64).
[[gnu::always_inline]] inline void PathTracer::add_emitters_found(glm::vec3& radiance, const glm::vec3& throughput, const glm::vec3& origin,
                                    const glm::vec3& dir, const RayHit& hit, const SurfacePoint* surface,
                                    const ScatteredRay& ray) const {
  // Later rays see the lamps; camera rays only those visible to them.
  if (lights_.has_area_lights() && (!ray.camera_ray || lights_.has_camera_visible_lamps())) {
    glm::vec3 lamps(0.0f);
    lights_.for_each_area_hit(origin, dir, hit.hit() ? hit.t : kInfinity, [&](size_t index, const auto& lamp, float t) {
      if (ray.camera_ray && !lamp.visible_to_camera()) return;
      // The lamp's density from where the ray left: the scattering vertex, not a surface the ray
      // passed through since (origin).
      const glm::vec3& from = ray.from->p;
      lamps += lights_.found_light_weight(index, ray, [&] { return lamp.pdf(from, dir, t + glm::length(origin - from)); }) *
               lamp.radiance(dir);
    });
    radiance += throughput * lamps;
  }
  if (!hit.hit()) {
    if (!ray.camera_ray || !settings_.transparent_background) radiance += throughput * lights_.escaped_radiance(dir, ray);
    return;
  }
  // Emission, seen by every ray including the camera's.
  const glm::vec3 emitted = surface->emitted();
  if (emitted == glm::vec3(0.0f)) return;
  float weight = 1.0f;
  if (const std::optional<size_t> emitter = lights_.emitter_index(hit.mesh)) {
    const auto& mesh_emitter = std::get<MeshEmitter>(lights_.light(*emitter));
    weight = lights_.found_light_weight(*emitter, ray, [&] {
      return mesh_emitter.pdf(ray.from->p, dir, glm::length(surface->position - ray.from->p), hit.triangle);
    });
  }
  radiance += throughput * emitted * weight;
}

glm::vec3 PathTracer::transmittance(const glm::vec3& origin, const glm::vec3& dir, float distance,
                                    uint32_t* rays) const {
  ++*rays;
  if (!has_transparency_) return glm::vec3(scene_.accel.occluded(origin, dir, distance) ? 0.0f : 1.0f);
  // Through surfaces with transparency, each hit passes 1 - alpha, up to the limit of
  // transparent bounces; an opaque one stops the ray. A ray toward an infinite light never runs
  // out of length.
  const bool unbounded = std::isinf(distance);
  const glm::vec3 target = unbounded ? origin : origin + distance * dir;
  glm::vec3 from = origin;
  float remaining = distance;
  glm::vec3 passed(1.0f);
  for (int crossed = 0;; ++crossed) {
    const RayHit hit = scene_.accel.intersect(from, dir, remaining);
    if (!hit.hit()) return passed;
    // As for a path: the limit's count of surfaces are passed, and one more (Cycles keeps every
    // limit one above its setting).
    if (crossed > settings_.max_transparent_bounces) return glm::vec3(0.0f);
    const SurfacePoint sp = shade_surface(scene_, hit, -dir);
    passed *= 1.0f - sp.inputs.coverage();
    if (!(max_component(passed) > 0.0f)) return glm::vec3(0.0f);
    from = offset_ray_origin(sp.position, -sp.geometric_normal);
    if (!unbounded) remaining = glm::length(target - from);
    ++*rays;
  }
}

PathResult PathTracer::trace(const glm::vec3& camera_origin, const glm::vec3& camera_dir,
                             const RayHit& camera_hit, const PixelSampler& sampler,
                             SurfacePoint* first_surface) const {
  PathResult result;
  glm::vec3 throughput(1.0f);
  glm::vec3 origin = camera_origin;
  glm::vec3 dir = camera_dir;
  float bsdf_pdf = 0.0f;
  bool bsdf_delta = false;
  int bounce = 0;  // scattering bounces; passing through a transparent surface is none
  int diffuse_bounces = 0;
  int glossy_bounces = 0;
  int transmission_bounces = 0;
  int transparent_bounces = 0;
  bool passed_transparent = false;  // the ray left its last surface through its transparency
  float cone_width = 0.0f;  // of the ray cone at its origin
  bool cone_followed = true;  // until a non-specular bounce
  PickSite site;       // where this vertex picks a light
  PickSite scattered;  // the site of the vertex that scattered the ray, for MIS at what it finds

  // `vertex` counts every surface met, transparent ones included, so each gets its own random
  // numbers.
  for (int vertex = 0;; ++vertex) {
    // One const initialisation: GCC 12 compiled a copy reassigned for later vertices into a loop
    // 12 % slower on the 10k sphere (render_bench), with fewer instructions.
    const RayHit hit = vertex == 0 ? camera_hit : scene_.accel.intersect(origin, dir, kInfinity);
    if (vertex > 0) ++result.rays;  // the camera's ray is the caller's
    // Still the camera's ray: it has passed only through transparent surfaces.
    const bool camera_ray = bounce == 0;
    const ScatteredRay arrival{bsdf_pdf, bsdf_delta, camera_ray, &scattered};
    if (!hit.hit()) {
      add_emitters_found(result.radiance, throughput, origin, dir, hit, nullptr, arrival);
      // What the camera sees through: the film's transparency (Cycles averages the channels).
      if (camera_ray) result.transparency = channel_average(throughput);
      break;
    }

    const glm::vec3 wo_world = -dir;
    cone_width += settings_.pixel_spread_angle * hit.t;
    // After a non-specular bounce the footprint a camera pixel would have here (pbrt-v4,
    // Camera::Approximate_dp_dxy): the detail a camera could see, and the mip levels it reads.
    const float footprint =
        cone_followed ? cone_width
                      : settings_.pixel_spread_angle * glm::length(origin + hit.t * dir - camera_origin);
    const SurfacePoint sp = shade_surface(scene_, hit, wo_world, footprint);
    if (vertex == 0) {
      result.hit = true;
      result.first_distance = hit.t;
      if (first_surface) *first_surface = sp;
    }
    add_emitters_found(result.radiance, throughput, origin, dir, hit, &sp, arrival);
    // Cycles terminates here, after the lamp and background hits of the arriving ray counted.
    if (bounce > settings_.max_bounces || diffuse_bounces > settings_.max_diffuse_bounces ||
        glossy_bounces > settings_.max_glossy_bounces || transmission_bounces > settings_.max_transmission_bounces ||
        transparent_bounces > settings_.max_transparent_bounces)
      break;

    const VertexDimensions dims(vertex);
    // Russian roulette, continuation probability min(1, sqrt(max throughput)), after Cycles'
    // minimum of one bounce (its min_bounce 0, kept one above) or, on a ray that last passed a
    // transparent surface, one transparent bounce.
    if ((passed_transparent ? transparent_bounces : bounce) > 1) {
      const float continue_probability = std::min(1.0f, std::sqrt(max_component(throughput)));
      if (!(sampler.get_2d(dims.roulette).x < continue_probability)) break;
      throughput /= continue_probability;
    }

    const ShadingFrame frame = ShadingFrame::from_normal(sp.shading_normal);
    const glm::vec3 wo = frame.to_local(wo_world);
    const std::optional<PrincipledParameters>& constant = constant_parameters_[sp.material];
    const PrincipledParameters parameters =
        constant ? *constant : PrincipledParameters(sp.inputs, settings_.clearcoat_estimator, settings_.multiscatter_walk);
    ShadingGeometry geometry;
    geometry.front_face = sp.front_face;
    if (sp.smooth_normal != sp.shading_normal) {
      geometry.smooth_normal = frame.to_local(sp.smooth_normal);
      // Without a normal map the clearcoat's and the velvet's normal is the shading normal: both
      // are the smooth normal made valid for reflection.
      if ((parameters.clearcoat_enabled || parameters.velvet_enabled) && scene_.materials[sp.material].normal_map)
        geometry.unmapped_normal =
            frame.to_local(ensure_valid_reflection(sp.geometric_normal, wo_world, sp.smooth_normal));
    }
    Bsdf bsdf(frame, sp.geometric_normal);
    add_principled_lobes(parameters, wo, geometry, &bsdf.lobes(), parameters.multiscatter ? walk_seed(sampler, dims) : 0);

    // Next-event estimation: one lamp, one point on it.
    if (!lights_.empty() && is_non_specular(bsdf.flags())) {
      site = lights_.site(sp.position, {sp.shading_normal, is_transmissive(bsdf.flags())});
      const auto light = lights_.sample(site, sampler.get_2d(dims.light));
      if (light) {
        float pdf_bsdf;
        BxDFFlags lobes;
        const glm::vec3 f = bsdf.eval(light->wi, &pdf_bsdf, &lobes);
        if (max_component(f) > 0.0f) {
          // The shadow ray starts on the side its lobes scatter to: the viewer's for reflection,
          // the far one for transmission, whichever side of the triangle the lamp is on. A lamp
          // beyond the triangle's plane is then reached only around the surface, never through it.
          const glm::vec3 side = is_reflective(lobes) ? sp.geometric_normal : -sp.geometric_normal;
          // From a start lifted off the triangle the ray aims again at the same lamp point (toward
          // an infinite light, in the same direction).
          const glm::vec3 start = shadow_ray_start(scene_.meshes[hit.mesh], hit, sp, light->wi, side);
          glm::vec3 shadow_dir = light->wi;
          float shadow_distance = light->distance;
          if (start != sp.position && !std::isinf(light->distance)) {
            const glm::vec3 to_light = sp.position + light->distance * light->wi - start;
            shadow_distance = glm::length(to_light);
            shadow_dir = to_light / shadow_distance;
          }
          const glm::vec3 shadow_origin = offset_ray_origin(start, side);
          // Shorten the shadow ray by a relative margin so it cannot hit geometry touching the lamp.
          const glm::vec3 visible =
              transmittance(shadow_origin, shadow_dir, shadow_distance * (1.0f - 1e-4f), &result.rays);
          if (max_component(visible) > 0.0f) {
            const float weight = light->delta ? 1.0f : power_heuristic(light->pdf, pdf_bsdf);
            result.radiance += throughput * visible * f * light->radiance * (weight / light->pdf);
          }
        }
      }
    }

    BsdfSample s;
    if (!bsdf.sample(sampler.get_2d(dims.bsdf), &s)) break;
    throughput *= s.weight;
    if (!(max_component(throughput) > 0.0f)) break;
    passed_transparent = is_transparent(s.flags);
    if (passed_transparent) {
      // Straight on, as if the surface were not there: the ray keeps its direction and the
      // MIS pdf of the bounce that made it.
      ++transparent_bounces;
      origin = offset_ray_origin(sp.position, -sp.geometric_normal);
      continue;
    }
    ++bounce;
    bsdf_pdf = s.pdf;
    scattered = site;
    if (!is_specular(s.flags)) cone_followed = false;
    bsdf_delta = is_specular(s.flags);
    // Cycles counts a bounce by its label: transmission first, then diffuse, else glossy (a
    // mirror included).
    (is_transmissive(s.flags) ? transmission_bounces : is_diffuse(s.flags) ? diffuse_bounces : glossy_bounces)++;
    dir = s.wi;
    origin = offset_ray_origin(sp.position, is_reflective(s.flags) ? sp.geometric_normal : -sp.geometric_normal);
  }
  return result;
}

}  // namespace matrender
