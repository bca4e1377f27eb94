#include "object_renderer.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "dataset_checks.h"
#include "matgeom/bounding_sphere.h"
#include "matgeom/material_classes.h"
#include "matrender/paper_setup.h"

namespace make_dataset {
namespace {

using nlohmann::ordered_json;
constexpr double kDegree = 3.14159265358979323846 / 180.0;

matrender::SceneDescription object_scene(const DatasetConfig& config, size_t index) {
  const ObjectConfig& object = config.objects[index];
  matrender::SceneDescription scene;
  for (size_t s = 0; s < object.slots.size(); ++s)
    for (size_t k = 0; k < object.slots[s].candidates.size(); ++k) {
      const MaterialCandidate& candidate = object.slots[s].candidates[k];
      const matrender::Origin origin{config.source, fmt::format("/objects/{}/materials/{}/{}", index,
                                                                object.slots[s].key, k)};
      matrender::MaterialDescription material;
      if (const auto* spec = std::get_if<matgeom::LibraryMaterialSpec>(&candidate.source))
        material.library = matrender::LibraryMaterialRequest{*spec, config.render.material_resolution, origin};
      else
        material.folder = matrender::MaterialFolderFile{std::get<std::string>(candidate.source), origin};
      scene.materials.emplace(candidate.name, std::move(material));
    }
  matrender::ObjectDescription description;
  description.source = object.source;
  description.uv_pass = object.uv_pass;
  description.origin = matrender::Origin{config.source, "/objects/" + std::to_string(index)};
  scene.objects.push_back(std::move(description));
  scene.lights = matrender::LightRigDescription{config.illuminance_lux};
  scene.camera.placement = matrender::MatrixPlacement{};
  scene.camera.width = config.render.width;
  scene.camera.height = config.render.height;
  return scene;
}

double grid_radius(const CameraConfig& camera, const matgeom::TriangleMesh& mesh, const matgeom::Sphere& bounds,
                   const glm::dvec3& centre, double aspect) {
  switch (camera.radius_rule) {
    case RadiusRule::Fixed:
      return camera.radius_m;
    case RadiusRule::BoundingBox: {
      glm::dvec3 low(mesh.positions.front()), high(mesh.positions.front());
      for (const glm::vec3& p : mesh.positions) low = glm::min(low, glm::dvec3(p)), high = glm::max(high, glm::dvec3(p));
      const glm::dvec3 extent = high - low;
      return std::max(camera.min_radius_m, camera.box_factor * std::max({extent.x, extent.y, extent.z}));
    }
    case RadiusRule::Fit:
    default: {
      // The sphere about the grid's centre that holds the bounding sphere, seen within the
      // narrower of the two fields of view.
      const double reach = glm::length(bounds.center - centre) + bounds.radius;
      const double vertical = camera.vertical_fov_deg * kDegree;
      const double horizontal = 2.0 * std::atan(aspect * std::tan(0.5 * vertical));
      return reach / std::sin(0.5 * std::min(vertical, horizontal)) / camera.fill;
    }
  }
}

ordered_json vector_json(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

ordered_json matrix_json(const glm::dmat4& m) {
  ordered_json rows = ordered_json::array();
  for (int r = 0; r < 4; ++r) rows.push_back({m[0][r], m[1][r], m[2][r], m[3][r]});
  return rows;
}

}  // namespace

uint32_t dataset_aovs() {
  using P = matrender::MaterialParameter;
  return matrender::AovAlpha | matrender::AovNormalWorld | matrender::AovNormalTangent | matrender::AovDepth |
         matrender::AovLabel | matrender::AovAmbientOcclusion | matrender::AovSampleCount |
         matrender::parameter_aov(P::BaseColor) |
         matrender::parameter_aov(P::Roughness) | matrender::parameter_aov(P::Metallic);
}

ObjectRenderer::ObjectRenderer(const DatasetConfig& config, size_t object)
    : config_(config), object_index_(object), object_(config.objects[object]), built_(matrender::build_scene(object_scene(config, object))) {
  const matgeom::TriangleMesh& mesh = built_.object_surfaces.front();
  const size_t part_count = built_.scene.part_materials(built_.object_meshes.front()).size();
  slot_parts_ = parts_of_slots(config, object, mesh.part_names, part_count);
  const CameraConfig& camera = config.camera;
  grid_.center = matgeom::surface_centroid(mesh);
  grid_.radius = grid_radius(camera, mesh, built_.bounds, grid_.center,
                             static_cast<double>(config.render.width) / config.render.height);
  grid_.phi_min = camera.phi_min_deg * kDegree;
  grid_.phi_max = camera.phi_max_deg * kDegree;
  grid_.theta_min = camera.theta_min_deg * kDegree;
  grid_.theta_max = camera.theta_max_deg * kDegree;
  grid_.n_phi = camera.n_phi;
  grid_.n_theta = camera.n_theta;
  exposure_stops_ = config.render.exposure_stops ? *config.render.exposure_stops
                                                 : matrender::grey_card_exposure(*built_.rig, grid_);
}

void ObjectRenderer::select_variant(const matgeom::MaterialVariant& variant) {
  matrender::ObjectDescription materials;
  materials.origin = matrender::Origin{config_.source, "/objects"};
  const std::vector<std::string>& part_names = built_.object_surfaces.front().part_names;
  for (size_t s = 0; s < object_.slots.size(); ++s) {
    const std::string& name = object_.slots[s].candidates[variant[s]].name;
    if (object_.slots[s].parts.empty())
      materials.material = name;  // every part first; the named slots' parts below replace it
    else
      for (const uint32_t part : slot_parts_[s]) materials.part_materials[part_names[part]] = name;
  }
  matrender::assign_object_materials(built_, 0, materials);
  const std::vector<uint32_t>& ids = built_.scene.part_materials(built_.object_meshes.front());
  slot_materials_.clear();
  for (size_t s = 0; s < object_.slots.size(); ++s) {
    const MaterialCandidate& candidate = object_.slots[s].candidates[variant[s]];
    int32_t label = 0;
    if (!slot_parts_[s].empty()) label = built_.scene.material(ids[slot_parts_[s].front()]).label_id;
    else if (const auto* spec = std::get_if<matgeom::LibraryMaterialSpec>(&candidate.source))
      label = matgeom::label_id(spec->material_class);
    if (!matgeom::material_class_of_label(label) || label == 0)
      throw InputError(config_.source + ": " + object_.name + ": material \"" + candidate.spelled +
                       "\" has no material class, so its pixels would be labelled background; name its folder "
                       "after its class (\"wood_oak\") or give its metadata.json a category");
    slot_materials_.push_back({object_.slots[s].key, candidate.name, label});
  }
}

matrender::Camera ObjectRenderer::view_camera(size_t view) const {
  const auto n_theta = static_cast<size_t>(grid_.n_theta);
  return matrender::grid_view(grid_, static_cast<int>(view / n_theta), static_cast<int>(view % n_theta),
                              config_.render.width, config_.render.height, config_.camera.vertical_fov_deg * kDegree);
}

matlearn::FramePose ObjectRenderer::view_pose(size_t view, const std::string& stem) const {
  const glm::dmat4 m = view_camera(view).camera_to_world;
  matlearn::FramePose pose;
  pose.stem = stem;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) pose.camera_to_world[static_cast<size_t>(r)][static_cast<size_t>(c)] = m[c][r];
  return pose;
}

matlearn::CameraIntrinsics ObjectRenderer::intrinsics() const {
  return matlearn::pinhole_intrinsics(config_.render.width, config_.render.height,
                                      config_.camera.vertical_fov_deg * kDegree);
}

matrender::RenderSettings ObjectRenderer::sampling_settings() const {
  matrender::RenderSettings settings;
  settings.samples_per_pixel = config_.render.samples;
  settings.noise_threshold = config_.render.noise_threshold;
  settings.min_samples = config_.render.min_samples;
  settings.denoise = config_.render.denoise;
  return settings;
}

int ObjectRenderer::fewest_samples() const { return matrender::fewest_samples_per_pixel(sampling_settings()); }

bool ObjectRenderer::render(size_t view, uint32_t seed, int threads, const std::atomic<bool>* cancel,
                            matlearn::FrameMaps& maps, matrender::RenderStats* stats) {
  const RenderConfig& r = config_.render;
  matrender::RenderSettings settings = sampling_settings();
  settings.seed = seed;
  settings.threads = threads;
  settings.max_bounces = r.max_bounces;
  settings.max_diffuse_bounces = r.max_diffuse_bounces;
  settings.max_glossy_bounces = r.max_glossy_bounces;
  settings.max_transmission_bounces = r.max_transmission_bounces;
  settings.transparent_background = true;
  using P = matrender::MaterialParameter;
  settings.aovs = dataset_aovs();
  settings.ambient_occlusion_error = r.ambient_occlusion_error;
  settings.ambient_occlusion_distance = r.ambient_occlusion_distance_m;
  settings.cancel = cancel;
  matrender::FrameBuffers frame;
  const matrender::RenderStats result = matrender::render(built_.scene, view_camera(view), settings, frame);
  if (stats) *stats = result;
  if (result.cancelled) return false;
  maps.width = frame.width;
  maps.height = frame.height;
  maps.color = std::move(frame.color);
  maps.coverage = std::move(frame.alpha);
  maps.base_color = std::move(frame.parameter(P::BaseColor));
  maps.roughness = std::move(frame.parameter(P::Roughness));
  maps.metallic = std::move(frame.parameter(P::Metallic));
  maps.ambient_occlusion = std::move(frame.ambient_occlusion);
  maps.normal_world = std::move(frame.normal_world);
  maps.normal_tangent = std::move(frame.normal_tangent);
  maps.depth = std::move(frame.depth);
  maps.label = std::move(frame.label);
  maps.sample_count = std::move(frame.sample_count);
  maps.exposure_stops = exposure_stops_;
  return true;
}

std::string ObjectRenderer::provenance_json(const DatasetPlan& plan, size_t variant) const {
  const size_t object = object_index_;
  ordered_json json;
  json["software"] = {{"name", "matpredict make_dataset"}, {"version", MATPREDICT_VERSION}};
  ordered_json source;
  if (const auto* builtin = std::get_if<matrender::BuiltinObject>(&object_.source))
    source = {{"builtin", builtin->name}, {"seed", builtin->seed}};
  else
    source = {{"mesh", std::filesystem::path(std::get<matrender::MeshFile>(object_.source).path).filename().string()}};
  const char* uv_pass[] = {"never", "when_missing", "always"};
  source["uv_pass"] = uv_pass[static_cast<int>(object_.uv_pass)];
  json["object"] = {{"name", object_.name}, {"source", source}};

  ordered_json slots = ordered_json::array();
  const std::vector<std::string>& part_names = built_.object_surfaces.front().part_names;
  for (size_t s = 0; s < object_.slots.size(); ++s) {
    const MaterialCandidate& candidate = object_.slots[s].candidates[plan.variants[object][variant][s]];
    ordered_json parts = ordered_json::array();
    for (const uint32_t part : slot_parts_[s]) parts.push_back(part < part_names.size() ? part_names[part] : std::to_string(part));
    ordered_json material = {{"slot", object_.slots[s].key}, {"parts", parts}, {"material", candidate.name}};
    if (const auto* spec = std::get_if<matgeom::LibraryMaterialSpec>(&candidate.source))
      material["library"] = {{"spec", matgeom::library_material_name(*spec)},
                             {"seed", spec->seed},
                             {"resolution", config_.render.material_resolution}};
    else
      material["matsynth"] = candidate.spelled;
    material["label_id"] = slot_materials_[s].label_id;
    slots.push_back(material);
  }
  json["variant"] = {{"index", variant},
                     {"of", plan.variants[object].size()},
                     {"combination", config_.combination == matgeom::VariantCombination::Cartesian ? "cartesian" : "zip"},
                     {"max_variants", config_.max_variants ? ordered_json(*config_.max_variants) : ordered_json(nullptr)},
                     {"cap_seed", config_.variant_seed},
                     {"slots", slots}};

  json["camera"] = {{"grid",
                     {{"center", vector_json(grid_.center)},
                      {"radius", grid_.radius},
                      {"phi", {grid_.phi_min, grid_.phi_max}},
                      {"theta", {grid_.theta_min, grid_.theta_max}},
                      {"n_phi", grid_.n_phi},
                      {"n_theta", grid_.n_theta},
                      {"cell_centres", "phi_i = phi_min + (i + 1/2)(phi_max - phi_min)/n_phi, theta_j likewise"}}},
                    {"vertical_fov", config_.camera.vertical_fov_deg * kDegree},
                    {"width", config_.render.width},
                    {"height", config_.render.height}};

  ordered_json lamps = ordered_json::array();
  for (const matgeom::RigLight& lamp : built_.rig->lights)
    lamps.push_back({{"kind", lamp.kind == matgeom::RigLightKind::Area ? "area" : "spot"},
                     {"light_to_world", matrix_json(lamp.light_to_world)},
                     {"size", {lamp.size_x, lamp.size_y}},
                     {"spot_angle", lamp.spot_angle},
                     {"spot_blend", lamp.spot_blend},
                     {"power_w", lamp.power},
                     {"color", vector_json(lamp.color)}});
  json["lights"] = {{"rig", "paper"},
                    {"illuminance_lux", built_.rig->illuminance_lux},
                    {"power_scale", built_.rig->power_scale},
                    {"bounds", {{"center", vector_json(built_.bounds.center)}, {"radius", built_.bounds.radius}}},
                    {"lamps", lamps}};

  const RenderConfig& r = config_.render;
  ordered_json seeds = ordered_json::object();
  for (size_t view = 0; view < plan.views; ++view)
    seeds[view_stem(plan, view)] = frame_seed(config_.seed, {object, variant, view});
  json["render"] = {{"renderer", "matpredict libmatrender (Principled BSDF path tracer, Cycles 3.4 conventions)"},
                    {"samples", r.samples},
                    {"noise_threshold", r.noise_threshold},
                    {"min_samples", r.min_samples},
                    {"fewest_samples", fewest_samples()},
                    {"denoise", r.denoise},
                    {"max_bounces", r.max_bounces},
                    {"max_diffuse_bounces", r.max_diffuse_bounces},
                    {"max_glossy_bounces", r.max_glossy_bounces},
                    {"max_transmission_bounces", r.max_transmission_bounces},
                    {"exposure_stops", exposure_stops_},
                    {"exposure_rule", r.exposure_stops ? "configured"
                                                       : "grey card: a Lambertian card at the grid's centre facing the "
                                                         "camera shows half its albedo, for its illuminance averaged over "
                                                         "the grid's views (log2(683 pi / lux) - 1)"},
                    {"transparent_background", true},
                    {"ambient_occlusion",
                     {{"distance_m", r.ambient_occlusion_distance_m},
                      {"standard_error_at_most", r.ambient_occlusion_error},
                      {"rule", "each pixel traces occlusion rays from its hits until the standard error estimated from "
                               "its own trials, sqrt(p (1 - p) / n) with p = (escaped + 1) / (n + 2), is at most the "
                               "bound; stratified directions make the true error smaller"}}},
                    {"frame_seeds", seeds}};
  json["configuration"] = config_.canonical_yaml;
  return json.dump();
}

}  // namespace make_dataset
