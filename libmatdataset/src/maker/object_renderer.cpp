#include "matdataset/maker/object_renderer.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "matbase/pi.h"
#include "matdataset/maker/dataset_checks.h"
#include "matgeom/bounding_sphere.h"
#include "matgeom/uv/uv_scale.h"
#include "matmaterial/folder/material_folder.h"
#include "matmaterial/library/material_library.h"
#include "matmaterial/material_classes.h"
#include "matrender/light_meter.h"
#include "matrender/paper_setup.h"
#include "matrender/scene_overrides.h"

namespace matdataset {
namespace {

using nlohmann::ordered_json;
constexpr double kDegree = matbase::kPi / 180.0;

// The object as the scene describes it, at UV scale `uv_scale`.
matrender::ObjectDescription object_description(const DatasetConfig& config, size_t index, double uv_scale) {
  const ObjectConfig& object = config.objects[index];
  matrender::ObjectDescription description;
  std::visit([&description](const auto& source) { description.source = source; }, object.source);
  description.uv_pass = object.uv_pass;
  description.uv_scale = uv_scale;
  description.origin = matrender::Origin{config.source, "/objects/" + std::to_string(index)};
  return description;
}

// The scan's parts around the object of a `kind: scan` object, in their own materials.
matrender::ObjectDescription scan_surroundings(const DatasetConfig& config, size_t index) {
  const ObjectConfig& object = config.objects[index];
  matrender::MeshFile rest = std::get<matrender::MeshFile>(object.source);
  rest.except_parts = object.surroundings.scan.target;
  rest.only_parts.clear();
  matrender::ObjectDescription surroundings;
  surroundings.source = rest;
  surroundings.surroundings = true;
  surroundings.origin = matrender::Origin{config.source, "/objects/" + std::to_string(index) + "/surroundings"};
  return surroundings;
}

// The paper's scene of the object (its rig at the configured illuminance) at UV scale
// `uv_scale`, in `room` when it has one, or back in its scan (the scene's second object,
// surroundings), with every
// candidate material of its slots among the scene's materials; each frame places the camera
// itself.
matrender::SceneDescription object_scene(const DatasetConfig& config, size_t index, double uv_scale,
                                         const std::optional<matgeom::RoomSpec>& room,
                                         const std::vector<DistractorSlot>& distractors) {
  const ObjectConfig& object = config.objects[index];
  matrender::SceneDescription scene = matrender::paper_object_scene(object_description(config, index, uv_scale));
  if (room) {
    matrender::ObjectDescription surroundings;
    surroundings.source = matrender::RoomObject{*room};
    surroundings.surroundings = true;
    surroundings.origin = matrender::Origin{config.source, "/objects/" + std::to_string(index) + "/surroundings"};
    scene.objects.push_back(std::move(surroundings));
  }
  if (object.surroundings.kind == SurroundingsKind::Scan) scene.objects.push_back(scan_surroundings(config, index));
  // Each distractor where it was made; every frame moves it to its place (or hides it).
  for (const DistractorSlot& distractor : distractors) {
    matrender::ObjectDescription placed;
    std::visit([&placed](const auto& source) { placed.source = source; }, distractor.object);
    placed.uv_pass = matrender::UvPassMode::WhenMissing;
    placed.surroundings = true;
    placed.origin = matrender::Origin{config.source, "/objects/" + std::to_string(index) + "/surroundings/distractors"};
    scene.objects.push_back(std::move(placed));
  }
  matrender::SceneOverrides overrides;
  overrides.placement = matrender::MatrixPlacement{};
  overrides.width = config.render.width;
  overrides.height = config.render.height;
  for (size_t s = 0; s < object.slots.size(); ++s)
    for (size_t k = 0; k < object.slots[s].candidates.size(); ++k) {
      const MaterialCandidate& candidate = object.slots[s].candidates[k];
      const matrender::Origin origin{config.source, fmt::format("/objects/{}/materials/{}/{}", index,
                                                                object.slots[s].key, k)};
      overrides.materials.emplace(candidate.name,
                                  candidate_scene_material(candidate, config.render.material_resolution, origin));
    }
  matrender::apply_scene_overrides(overrides, scene);
  return scene;
}

}  // namespace

double camera_grid_radius(const CameraConfig& camera, const matgeom::TriangleMesh& mesh, const matgeom::Sphere& bounds,
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

namespace {

// A candidate as the scene's materials load it: generated by the library at the configured
// resolution, or read from its folder.
matmaterial::FolderMaterial load_candidate(const MaterialCandidate& candidate, int resolution) {
  if (const auto* spec = std::get_if<matmaterial::LibraryMaterialSpec>(&candidate.source))
    return matmaterial::generate_library_material(*spec, {resolution, 0});
  return matmaterial::read_material_folder(std::get<std::string>(candidate.source));
}

// The material with its images moved to the end of `images`, its image indices following them.
matmaterial::MaterialInputs with_images_appended(matmaterial::FolderMaterial material,
                                           std::vector<matbase::ImagePixels>& images) {
  const int offset = static_cast<int>(images.size());
  for (matmaterial::MaterialInput& input : material.material.inputs)
    if (input.image >= 0) input.image += offset;
  if (material.material.normal_image >= 0) material.material.normal_image += offset;
  images.insert(images.end(), std::make_move_iterator(material.images.begin()),
                std::make_move_iterator(material.images.end()));
  return material.material;
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
    : config_(config), object_index_(object), object_(config.objects[object]) {
  // The grid (and the room it sizes) from the object's surface as placed, before its UV pass,
  // which moves no vertex: the room is built into the object's scene with it.
  const matgeom::TriangleMesh surface =
      matrender::placed_object_surface(object_description(config, object, object_.uv_scales.front()));
  const CameraConfig& camera = config.camera;
  const matgeom::Sphere bounds = matgeom::minimal_enclosing_sphere(surface.positions);
  grid_.center = matgeom::surface_centroid(surface);
  grid_.radius = camera_grid_radius(camera, surface, bounds, grid_.center,
                                    static_cast<double>(config.render.width) / config.render.height);
  grid_.phi_min = camera.phi_min_deg * kDegree;
  grid_.phi_max = camera.phi_max_deg * kDegree;
  grid_.theta_min = camera.theta_min_deg * kDegree;
  grid_.theta_max = camera.theta_max_deg * kDegree;
  grid_.n_phi = camera.n_phi;
  grid_.n_theta = camera.n_theta;
  grid_views_ = static_cast<size_t>(camera.n_phi) * static_cast<size_t>(camera.n_theta);
  if (object_.surroundings.made_room()) room_ = surroundings_room(object_.surroundings, surface, grid_);
  if (object_.surroundings.kind == SurroundingsKind::Distractors) {
    const auto* builtin = std::get_if<matrender::BuiltinObject>(&object_.source);
    distractor_slots_ = draw_distractor_slots(object_.surroundings.distractors,
                                              builtin ? std::optional<std::string>(builtin->name) : std::nullopt,
                                              config.seed, object);
    target_footprint_ = footprint(surface);
    target_size_ = bounds.radius;
    // Within the walls (the room is square about the grid's centre), or the floor's edge.
    distractor_reach_ = kDistractorReachOfRoom * room_->half_width -
                        glm::length(target_footprint_.center - glm::dvec2(room_->floor_center));
  }
  built_ = matrender::build_scene(object_scene(config, object, object_.uv_scales.front(), room_, distractor_slots_));
  size_distractors();
  const matgeom::TriangleMesh& mesh = built_.object_surfaces.front();
  const size_t part_count = built_.scene.part_materials(built_.object_meshes.front()).size();
  slot_parts_ = parts_of_slots(config, object, mesh.part_names, part_count);
}

void ObjectRenderer::select_variant(size_t index, const MaterialVariant& variant, const std::atomic<bool>* cancel) {
  if (index != variant_index_ || variant != variant_) {
    lighting_.clear();
    view_surroundings_.clear();
  }
  // Another UV scale is another UV pass: the object is built again (its geometry, and so the
  // camera grid, stay as they are), lit again view by view.
  if (const double scale = object_.uv_scale_of(variant); scale != built_.object_uv_scales.front()) {
    built_ = matrender::build_scene(object_scene(config_, object_index_, scale, room_, distractor_slots_), cancel);
    size_distractors();
    lit_view_ = SIZE_MAX;
  }
  variant_index_ = index;
  variant_ = variant;
  built_.materials.cancel_on(cancel);
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
    else if (const auto* spec = std::get_if<matmaterial::LibraryMaterialSpec>(&candidate.source))
      label = matmaterial::label_id(spec->material_class);
    if (!matmaterial::material_class_of_label(label) || label == 0)
      throw matbase::InputError(config_.source + ": " + object_.name + ": material \"" + candidate.spelled +
                       "\" has no material class, so its pixels would be labelled background; name its folder "
                       "after its class (\"wood_oak\") or give its metadata.json a category");
    slot_materials_.push_back({object_.slots[s].key, candidate.name, label});
  }
  if (room_) put_surroundings_in_materials();
}

void ObjectRenderer::put_surroundings_in_materials() {
  surroundings_ = draw_surroundings(object_.surroundings, config_.seed, object_index_, variant_index_);
  matrender::ObjectDescription materials;
  materials.origin = matrender::Origin{config_.source, "/objects/" + std::to_string(object_index_) + "/surroundings"};
  const auto describe = [&](const MaterialCandidate& candidate, const char* key) {
    built_.materials.describe(candidate.name,
                              candidate_scene_material(candidate, config_.render.material_resolution,
                                                       matrender::Origin{config_.source, materials.origin.pointer.value() + "/" + key}));
    return candidate.name;
  };
  materials.part_materials[matgeom::kRoomFloorPart] = describe(*surroundings_.floor, "floor_materials");
  if (surroundings_.walls) {
    materials.part_materials[matgeom::kRoomWallsPart] = describe(*surroundings_.walls, "wall_materials");
    if (room_->ceiling) materials.part_materials[matgeom::kRoomCeilingPart] = surroundings_.walls->name;
  }
  matrender::assign_object_materials(built_, 1, materials);
  distractor_materials_ = draw_distractor_materials(object_.surroundings.distractors, distractor_slots_.size(),
                                                    config_.seed, object_index_, variant_index_);
  for (size_t k = 0; k < distractor_materials_.size(); ++k) {
    matrender::ObjectDescription distractor;
    distractor.origin = matrender::Origin{config_.source, materials.origin.pointer.value() + "/distractors/materials"};
    distractor.material = describe(distractor_materials_[k], "distractors/materials");
    matrender::assign_object_materials(built_, kFirstDistractor + k, distractor);
  }
}

size_t ObjectRenderer::target_pixels(size_t view) {
  // A quarter-size pass at most, one sample a pixel, no bounce: only which object each pixel sees.
  matrender::Camera camera = view_camera(view);
  const int width = std::min(camera.width, kVisibilityWidth);
  camera.height = std::max(1, static_cast<int>(std::lround(static_cast<double>(camera.height) * width / camera.width)));
  camera.width = width;
  matrender::RenderSettings settings;
  settings.samples_per_pixel = 1;
  settings.max_bounces = 0;
  settings.aovs = matrender::AovObjectId;
  matrender::FrameBuffers frame;
  matrender::render(built_.scene, camera, settings, frame);
  const auto target = static_cast<int32_t>(built_.object_meshes.front());
  return static_cast<size_t>(std::count(frame.object_id.begin(), frame.object_id.end(), target));
}

void ObjectRenderer::size_distractors() {
  distractor_sizings_.clear();
  distractor_radii_.clear();
  for (size_t k = 0; k < distractor_slots_.size(); ++k) {
    matgeom::TriangleMesh& surface = built_.object_surfaces[kFirstDistractor + k];
    const double scale = distractor_slots_[k].scale;
    const Footprint own = footprint(surface);
    const double size = matgeom::minimal_enclosing_sphere(surface.positions).radius;
    const double factor = size > 0.0 ? scale * target_size_ / size : 1.0;
    distractor_sizings_.push_back(distractor_sizing(own, factor));
    distractor_radii_.push_back(own.radius * factor);
    // Materials repeat their maps for the surface at its size (its place does not change that).
    matgeom::transform_mesh(surface, distractor_sizings_.back());
  }
}

void ObjectRenderer::place_distractors_in_scene(const std::vector<DistractorPlacement>& placements) {
  for (size_t k = 0; k < distractor_slots_.size(); ++k) built_.scene.set_mesh_enabled(built_.object_meshes[kFirstDistractor + k], false);
  for (const DistractorPlacement& placement : placements) {
    const uint32_t mesh = built_.object_meshes[kFirstDistractor + placement.slot];
    built_.scene.set_mesh_transform(mesh, placement.transform);
    built_.scene.set_mesh_enabled(mesh, true);
  }
}

const ObjectRenderer::ViewSurroundings& ObjectRenderer::view_surroundings(size_t view) {
  if (const auto found = view_surroundings_.find(view); found != view_surroundings_.end()) return found->second;
  const DistractorsConfig& config = object_.surroundings.distractors;
  ViewSurroundings best;
  if (object_.surroundings.kind == SurroundingsKind::Scan) return view_surroundings_.emplace(view, scan_view(view)).first->second;
  best.visible_fraction = -1.0;
  if (distractor_slots_.empty()) return view_surroundings_.emplace(view, best).first->second;
  // The target's pixels without distractors depend on the view alone, not on the variant.
  auto [unoccluded, first] = target_pixels_alone_.try_emplace(view, 0);
  if (first) {
    place_distractors_in_scene({});
    unoccluded->second = target_pixels(view);
  }
  const size_t alone = unoccluded->second;
  SeedStream draws = distractor_draws(config_.seed, object_index_, variant_index_, view);
  for (int attempt = 1; attempt <= config.tries; ++attempt) {
    const std::optional<std::vector<DistractorPlacement>> placements =
        place_distractors(config, target_footprint_, distractor_sizings_, distractor_radii_, room_->floor_center.z,
                          distractor_reach_, draws);
    if (!placements) continue;
    place_distractors_in_scene(*placements);
    const double visible = alone > 0 ? static_cast<double>(target_pixels(view)) / static_cast<double>(alone) : 1.0;
    if (visible > best.visible_fraction) best = {*placements, attempt, visible, visible >= config.visible_fraction};
    if (best.satisfied) break;
  }
  if (best.visible_fraction < 0.0) best = {{}, config.tries, 1.0, false};  // no draw placed them all: none stand there
  return view_surroundings_.emplace(view, best).first->second;
}

ObjectRenderer::ViewSurroundings ObjectRenderer::scan_view(size_t view) {
  // The target's pixels without the scan's other parts depend on the view alone.
  const uint32_t room = built_.object_meshes[1];
  auto [unoccluded, first] = target_pixels_alone_.try_emplace(view, 0);
  if (first) {
    built_.scene.set_mesh_enabled(room, false);
    unoccluded->second = target_pixels(view);
    built_.scene.set_mesh_enabled(room, true);
  }
  ViewSurroundings seen;
  const size_t alone = unoccluded->second;
  seen.visible_fraction = alone > 0 ? static_cast<double>(target_pixels(view)) / static_cast<double>(alone) : 1.0;
  seen.satisfied = seen.visible_fraction >= object_.surroundings.scan.visible_fraction;
  return seen;
}

std::string ObjectRenderer::view_surroundings_json(size_t view) {
  if (object_.surroundings.kind == SurroundingsKind::Scan) {
    const ViewSurroundings& seen = view_surroundings(view);
    return ordered_json{{"visible_fraction", seen.visible_fraction}, {"enough_visible", seen.satisfied}}.dump();
  }
  if (distractor_slots_.empty()) return "";
  const ViewSurroundings& drawn = view_surroundings(view);
  ordered_json placements = ordered_json::array();
  for (const DistractorPlacement& placement : drawn.placements)
    placements.push_back({{"slot", placement.slot},
                          {"material", distractor_materials_[placement.slot].name},
                          {"transform", matrix_json(placement.transform)}});
  return ordered_json{{"distractors", placements},
                      {"draws", drawn.tries},
                      {"visible_fraction", drawn.visible_fraction},
                      {"enough_visible", drawn.satisfied}}
      .dump();
}

matgeom::ObjectAsset ObjectRenderer::variant_asset() const {
  matgeom::ObjectAsset asset;
  asset.mesh = built_.object_surfaces.front();
  asset.materials.resize(built_.scene.part_materials(built_.object_meshes.front()).size());
  for (size_t s = 0; s < object_.slots.size(); ++s) {
    const MaterialCandidate& candidate = object_.slots[s].candidates[variant_[s]];
    matmaterial::FolderMaterial loaded = load_candidate(candidate, config_.render.material_resolution);
    const std::optional<double> tile_size_m = loaded.tile_size_m;
    const matmaterial::MaterialInputs material = with_images_appended(std::move(loaded), asset.images);
    for (const uint32_t part : slot_parts_[s])
      asset.materials[part] = tile_size_m ? matgeom::with_texture_repeats(
                                                material, matgeom::texture_repeats(asset.mesh, part, *tile_size_m))
                                          : material;
  }
  return asset;
}

matrender::Camera ObjectRenderer::view_camera(size_t view) const {
  const auto n_theta = static_cast<size_t>(grid_.n_theta);
  const size_t cell = view % grid_views_;
  return matrender::grid_view(grid_, static_cast<int>(cell / n_theta), static_cast<int>(cell % n_theta),
                              config_.render.width, config_.render.height, config_.camera.vertical_fov_deg * kDegree);
}

void ObjectRenderer::light_view(size_t view) {
  const ViewLighting& lighting = view_lighting(view);
  if (lit_view_ == view) return;
  matrender::set_scene_lighting(built_, lighting.scene.lights, lighting.scene.background, &environment_images_);
  lit_view_ = view;
}

const ObjectRenderer::ViewLighting& ObjectRenderer::view_lighting(size_t view) {
  if (const auto found = lighting_.find(view); found != lighting_.end()) return found->second;
  ViewLighting lighting;
  lighting.drawn = draw_frame_lighting(config_.lighting, config_.seed, {object_index_, variant_index_, view}, grid_views_,
                                       built_.bounds);
  const std::string where = fmt::format("{}: the lighting of {} view {}", config_.source, object_.name, view);
  lighting.scene = matrender::read_lighting_text(scene_lighting_json(lighting.drawn).dump(), where, ".");
  matrender::set_scene_lighting(built_, lighting.scene.lights, lighting.scene.background, &environment_images_);
  lit_view_ = view;
  lighting.exposure_stops =
      config_.render.exposure_stops
          ? *config_.render.exposure_stops
          : matrender::grey_card_exposure(built_.scene.lamps(), built_.scene.background(), grid_);
  return lighting_.emplace(view, std::move(lighting)).first->second;
}

std::string ObjectRenderer::view_lighting_json(size_t view) {
  const ViewLighting& lighting = view_lighting(view);
  ordered_json json = scene_lighting_json(lighting.drawn);
  json["setup"] = lighting.drawn.setup;
  json["background_visible"] = lighting.drawn.background_visible;
  json["exposure_stops"] = lighting.exposure_stops;
  return json.dump();
}

FramePose ObjectRenderer::view_pose(size_t view, const std::string& stem) {
  const glm::dmat4 m = view_camera(view).camera_to_world;
  FramePose pose;
  pose.stem = stem;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) pose.camera_to_world[static_cast<size_t>(r)][static_cast<size_t>(c)] = m[c][r];
  pose.lighting_json = view_lighting_json(view);
  pose.surroundings_json = view_surroundings_json(view);
  return pose;
}

CameraIntrinsics ObjectRenderer::intrinsics() const {
  return pinhole_intrinsics(config_.render.width, config_.render.height,
                            config_.camera.vertical_fov_deg * kDegree);
}

int ObjectRenderer::fewest_samples() const { return matrender::fewest_samples_per_pixel(config_.render.settings); }

bool ObjectRenderer::render(size_t view, uint32_t seed, int threads, const std::atomic<bool>* cancel,
                            FrameMaps& maps, matrender::RenderStats* stats) {
  light_view(view);
  const ViewLighting& lighting = view_lighting(view);
  if (!distractor_slots_.empty()) place_distractors_in_scene(view_surroundings(view).placements);
  matrender::RenderSettings settings = config_.render.settings;
  settings.seed = seed;
  settings.threads = threads;
  settings.transparent_background = !lighting.drawn.background_visible;
  using P = matrender::MaterialParameter;
  settings.aovs = dataset_aovs() | (has_surroundings() ? matrender::AovObjectId : 0u);
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
  if (has_surroundings()) {
    // The label is the target's alone; the region says what each pixel's labelled sample is on.
    const int32_t target = static_cast<int32_t>(built_.object_meshes.front());
    maps.region.resize(frame.object_id.size());
    for (size_t p = 0; p < maps.region.size(); ++p) {
      const int32_t hit = frame.object_id[p];
      const FrameRegion region = hit < 0 ? FrameRegion::Background
                                 : hit == target ? FrameRegion::Target
                                                 : FrameRegion::Surroundings;
      maps.region[p] = static_cast<int32_t>(region);
      if (region != FrameRegion::Target) maps.label[p] = 0;
    }
  }
  maps.sample_count = std::move(frame.sample_count);
  maps.exposure_stops = lighting.exposure_stops;
  maps.opaque_background = lighting.drawn.background_visible;
  return true;
}

std::optional<double> ObjectRenderer::shared_exposure_stops() {
  if (!lights_every_frame_alike(config_.lighting)) return std::nullopt;
  light_view(0);
  return view_lighting(0).exposure_stops;
}

std::string ObjectRenderer::provenance_json(const DatasetPlan& plan, size_t variant) {
  const size_t object = object_index_;
  ordered_json json;
  json["software"] = {{"name", "matpredict make_dataset"}, {"version", MATPREDICT_VERSION}};
  ordered_json source;
  if (const auto* builtin = std::get_if<matrender::BuiltinObject>(&object_.source))
    source = {{"builtin", builtin->name}, {"seed", builtin->seed}};
  else {
    const auto& file = std::get<matrender::MeshFile>(object_.source);
    source = {{"mesh", std::filesystem::path(file.path).filename().string()}};
    if (file.read_options.auto_smooth_deg) source["auto_smooth_deg"] = *file.read_options.auto_smooth_deg;
  }
  const char* uv_pass[] = {"never", "when_missing", "always"};
  source["uv_pass"] = uv_pass[static_cast<int>(object_.uv_pass)];
  // Recorded where it is not the default, so datasets made before it existed resume unchanged.
  if (const double scale = object_.uv_scale_of(plan.variants[object][variant]); scale != 1.0) source["uv_scale"] = scale;
  json["object"] = {{"name", object_.name}, {"source", source}};

  ordered_json slots = ordered_json::array();
  const std::vector<std::string>& part_names = built_.object_surfaces.front().part_names;
  for (size_t s = 0; s < object_.slots.size(); ++s) {
    const MaterialCandidate& candidate = object_.slots[s].candidates[plan.variants[object][variant][s]];
    ordered_json parts = ordered_json::array();
    for (const uint32_t part : slot_parts_[s]) parts.push_back(part < part_names.size() ? part_names[part] : std::to_string(part));
    ordered_json material = {{"slot", object_.slots[s].key}, {"parts", parts}, {"material", candidate.name}};
    if (const auto* spec = std::get_if<matmaterial::LibraryMaterialSpec>(&candidate.source))
      material["library"] = {{"spec", matmaterial::library_material_name(*spec)},
                             {"seed", spec->seed},
                             {"resolution", config_.render.material_resolution}};
    else
      material["matsynth"] = candidate.spelled;
    material["label_id"] = slot_materials_[s].label_id;
    slots.push_back(material);
  }
  json["variant"] = {{"index", variant},
                     {"of", plan.variants[object].size()},
                     {"combination", config_.combination == VariantCombination::Cartesian ? "cartesian" : "zip"},
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

  // One fixed rig lights every frame alike: its lamps are recorded here, as before lighting setups
  // existed, so that such datasets resume unchanged. Otherwise each frame's lighting is in
  // transforms.json.
  const std::optional<double> exposure = shared_exposure_stops();
  if (exposure) {
    const matgeom::LightRig& rig = *built_.rig;
    ordered_json lamps = ordered_json::array();
    for (const matgeom::RigLight& lamp : rig.lights)
      lamps.push_back({{"kind", lamp.kind == matgeom::RigLightKind::Area ? "area" : "spot"},
                       {"light_to_world", matrix_json(lamp.light_to_world)},
                       {"size", {lamp.size_x, lamp.size_y}},
                       {"spot_angle", lamp.spot_angle},
                       {"spot_blend", lamp.spot_blend},
                       {"power_w", lamp.power},
                       {"color", vector_json(lamp.color)}});
    json["lights"] = {{"rig", "paper"},
                      {"illuminance_lux", rig.illuminance_lux},
                      {"power_scale", rig.power_scale},
                      {"bounds", {{"center", vector_json(built_.bounds.center)}, {"radius", built_.bounds.radius}}},
                      {"lamps", lamps}};
  } else {
    const char* rules[] = {"per_view", "per_variant", "every_setup"};
    ordered_json setups = ordered_json::array();
    for (const LightingSetup& setup : config_.lighting.setups) setups.push_back(setup.name);
    json["lights"] = {{"setups", setups},
                      {"assign", rules[static_cast<int>(config_.lighting.assignment)]},
                      {"bounds", {{"center", vector_json(built_.bounds.center)}, {"radius", built_.bounds.radius}}},
                      {"each_frame", "transforms.json: frames[].lighting, as a scene file's lights and background"}};
  }

  const RenderConfig& r = config_.render;
  const matrender::RenderSettings& rs = r.settings;
  ordered_json seeds = ordered_json::object();
  for (size_t view = 0; view < plan.views; ++view)
    seeds[view_stem(plan, view)] = frame_seed(config_.seed, {object, variant, view});
  json["render"] = {{"renderer", "matpredict libmatrender (Principled BSDF path tracer, Cycles 3.4 conventions)"},
                    {"samples", rs.samples_per_pixel},
                    {"noise_threshold", rs.noise_threshold},
                    {"min_samples", rs.min_samples},
                    {"fewest_samples", fewest_samples()},
                    {"denoise", rs.denoise},
                    {"max_bounces", rs.max_bounces},
                    {"max_diffuse_bounces", rs.max_diffuse_bounces},
                    {"max_glossy_bounces", rs.max_glossy_bounces},
                    {"max_transmission_bounces", rs.max_transmission_bounces},
                    {"exposure_stops", exposure ? ordered_json(*exposure) : ordered_json("per frame (transforms.json)")},
                    {"exposure_rule", r.exposure_stops ? "configured"
                                                       : "grey card: a Lambertian card at the grid's centre facing the "
                                                         "camera shows half its albedo, for its illuminance under the "
                                                         "frame's lighting averaged over the grid's views "
                                                         "(log2(683 pi / lux) - 1)"},
                    {"transparent_background", !any_background_visible(config_.lighting)},
                    {"ambient_occlusion",
                     {{"distance_m", rs.ambient_occlusion_distance},
                      {"standard_error_at_most", rs.ambient_occlusion_error},
                      {"rule", "each pixel traces occlusion rays from its hits until the standard error estimated from "
                               "its own trials, sqrt(p (1 - p) / n) with p = (escaped + 1) / (n + 2), is at most the "
                               "bound; stratified directions make the true error smaller"}}},
                    {"frame_seeds", seeds}};
  // Recorded only where there are surroundings, so datasets made before they existed resume unchanged.
  if (room_) {
    ordered_json materials = ordered_json::object();
    const int resolution = config_.render.material_resolution;
    const auto material = [&](const MaterialCandidate& candidate) {
      return ordered_json{{"name", candidate.name}, {"scene", candidate_scene_json(candidate, resolution)}};
    };
    materials[matgeom::kRoomFloorPart] = material(*surroundings_.floor);
    if (surroundings_.walls) materials[matgeom::kRoomWallsPart] = material(*surroundings_.walls);
    if (room_->ceiling) materials[matgeom::kRoomCeilingPart] = material(*surroundings_.walls);
    json["surroundings"] = {{"kind", surroundings_kind_name(object_.surroundings.kind)},
                            {"room", ordered_json::parse(room_scene_json(*room_))},
                            {"materials", materials},
                            {"drawn", "per variant, from the configuration's seed and the object's and variant's indices"}};
    if (!distractor_slots_.empty()) {
      const DistractorsConfig& distractors = object_.surroundings.distractors;
      ordered_json distractor_slots = ordered_json::array();
      for (size_t k = 0; k < distractor_slots_.size(); ++k) {
        ordered_json object_json;
        if (const auto* builtin = std::get_if<matrender::BuiltinObject>(&distractor_slots_[k].object))
          object_json = {{"builtin", builtin->name}, {"seed", builtin->seed}};
        else
          object_json = {{"mesh", std::get<matrender::MeshFile>(distractor_slots_[k].object).path}};
        distractor_slots.push_back({{"object", object_json},
                         {"scale", distractor_slots_[k].scale},
                         {"material", material(distractor_materials_[k])}});
      }
      json["surroundings"]["distractors"] = {
          {"slots", distractor_slots},
          {"visible_fraction", distractors.visible_fraction},
          {"tries", distractors.tries},
          {"each_frame", "transforms.json: frames[].surroundings: each distractor's slot and transform (from its mesh "
                         "as made to its place, rows), the draws taken and the target's visible fraction"}};
    }
  } else if (object_.surroundings.kind == SurroundingsKind::Scan) {
    const ScanConfig& scan = object_.surroundings.scan;
    json["surroundings"] = {
        {"kind", surroundings_kind_name(SurroundingsKind::Scan)},
        {"scan", {{"mesh", std::filesystem::path(std::get<matrender::MeshFile>(object_.source).path).filename().string()},
                  {"target", scan.target}}},
        {"materials", "the scan's own: its vertex colours, or the materials of its file"},
        {"visible_fraction", scan.visible_fraction},
        {"each_frame", "transforms.json: frames[].surroundings: the fraction of the target's pixels (of those it shows "
                       "without the rest of the scan) the rest of the scan leaves visible"}};
  }
  json["configuration"] = config_.canonical_yaml;
  // Where its relative paths lead, when that is not beside the dataset (where a reader looks
  // first): recorded only then, so that a dataset copied with its configuration resumes unchanged.
  const std::filesystem::path beside = std::filesystem::absolute(config_.output).lexically_normal().parent_path();
  if (!config_.folder.empty() && beside != std::filesystem::path(config_.folder))
    json["configuration_folder"] = config_.folder;
  return json.dump();
}

}  // namespace matdataset
