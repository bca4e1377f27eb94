#include "matdataset/maker/dataset_config.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "matbase/document/yaml_checks.h"
#include "matbase/file/input_file.h"
#include "matbase/image/image_writing.h"
#include "matbase/number_text.h"
#include "matdataset/format/dataset_folders.h"
#include "matdataset/format/dataset_writer.h"
#include "matgeom/builtin/builtin_objects.h"

namespace matdataset {
namespace {

namespace fs = std::filesystem;

constexpr int kMaxResolution = 16384;
// The sample count map stores each pixel's samples in 16 bits.
constexpr int kMaxSamples = kMaxSampleCount;
constexpr int kMaxGridSide = 4096;
constexpr int kMaxBounces = 1024;

const char* const kDefaultYaml = R"(# make_dataset's embedded default: 6 objects x 3 materials x 8 views, about a minute on 2 cores.
output: dataset_out
seed: 0
variants:
  strategy: cartesian
  max_variants: null
  seed: 42
materials:
  all: [wood/raw:1, metal/brushed:2, fabric/twill:3]
objects:
  - {name: vase, builtin: vase, seed: 0}
  - {name: chair, builtin: chair, seed: 0}
  - {name: table, builtin: table, seed: 0}
  - {name: stool, builtin: stool, seed: 0}
  - {name: mug, builtin: mug, seed: 0}
  - {name: pillow, builtin: pillow, seed: 0}
camera:
  grid: [2, 4]
  phi_deg: [0, 90]
  theta_deg: [-90, 90]
  fov_deg: 39.597752
  radius: {rule: fit, fill: 0.9}
render:
  resolution: [128, 128]
  samples: 32
  exposure: auto
  bounces: {max: 12, diffuse: 4, glossy: 4, transmission: 12}
  ambient_occlusion: {error: 0.02, distance: 1.0}
  material_resolution: 256
lights:
  rig: paper
  illuminance_lux: 1000
splits:
  seed: 42
  ratios: [0.7, 0.15, 0.15]
  paper_train_fraction: 0.8
paper_texture_layout: false
)";

// Where values come from, for errors: the file, or the option that overrode a key.
class Sources {
 public:
  explicit Sources(std::string file) : file_(std::move(file)) {}
  void overridden(const std::string& key, const std::string& option) { options_[key] = option; }
  bool is_overridden(const std::string& key) const { return options_.count(key) > 0; }
  // "config.yaml: render.samples" or "--spp (render.samples)": the option that set the key or a
  // key around it, else the option that set a key inside it (`--set render.resolution.1=64` on a
  // file whose resolution is one side makes `render.resolution` wrong), else the file.
  std::string at(const std::string& key) const {
    if (key.empty()) return file_;
    for (std::string prefix = key;; prefix = prefix.substr(0, prefix.rfind('.'))) {
      if (const auto it = options_.find(prefix); it != options_.end()) return it->second + " (" + key + ")";
      if (prefix.find('.') == std::string::npos) break;
    }
    for (const auto& [overridden_key, option] : options_)
      if (overridden_key.rfind(key + ".", 0) == 0) return option + " (" + key + ")";
    return file_ + ": " + key;
  }
  const std::string& file() const { return file_; }

 private:
  std::string file_;
  std::map<std::string, std::string> options_;
};

// A YAML node with its dotted key, whose getters check the value and name the key in errors.
class Value {
 public:
  Value(YAML::Node node, std::string key, const Sources& sources)
      : node_(std::move(node)), key_(std::move(key)), sources_(sources) {}

  // Whether the key is given. A key written with no value (`samples:`, `--set render.samples=`)
  // is refused rather than read as absent, which would silently give it its default.
  bool present() const {
    if (is_null()) fail("no value given: write one, or leave the key out for its default");
    return node_.IsDefined();
  }
  // Whether the key is given as null (`~`, `null` or nothing), which only `max_variants` accepts.
  bool is_null() const { return node_.IsDefined() && node_.IsNull(); }
  const std::string& key() const { return key_; }
  [[noreturn]] void fail(const std::string& message) const { throw matbase::InputError(sources_.at(key_) + ": " + message); }

