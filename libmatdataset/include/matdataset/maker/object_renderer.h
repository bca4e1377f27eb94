#pragma once
// One object of the dataset, built once and rendered in all its variants from all its views:
// its scene (one BVH) holds every candidate material, a variant only changes which material
// each part uses, and the grid's cameras are placed by the radius rule around the object.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "matdataset/format/dataset_writer.h"
#include "matdataset/maker/dataset_config.h"
#include "matdataset/maker/dataset_plan.h"
#include "matdataset/maker/distractors.h"
#include "matdataset/maker/frame_lighting.h"
#include "matdataset/maker/object_framing.h"
#include "matdataset/maker/scene_meter.h"
#include "matgeom/bounding_sphere.h"
#include "matgeom/object_asset.h"
#include "matrender/render.h"
#include "matrender/scene_builder.h"
#include "matrender/scene_file.h"

namespace matdataset {

// The AOVs a dataset frame needs: coverage, normals, depth, label, ambient occlusion, the
// sample count, base colour, roughness and metallic.
uint32_t dataset_aovs();

class ObjectRenderer {
 public:
  // Loads the object and builds its scene; throws matbase::InputError naming the configuration's key
  // when the object cannot be loaded or a part is in no slot.
  ObjectRenderer(const DatasetConfig& config, size_t object);

  // Puts the object in the materials of variant `index` of the plan (loading those not used
  // before); throws matbase::InputError for a material that cannot be loaded or has no material
  // class, and matbase::Cancelled soon after `cancel` (when given) is set.
  void select_variant(size_t index, const MaterialVariant& variant, const std::atomic<bool>* cancel = nullptr);

  // The materials of the selected variant, slot by slot.
  const std::vector<SlotMaterial>& slot_materials() const { return slot_materials_; }

  // Whether the object stands in surroundings (its frames then have region maps).
  bool has_surroundings() const { return object_.surroundings.present(); }

  // A view's distractors in the selected variant: the draw kept (the first whose target shows at
  // least the configured visible fraction, else the one that showed it most), the draws it took
  // and the fraction. Drawn the first time it is asked for. In a scan, the fraction of the target
  // the scan's other parts leave visible, in one draw.
  struct ViewSurroundings {
    std::vector<DistractorPlacement> placements;
    int tries = 1;
    double visible_fraction = 1.0;
    bool satisfied = true;
  };
  const ViewSurroundings& view_surroundings(size_t view);

  // The selected variant as an asset a glTF writer takes (for another renderer to get the same
  // object): the object's surface in world space, each part in its slot's material with the maps
  // repeated per UV unit as this renderer repeats them. The materials are loaded (generated)
  // again.
  matgeom::ObjectAsset variant_asset() const;

  // The scene the views are rendered in: its lamps and background are those of the view lit last.
  const matrender::Scene& scene() const { return built_.scene; }

  // A view's lighting in the selected variant (frame_lighting.h), drawn the first time it is asked
  // for, and the exposure its images take: the configuration's, or the grey-card rule's under it.
  struct ViewLighting {
    FrameLighting drawn;
    matrender::SceneLighting scene;
    double exposure_stops = 0.0;
    // With surroundings: the card measured in the scene received no light (a closed room under a
    // sky, lamps outside the walls), so the frame is black.
    bool unlit = false;
  };
  const ViewLighting& view_lighting(size_t view);
  // What transforms.json records of a view's lighting: the setup's name, the scene file's
  // "lights" and "background", whether camera rays see it, and the exposure.
  std::string view_lighting_json(size_t view);
  // The scene material each part of the object renders with in the selected variant.
  const std::vector<uint32_t>& part_materials() const {
    return built_.scene.part_materials(built_.object_meshes.front());
  }

  matrender::Camera view_camera(size_t view) const;
  // The view's camera and its lighting's record.
  FramePose view_pose(size_t view, const std::string& stem);
  CameraIntrinsics intrinsics() const;

  // The fewest camera samples a pixel takes (adaptive sampling may stop pixels early).
  int fewest_samples() const;

  // Renders one view with `seed` under its lighting, its figures into *stats when given; false
  // when cancelled (the maps are then incomplete).
  bool render(size_t view, uint32_t seed, int threads, const std::atomic<bool>* cancel, FrameMaps& maps,
              matrender::RenderStats* stats = nullptr);

  // Everything needed to render a frame of the selected variant again, as a JSON object.
  std::string provenance_json(const DatasetPlan& plan, size_t variant);

 private:
  const DatasetConfig& config_;
  size_t object_index_;
  const ObjectConfig& object_;
  matrender::BuiltScene built_;
  matgeom::CameraGridSpec grid_;
  size_t grid_views_ = 0;
  size_t variant_index_ = 0;
  MaterialVariant variant_;  // the selected one
  std::map<size_t, ViewLighting> lighting_;  // the selected variant's views lit so far
  matrender::EnvironmentImages environment_images_;
  // The exposure of every frame when one fixed rig lights them all alike (what metadata.json
  // records then), none otherwise.
  std::optional<double> shared_exposure_stops();
  // Puts the view's lighting in the scene; the view that is there already stays.
  void light_view(size_t view);
  size_t lit_view_ = SIZE_MAX;
  std::vector<SlotMaterial> slot_materials_;
  std::vector<std::vector<uint32_t>> slot_parts_;  // the parts of each slot
  // The room made to measure the object stands in (the scene's object 1; a scan's other parts are
  // object 1 instead), and the selected variant's draw of its materials.
  std::optional<matgeom::RoomSpec> room_;
  DrawnSurroundings surroundings_;
  void put_surroundings_in_materials();
  // The distractors (the scene's objects from kFirstDistractor on): each slot's object, its
  // footprint as built, the selected variant's materials, and each view's draw.
  static constexpr size_t kFirstDistractor = 2;
  static constexpr int kVisibilityWidth = 128;
  std::vector<DistractorSlot> distractor_slots_;
  std::vector<glm::dmat4> distractor_sizings_;  // each slot's mesh as built to its size (distractor_sizing)
  std::vector<double> distractor_radii_;         // its footprint's radius then
  Footprint target_footprint_;
  double target_size_ = 0.0;  // the target's bounding sphere radius, which distractors' scales are of
  double distractor_reach_ = 0.0;
  std::vector<MaterialCandidate> distractor_materials_;
  std::map<size_t, ViewSurroundings> view_surroundings_;  // the selected variant's
  std::map<size_t, size_t> target_pixels_alone_;           // by view, whatever the variant
  // The target's pixels in a small object-id pass of the view with the surroundings as they are.
  size_t target_pixels(size_t view);
  // A view of the target in its scan: the fraction of its pixels the scan's other parts leave.
  ViewSurroundings scan_view(size_t view);
  // What every build of the scene is followed by: the distractors sized, the meter's card hidden.
  void settle_built_scene();
  // The illuminance of the card measured in the scene (scene_meter.h) under the lighting there now,
  // whose scene-file text is `lighting`: measured once per lighting of the selected variant (a
  // fixed rig lights every view alike; the room's materials change with the variant).
  double measured_card_lux(const std::string& lighting);
  std::map<std::string, double> card_lux_;
  // Each slot's sizing, from its surface as built (which is left at that size for its materials).
  void size_distractors();
  void place_distractors_in_scene(const std::vector<DistractorPlacement>& placements);
  std::string view_surroundings_json(size_t view);
};

}  // namespace matdataset
