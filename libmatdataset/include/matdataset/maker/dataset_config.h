#pragma once
// make_dataset's configuration (docs/make_dataset.md, "Configuration"): what to render (objects,
// their material slots and candidates, how variants combine), how (resolution, samples,
// bounces, ambient occlusion's error), from where (the paper's camera grid and a radius rule)
// and under what light (lighting setups, lighting_setups.h). It comes from the embedded default
// or a YAML/JSON file, then command-line overrides (--set KEY=VALUE and the named options, which
// set the same keys); every value is checked, and an error names the file or option and the key.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "matdataset/format/dataset_splits.h"
#include "matdataset/format/dataset_writer.h"
#include "matdataset/maker/lighting_setups.h"
#include "matdataset/maker/material_candidate.h"
#include "matdataset/maker/material_variants.h"
#include "matdataset/maker/render_keys.h"
#include "matdataset/maker/surroundings.h"
#include "matmaterial/library/material_library.h"
#include "matrender/paper_setup.h"
#include "matrender/scene_description.h"

namespace matdataset {

using matbase::InputError;

struct SlotConfig {
  std::string key;                 // "all", "mat1", ...: the variant_map key
  std::vector<std::string> parts;  // the object's part names in this slot; empty: every part
  std::vector<MaterialCandidate> candidates;
};

struct ObjectConfig {
  std::string name;  // the dataset's object folder
  std::variant<matrender::MeshFile, matrender::BuiltinObject> source;
  matrender::UvPassMode uv_pass = matrender::UvPassMode::WhenMissing;
  // The paper's s: the UV pass's texel density times this, so the materials' maps repeat s
  // times as often. Only where the pass runs (dataset_checks.h). Several (its Figure 3 study)
  // render every material variant once per scale: the variant's last index picks it
  // (material_variants.h).
  std::vector<double> uv_scales = {1.0};
  double uv_scale_of(const MaterialVariant& variant) const {
    return uv_scales.size() > 1 ? uv_scales.at(variant.back()) : uv_scales.front();
  }
  std::vector<SlotConfig> slots;
  // The object's own `surroundings`, else the configuration's.
  SurroundingsConfig surroundings;
};

// How far the cameras are from the object's centroid.
enum class RadiusRule {
  Fit,          // the object's bounding sphere fills `fill` of the vertical field of view
  Fixed,        // radius_m
  BoundingBox,  // the repository's: max(min_radius_m, box_factor x the largest side of the box)
};

struct CameraConfig {
  int n_phi = 16, n_theta = 32;  // the paper's grid
  double phi_min_deg = 0.0, phi_max_deg = 90.0;
  double theta_min_deg = -90.0, theta_max_deg = 90.0;
  double vertical_fov_deg = 39.597752;  // Blender's 50 mm lens on its 36 mm sensor
  RadiusRule radius_rule = RadiusRule::Fit;
  double fill = 0.9;
  double radius_m = 1.0;
  double box_factor = 2.2, min_radius_m = 1.0;
};

struct RenderConfig {
  int width = 512, height = 512;
  // The render settings the configuration sets (render_keys.h); the maker sets the others per
  // frame: the seed, the threads, the transparent background, the AOVs.
  matrender::RenderSettings settings = dataset_render_defaults();
  // Applied to the images; none: the grey-card rule (matrender::grey_card_exposure) under each
  // frame's own lighting.
  std::optional<double> exposure_stops;
  int material_resolution = 1024;  // texels per side of the library's maps
  bool hdr_images = false;  // write each image in linear floats too (images_hdr/)
};

struct DatasetConfig {
  std::string source;  // the file it came from, or "the embedded default"
  // The absolute folder of the file it came from, which its relative paths (meshes, material
  // folders) are relative to; empty for the embedded default and text given in memory.
  std::string folder;
  std::string output = "dataset_out";
  uint64_t seed = 0;  // of every frame's samples (each frame's own seed follows from it)
  VariantCombination combination = VariantCombination::Cartesian;
  std::optional<uint64_t> max_variants;
  uint64_t variant_seed = 42;  // of the uniform cap
  std::vector<ObjectConfig> objects;
  CameraConfig camera;
  RenderConfig render;
  LightingConfig lighting;  // the paper's rig at 1000 lx unless set
  uint64_t split_seed = 42;
  SplitRatios split_ratios;
  double paper_train_fraction = 0.8;
  bool paper_texture_layout = false;
  // The configuration after overrides, as YAML: recorded in every variant's metadata.
  std::string canonical_yaml;
};

// One override: a dotted key ("render.samples", "camera.radius.fill") and its value as YAML
// ("128", "[wood, metal:2]"), and the option that gave it (named in errors).
struct Override {
  std::string key;
  std::string value;
  std::string option;
  // A named option's value quotes its scalars only to keep each one whole ("--output 'a: b'"):
  // each is then read as its key needs, as an unquoted YAML scalar is, and not only as text.
  bool untyped_scalars = false;
};

// The maps object `object`'s frames have beyond every frame's.
FrameContents frame_contents(const DatasetConfig& config, size_t object);

// The embedded default: six built-in objects in three library materials, 2 x 4 views at 128 px.
const std::string& embedded_default_yaml();

// Reads `file` (YAML or JSON; empty: the embedded default), applies the overrides in order and
// checks every value. Throws matbase::InputError naming the file or option and the key.
DatasetConfig load_config(const std::string& file, const std::vector<Override>& overrides);
// The same from YAML text; `source` names it in errors and relative paths resolve against `base`.
DatasetConfig parse_config(const std::string& yaml, const std::string& source, const std::filesystem::path& base,
                           const std::vector<Override>& overrides);

}  // namespace matdataset