  Value child(const std::string& name) const {
    return Value(node_.IsMap() ? node_[name] : YAML::Node(YAML::NodeType::Undefined),
                 key_.empty() ? name : key_ + "." + name, sources_);
  }
  // The map's keys must all be among `known`.
  void check_keys(const std::set<std::string>& known) const {
    if (!node_.IsMap()) fail("expected a mapping of keys");
    for (const auto& item : node_) {
      const std::string name = item.first.as<std::string>();
      if (!known.count(name)) {
        std::string list;
        for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
        child(name).fail("unknown key (known here: " + list + ")");
      }
    }
  }
  std::vector<Value> items() const {
    if (!node_.IsSequence()) fail("expected a list");
    std::vector<Value> values;
    for (size_t k = 0; k < node_.size(); ++k) values.emplace_back(node_[k], key_ + "." + std::to_string(k), sources_);
    return values;
  }
  std::vector<std::pair<std::string, Value>> entries() const {
    if (!node_.IsMap()) fail("expected a mapping of keys");
    std::vector<std::pair<std::string, Value>> values;
    for (const auto& item : node_) {
      const std::string name = item.first.as<std::string>();
      values.emplace_back(name, child(name));
    }
    return values;
  }
  std::string text() const {
    if (!node_.IsScalar()) fail("expected a single value");
    return node_.Scalar();
  }
  bool is_text() const { return node_.IsScalar(); }
  int64_t whole(int64_t low, int64_t high) const {
    const std::string t = text();
    if (const auto problem = matbase::whole_number_problem(t, low, high)) fail(*problem);
    return *matbase::whole_number(t);
  }
  uint64_t seed() const {
    const std::string t = text();
    if (const auto problem = matbase::seed_problem(t)) fail(*problem);
    return *matbase::unsigned_whole_number(t);
  }
  double number(double low, double high, bool low_open = false) const {
    const std::string t = text();
    if (const auto problem = matbase::number_problem(t, low, high, low_open)) fail(*problem);
    return *matbase::finite_number(t);
  }
  bool boolean() const {
    const std::string t = text();
    if (t == "true") return true;
    if (t == "false") return false;
    fail("expected true or false, got " + t);
  }
  // A list of exactly `n` numbers in the range.
  std::vector<double> numbers(size_t n, double low, double high) const {
    const std::vector<Value> list = items();
    if (list.size() != n) fail(fmt::format("expected a list of {} numbers", n));
    std::vector<double> values;
    for (const Value& v : list) values.push_back(v.number(low, high));
    return values;
  }

 private:
  YAML::Node node_;
  std::string key_;
  const Sources& sources_;
};

// Sets the node at dotted `key` of `root` to `value`, making maps on the way ("a.b.c"; a number
// indexes a list). A single value on the way is not replaced by a map: the key is misspelled.
void apply_override(YAML::Node root, const Override& o) {
  if (o.value.find_first_not_of(" \t") == std::string::npos)
    throw matbase::InputError(o.option + ": no value given: write one (null where the key takes none)");
  YAML::Node value;
  try {
    value = YAML::Load(o.value);
  } catch (const YAML::Exception& e) {
    throw matbase::InputError(o.option + ": \"" + o.value + "\" is not a YAML value: " + e.msg);
  }
  if (const std::optional<std::string> problem = matbase::repeated_key_problem(value))
    throw matbase::InputError(o.option + ": " + *problem);
  std::vector<std::string> parts;
  for (size_t start = 0;;) {
    const size_t dot = o.key.find('.', start);
    parts.push_back(o.key.substr(start, dot - start));
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  std::vector<YAML::Node> path = {root};
  for (size_t k = 0; k + 1 < parts.size(); ++k) {
    YAML::Node& node = path.back();
    const std::optional<int64_t> index = matbase::whole_number(parts[k]);
    if (node.IsSequence()) {
      if (!index || *index < 0 || static_cast<size_t>(*index) >= node.size())
        throw matbase::InputError(o.option + ": " + o.key + ": \"" + parts[k] + "\" is not an index of that list");
      path.push_back(node[static_cast<size_t>(*index)]);
    } else if (node.IsMap()) {
      if (!node[parts[k]].IsDefined() || node[parts[k]].IsNull()) node[parts[k]] = YAML::Node(YAML::NodeType::Map);
      path.push_back(node[parts[k]]);
    } else {
      throw matbase::InputError(o.option + ": " + o.key + ": " + parts[k - 1] + " is a single value, with no key \"" +
                       parts[k] + "\" inside");
    }
  }
  YAML::Node& parent = path.back();
  const std::optional<int64_t> index = matbase::whole_number(parts.back());
  if (parent.IsSequence()) {
    if (!index || *index < 0 || static_cast<size_t>(*index) >= parent.size())
      throw matbase::InputError(o.option + ": " + o.key + ": \"" + parts.back() + "\" is not an index of that list");
    parent[static_cast<size_t>(*index)] = value;
  } else if (parent.IsMap()) {
    parent[parts.back()] = value;
  } else {
    throw matbase::InputError(o.option + ": " + o.key + ": " + parts[parts.size() - 2] + " is a single value, with no key \"" +
                     parts.back() + "\" inside");
  }
}

MaterialCandidate read_candidate(const Value& v, const fs::path& base) {
  MaterialCandidate candidate;
  if (v.is_text()) {
    candidate.spelled = v.text();
    try {
      const matmaterial::LibraryMaterialSpec spec = matmaterial::parse_library_material(candidate.spelled);
      candidate.source = spec;
      const matmaterial::LibraryStyleInfo& style = matmaterial::resolved_style(spec);
      candidate.name = fmt::format("{}_{}_{}", matmaterial::material_class(spec.material_class).name, style.name, spec.seed);
    } catch (const std::invalid_argument& e) {
      v.fail(e.what());
    }
    return candidate;
  }
  v.check_keys({"matsynth"});
  const std::string folder = v.child("matsynth").text();
  const fs::path path = fs::path(folder).is_absolute() ? fs::path(folder) : base / folder;
  if (!fs::is_directory(path)) v.child("matsynth").fail("no folder at " + path.string());
  candidate.spelled = folder;
  candidate.source = path.lexically_normal().string();
  candidate.name = path.lexically_normal().filename().string();
  if (candidate.name.empty()) candidate.name = path.lexically_normal().parent_path().filename().string();
  return candidate;
}

// The slots of an object: its part lists (`slots`) and candidates (`materials`, or the
// configuration's top-level `materials`).
std::vector<SlotConfig> read_slots(const Value& object, const Value& defaults, const fs::path& base) {
  const Value materials = object.child("materials").present() ? object.child("materials") : defaults;
  if (!materials.present()) object.fail("no materials: give `materials` here or at the top level");
  std::map<std::string, std::vector<std::string>> parts;
  if (object.child("slots").present())
    for (const auto& [slot, list] : object.child("slots").entries()) {
      for (const Value& part : list.items()) parts[slot].push_back(part.text());
      if (parts[slot].empty())
        list.fail("an empty part list; a slot that takes every part not listed is left out of `slots`");
    }
  std::vector<SlotConfig> slots;
  for (const auto& [slot, list] : materials.entries()) {
    SlotConfig config;
    config.key = slot;
    config.parts = parts[slot];
    for (const Value& item : list.items()) {
      MaterialCandidate candidate = read_candidate(item, base);
      for (const MaterialCandidate& earlier : config.candidates)
        if (earlier.name == candidate.name)
          item.fail("\"" + earlier.spelled + "\" and \"" + candidate.spelled + "\" are both \"" + candidate.name +
                    "\" in the dataset; list each material of a slot once");
      config.candidates.push_back(std::move(candidate));
    }
    if (config.candidates.empty()) list.fail("a slot needs at least one candidate material");
    slots.push_back(std::move(config));
  }
  for (const auto& [slot, list] : parts) {
    bool found = false;
    for (const SlotConfig& s : slots) found = found || s.key == slot;
    if (!found) object.child("slots").child(slot).fail("the slot has no candidate materials in `materials`");
  }
  size_t catch_all = 0;
  for (const SlotConfig& s : slots) catch_all += s.parts.empty() ? 1 : 0;
  if (catch_all > 1) object.child("slots").fail("at most one slot may list no parts (it takes every part not listed)");
  return slots;
}

// Object names by their lower-case spelling, for folders that differ only in case.
using FolderNames = std::map<std::string, std::string>;

std::string folded_case(std::string name) {
  std::transform(name.begin(), name.end(), name.begin(),
                 [](char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); });
  return name;
}

ObjectConfig read_object(const Value& v, const Value& defaults, const fs::path& base, FolderNames& names) {
  v.check_keys({"name", "builtin", "mesh", "seed", "uv_pass", "slots", "materials"});
  ObjectConfig object;
  const bool builtin = v.child("builtin").present(), mesh = v.child("mesh").present();
  if (builtin == mesh) v.fail("give exactly one of `builtin` (a built-in object's name) and `mesh` (a file)");
  if (builtin) {
    const std::string name = v.child("builtin").text();
    const std::vector<std::string> known = matgeom::builtin_object_names();
    if (std::find(known.begin(), known.end(), name) == known.end()) {
      std::string list;
      for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
      v.child("builtin").fail("no built-in object \"" + name + "\" (built-in: " + list + ")");
    }
    const uint32_t seed =
        v.child("seed").present() ? static_cast<uint32_t>(v.child("seed").whole(0, 4294967295LL)) : 0u;
    object.source = matrender::BuiltinObject{name, seed};
    object.name = name;
  } else {
    if (v.child("seed").present()) v.child("seed").fail("only a built-in object has a seed");
    const std::string file = v.child("mesh").text();
    const fs::path path = fs::path(file).is_absolute() ? fs::path(file) : base / file;
    try {
      matbase::require_input_file(path.string());
    } catch (const std::exception& e) {
      v.child("mesh").fail(e.what());
    }
    object.source = matrender::MeshFile{path.lexically_normal().string()};
    object.name = path.stem().string();
  }
  const bool named = v.child("name").present();
  if (named) object.name = v.child("name").text();
  const Value name_source = named ? v.child("name") : v.child(builtin ? "builtin" : "mesh");
  if (const std::optional<std::string> problem = object_folder_problem(object.name))
    name_source.fail("\"" + object.name + "\" cannot name the object's folder: " + *problem +
                     (named ? "" : "; give the object a `name`"));
  if (const auto [earlier, inserted] = names.emplace(folded_case(object.name), object.name); !inserted)
    name_source.fail(earlier->second == object.name
                         ? "two objects are named \"" + object.name + "\"; give one a `name`"
                         : "\"" + object.name + "\" and \"" + earlier->second +
                               "\" differ only in case, so they would be one folder on Windows and macOS");
  if (v.child("uv_pass").present()) {
    const std::string mode = v.child("uv_pass").text();
    if (mode == "never") object.uv_pass = matrender::UvPassMode::Never;
    else if (mode == "when_missing") object.uv_pass = matrender::UvPassMode::WhenMissing;
    else if (mode == "always") object.uv_pass = matrender::UvPassMode::Always;
    else v.child("uv_pass").fail("expected never, when_missing or always, got " + mode);
  }
  object.slots = read_slots(v, defaults, base);
  return object;
}

void read_camera(const Value& v, CameraConfig& camera) {
  v.check_keys({"grid", "phi_deg", "theta_deg", "fov_deg", "radius"});
  if (v.child("grid").present()) {
    const std::vector<Value> grid = v.child("grid").items();
    if (grid.size() != 2) v.child("grid").fail("expected [N_phi, N_theta]");
    camera.n_phi = static_cast<int>(grid[0].whole(1, kMaxGridSide));
    camera.n_theta = static_cast<int>(grid[1].whole(1, kMaxGridSide));
  }
  if (v.child("phi_deg").present()) {
    const std::vector<double> phi = v.child("phi_deg").numbers(2, 0.0, 180.0);
    if (phi[0] > phi[1]) v.child("phi_deg").fail("expected [min, max] with min <= max");
    camera.phi_min_deg = phi[0], camera.phi_max_deg = phi[1];
  }
  if (v.child("theta_deg").present()) {
    const std::vector<double> theta = v.child("theta_deg").numbers(2, -360.0, 360.0);
    if (theta[0] > theta[1]) v.child("theta_deg").fail("expected [min, max] with min <= max");
    camera.theta_min_deg = theta[0], camera.theta_max_deg = theta[1];
  }
  if (v.child("fov_deg").present()) camera.vertical_fov_deg = v.child("fov_deg").number(0.0, 179.0, true);
  const Value radius = v.child("radius");
  if (!radius.present()) return;
  radius.check_keys({"rule", "fill", "metres", "factor", "min_metres"});
  const std::string rule = radius.child("rule").text();
  if (rule == "fit") {
    camera.radius_rule = RadiusRule::Fit;
    if (radius.child("fill").present()) camera.fill = radius.child("fill").number(0.0, 1.0, true);
  } else if (rule == "fixed") {
    camera.radius_rule = RadiusRule::Fixed;
    camera.radius_m = radius.child("metres").number(0.0, 65536.0, true);
  } else if (rule == "bounding_box") {
    camera.radius_rule = RadiusRule::BoundingBox;
    if (radius.child("factor").present()) camera.box_factor = radius.child("factor").number(0.0, 1000.0, true);
    if (radius.child("min_metres").present()) camera.min_radius_m = radius.child("min_metres").number(0.0, 65536.0);
  } else {
    radius.child("rule").fail("expected fit, fixed or bounding_box, got " + rule);
  }
}

void read_render(const Value& v, RenderConfig& render) {
  v.check_keys({"resolution", "samples", "noise_threshold", "min_samples", "denoise", "exposure", "bounces",
                "ambient_occlusion", "material_resolution"});
  if (const Value r = v.child("resolution"); r.present()) {
    if (r.is_text()) {
      render.width = render.height = static_cast<int>(r.whole(1, kMaxResolution));
    } else {
      const std::vector<Value> sides = r.items();
      if (sides.size() != 2) r.fail("expected a side or [width, height]");
      render.width = static_cast<int>(sides[0].whole(1, kMaxResolution));
      render.height = static_cast<int>(sides[1].whole(1, kMaxResolution));
    }
  }
  if (v.child("samples").present()) render.samples = static_cast<int>(v.child("samples").whole(1, kMaxSamples));
  if (v.child("noise_threshold").present()) render.noise_threshold = v.child("noise_threshold").number(0.0, 1.0);
  if (v.child("denoise").present()) render.denoise = v.child("denoise").boolean();
  if (v.child("min_samples").present())
    render.min_samples = static_cast<int>(v.child("min_samples").whole(0, kMaxSamples));
  if (const Value exposure = v.child("exposure"); exposure.present()) {
    const std::string text = exposure.text();
    if (text == "auto")
      render.exposure_stops = std::nullopt;
    else if (matbase::number_problem(text, -matbase::kMaxExposureStops, matbase::kMaxExposureStops, false))
      exposure.fail(fmt::format("expected auto or a number of stops from {} to {}, got {}", -matbase::kMaxExposureStops,
                                matbase::kMaxExposureStops, text));
    else
      render.exposure_stops = *matbase::finite_number(text);
  }
  if (const Value b = v.child("bounces"); b.present()) {
    b.check_keys({"max", "diffuse", "glossy", "transmission"});
    if (b.child("max").present()) render.max_bounces = static_cast<int>(b.child("max").whole(0, kMaxBounces));
    if (b.child("diffuse").present()) render.max_diffuse_bounces = static_cast<int>(b.child("diffuse").whole(0, kMaxBounces));
    if (b.child("glossy").present()) render.max_glossy_bounces = static_cast<int>(b.child("glossy").whole(0, kMaxBounces));
    if (b.child("transmission").present())
      render.max_transmission_bounces = static_cast<int>(b.child("transmission").whole(0, kMaxBounces));
  }
  if (const Value ao = v.child("ambient_occlusion"); ao.present()) {
    ao.check_keys({"error", "distance"});
    if (ao.child("error").present()) render.ambient_occlusion_error = ao.child("error").number(1e-4, 0.5);
    if (ao.child("distance").present())
      render.ambient_occlusion_distance_m = ao.child("distance").number(0.0, 65536.0, true);
  }
  if (v.child("material_resolution").present())
    render.material_resolution = static_cast<int>(
        v.child("material_resolution").whole(matmaterial::kMinLibraryResolution, matmaterial::kMaxLibraryResolution));
}

void read_splits(const Value& v, DatasetConfig& config) {
  v.check_keys({"seed", "ratios", "paper_train_fraction"});
  if (v.child("seed").present()) config.split_seed = v.child("seed").seed();
  if (v.child("ratios").present()) {
    const std::vector<double> r = v.child("ratios").numbers(3, 0.0, 1.0);
    if (std::abs(r[0] + r[1] + r[2] - 1.0) > 1e-6) v.child("ratios").fail("the three ratios must sum to 1");
    config.split_ratios = {r[0], r[1], r[2]};
  }
  if (v.child("paper_train_fraction").present())
    config.paper_train_fraction = v.child("paper_train_fraction").number(0.0, 1.0);
}

DatasetConfig read_config(const Value& root, const fs::path& base) {
  root.check_keys({"output", "seed", "variants", "materials", "objects", "camera", "render", "lights", "splits",
                   "paper_texture_layout"});
  DatasetConfig config;
  if (const Value output = root.child("output"); output.present()) {
    config.output = output.text();
    if (config.output.empty()) output.fail("an empty folder name; name the dataset's folder");
  }
  if (root.child("seed").present()) config.seed = root.child("seed").seed();
  if (const Value variants = root.child("variants"); variants.present()) {
    variants.check_keys({"strategy", "max_variants", "seed"});
    if (variants.child("strategy").present()) {
      const std::string strategy = variants.child("strategy").text();
      if (strategy == "cartesian") config.combination = VariantCombination::Cartesian;
      else if (strategy == "zip") config.combination = VariantCombination::Zip;
      else variants.child("strategy").fail("expected cartesian or zip, got " + strategy);
    }
    if (const Value cap = variants.child("max_variants"); !cap.is_null() && cap.present())
      config.max_variants = static_cast<uint64_t>(cap.whole(1, 1000000));
    if (variants.child("seed").present()) config.variant_seed = variants.child("seed").seed();
  }
  FolderNames names;
  const Value objects = root.child("objects");
  if (!objects.present()) root.fail("no objects: the configuration needs an `objects` list");
  for (const Value& object : objects.items()) config.objects.push_back(read_object(object, root.child("materials"), base, names));
  if (config.objects.empty()) objects.fail("the list is empty");
  if (root.child("camera").present()) read_camera(root.child("camera"), config.camera);
  if (root.child("render").present()) read_render(root.child("render"), config.render);
  if (const Value lights = root.child("lights"); lights.present()) {
    lights.check_keys({"rig", "illuminance_lux"});
    if (lights.child("rig").present() && lights.child("rig").text() != "paper")
      lights.child("rig").fail("the only rig is the paper's (paper)");
    if (lights.child("illuminance_lux").present())
      config.illuminance_lux = lights.child("illuminance_lux").number(0.0, 1e9, true);
  }
  if (root.child("splits").present()) read_splits(root.child("splits"), config);
  if (root.child("paper_texture_layout").present()) config.paper_texture_layout = root.child("paper_texture_layout").boolean();
  return config;
}

}  // namespace

const std::string& embedded_default_yaml() {
  static const std::string text = kDefaultYaml;
  return text;
}

namespace {

DatasetConfig read_root(YAML::Node root, const std::string& source, const fs::path& base,
                        const std::vector<Override>& overrides) {
  if (!root.IsMap()) throw matbase::InputError(source + ": expected a mapping of keys at the top");
  if (const std::optional<std::string> problem = matbase::repeated_key_problem(root))
    throw matbase::InputError(source + ": " + *problem);
  Sources sources(source);
  for (const Override& o : overrides) {
    apply_override(root, o);
    sources.overridden(o.key, o.option);
  }
  DatasetConfig config = read_config(Value(root, "", sources), base);
  config.source = source;
  // Like every path of the file, its output is relative to it; one given on the command line is
  // relative to the current folder, as a shell's paths are.
  if (!sources.is_overridden("output") && fs::path(config.output).is_relative() && base != fs::current_path())
    config.output = (base / config.output).lexically_normal().string();
  // Where the dataset goes is not part of what is rendered: a copy made elsewhere, or shards
  // written to other folders, record the same configuration.
  YAML::Node recorded = YAML::Clone(root);
  recorded.remove("output");
  YAML::Emitter out;
  out << recorded;
  config.canonical_yaml = std::string(out.c_str()) + "\n";
  return config;
}

matbase::InputError yaml_error(const std::string& source, const YAML::Exception& e) {
  return matbase::InputError(source + ": not valid YAML or JSON: " + e.msg + fmt::format(" (line {})", e.mark.line + 1));
}

}  // namespace

DatasetConfig load_config(const std::string& file, const std::vector<Override>& overrides) {
  if (file.empty()) return parse_config(embedded_default_yaml(), "the embedded default", fs::current_path(), overrides);
  try {
    matbase::require_input_file(file);
  } catch (const std::exception& e) {
    throw matbase::InputError(e.what());
  }
  YAML::Node root;
  try {
    root = YAML::LoadFile(file);
  } catch (const YAML::Exception& e) {
    throw yaml_error(file, e);
  }
  return read_root(root, file, fs::absolute(file).parent_path(), overrides);
}

DatasetConfig parse_config(const std::string& yaml, const std::string& source, const fs::path& base,
                           const std::vector<Override>& overrides) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml);
  } catch (const YAML::Exception& e) {
    throw yaml_error(source, e);
  }
  return read_root(root, source, base, overrides);
}

}  // namespace matdataset
