#include "matdataset/maker/dataset_config.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>
#include <tuple>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "matbase/document/document_node.h"
#include "matbase/document/yaml_document.h"
#include "matbase/file/input_file.h"
#include "matbase/image/image_writing.h"
#include "matbase/number_text.h"
#include "matdataset/format/dataset_folders.h"
#include "matdataset/format/dataset_writer.h"
#include "matgeom/builtin/builtin_objects.h"
#include "matrender/scene_file.h"
#include "matrender/denoiser.h"

namespace matdataset {
namespace {

namespace fs = std::filesystem;

constexpr int kMaxResolution = 16384;
constexpr int kMaxGridSide = 4096;

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

using matbase::DocumentNode;

// A list of exactly `count` numbers in [low, high].
std::vector<double> read_numbers(const DocumentNode& node, size_t count, double low, double high) {
  std::vector<double> values;
  for (const DocumentNode& item : node.items(count, fmt::format("a list of {} numbers", count)))
    values.push_back(item.number_in(low, high));
  return values;
}

// Gives every scalar of `node` the tag of an unquoted one ("?"), which the reader types by its key.
void untype_scalars(YAML::Node node) {
  if (node.IsScalar()) node.SetTag("?");
  if (node.IsSequence())
    for (size_t k = 0; k < node.size(); ++k) untype_scalars(node[k]);
  if (node.IsMap())
    for (const auto& entry : node) untype_scalars(entry.second);
}

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
  matbase::yaml_document_value(value, o.option);  // refuses a repeated key or an alias inside itself
  if (o.untyped_scalars) untype_scalars(value);
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

// The slots of an object: its part lists (`slots`) and candidates (`materials`, or the
// configuration's top-level `materials`).
std::vector<SlotConfig> read_slots(const DocumentNode& object, const std::optional<DocumentNode>& defaults,
                                   const fs::path& base) {
  const std::optional<DocumentNode> materials = object.has("materials") ? object.find("materials") : defaults;
  if (!materials) object.fail("no materials: give `materials` here or at the top level");
  std::map<std::string, std::vector<std::string>> parts;
  const std::optional<DocumentNode> slot_parts = object.find("slots");
  if (slot_parts)
    for (const auto& [slot, list] : slot_parts->members()) {
      for (const DocumentNode& part : list.items()) parts[slot].push_back(part.text());
      if (parts[slot].empty())
        list.fail("an empty part list; a slot that takes every part not listed is left out of `slots`");
    }
  std::vector<SlotConfig> slots;
  for (const auto& [slot, list] : materials->members()) {
    SlotConfig config;
    config.key = slot;
    config.parts = parts[slot];
    for (const DocumentNode& item : list.items()) {
      MaterialCandidate candidate = read_material_candidate(item, base);
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
    if (!found) slot_parts->required(slot).fail("the slot has no candidate materials in `materials`");
  }
  size_t catch_all = 0;
  for (const SlotConfig& s : slots) catch_all += s.parts.empty() ? 1 : 0;
  if (catch_all > 1) {
    const DocumentNode where = slot_parts ? *slot_parts : *materials;
    where.fail("at most one slot may list no parts (it takes every part not listed)");
  }
  return slots;
}

// Object names by their lower-case spelling, for folders that differ only in case.
using FolderNames = std::map<std::string, std::string>;

std::string folded_case(std::string name) {
  std::transform(name.begin(), name.end(), name.begin(),
                 [](char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); });
  return name;
}

ObjectConfig read_object(const DocumentNode& v, const std::optional<DocumentNode>& defaults,
                         const SurroundingsConfig& surroundings, const fs::path& base, FolderNames& names) {
  v.expect_keys({"name", "builtin", "mesh", "seed", "uv_pass", "uv_scale", "auto_smooth_deg", "slots", "materials",
                 "surroundings"});
  ObjectConfig object;
  object.surroundings = surroundings;
  if (const std::optional<DocumentNode> own = v.find("surroundings")) object.surroundings = read_surroundings(*own, base);
  const std::optional<DocumentNode> builtin = v.find("builtin"), mesh = v.find("mesh");
  if (builtin.has_value() == mesh.has_value())
    v.fail("give exactly one of `builtin` (a built-in object's name) and `mesh` (a file)");
  if (builtin && object.surroundings.kind == SurroundingsKind::Scan)
    (v.has("surroundings") ? v.required("surroundings") : *builtin)
        .fail("`kind: scan` puts the object back in the scan it came from: give the scan as the object's `mesh`, "
              "a built-in object has no scan");
  if (builtin) {
    if (const std::optional<DocumentNode> angle = v.find("auto_smooth_deg"))
      angle->fail("only a mesh file's faces can be smoothed (a built-in object has its own normals)");
    const std::vector<std::string> known = matgeom::builtin_object_names();
    const std::string name = known[builtin->choice(known)];
    const std::optional<DocumentNode> seed = v.find("seed");
    object.source = matrender::BuiltinObject{name, seed ? seed->uint32() : 0u};
    object.name = name;
  } else {
    if (const std::optional<DocumentNode> seed = v.find("seed")) seed->fail("only a built-in object has a seed");
    matrender::MeshFile mesh_file;
    const std::string file = mesh->text();
    const fs::path path = fs::path(file).is_absolute() ? fs::path(file) : base / file;
    try {
      matbase::require_input_file(path.string());
    } catch (const std::exception& e) {
      mesh->fail(e.what());
    }
    mesh_file.path = path.lexically_normal().string();
    if (const std::optional<DocumentNode> angle = v.find("auto_smooth_deg"))
      mesh_file.read_options.auto_smooth_deg = matrender::read_auto_smooth_deg(*angle);
    // A scan's object is its target parts; the others are its surroundings (object_renderer.h).
    mesh_file.only_parts = object.surroundings.scan.target;
    object.source = mesh_file;
    object.name = path.stem().string();
  }
  const std::optional<DocumentNode> name = v.find("name");
  if (name) object.name = name->text();
  const DocumentNode name_source = name ? *name : builtin ? *builtin : *mesh;
  if (const std::optional<std::string> problem = object_folder_problem(object.name))
    name_source.fail("\"" + object.name + "\" cannot name the object's folder: " + *problem +
                     (name ? "" : "; give the object a `name`"));
  if (const auto [earlier, inserted] = names.emplace(folded_case(object.name), object.name); !inserted)
    name_source.fail(earlier->second == object.name
                         ? "two objects are named \"" + object.name + "\"; give one a `name`"
                         : "\"" + object.name + "\" and \"" + earlier->second +
                               "\" differ only in case, so they would be one folder on Windows and macOS");
  if (const std::optional<DocumentNode> uv_pass = v.find("uv_pass")) {
    constexpr matrender::UvPassMode kModes[] = {matrender::UvPassMode::Never, matrender::UvPassMode::WhenMissing,
                                                matrender::UvPassMode::Always};
    object.uv_pass = kModes[uv_pass->choice({"never", "when_missing", "always"})];
  }
  if (const std::optional<DocumentNode> scale = v.find("uv_scale")) {
    object.uv_scales.clear();
    for (const DocumentNode& item : scale->is_list() ? scale->items("a scale or a list of scales")
                                                     : std::vector<DocumentNode>{*scale}) {
      const double s = item.number_in(matrender::kMinUvScale, matrender::kMaxUvScale);
      if (std::find(object.uv_scales.begin(), object.uv_scales.end(), s) != object.uv_scales.end())
        item.fail(fmt::format("{} is listed twice: each scale makes its own variants", s));
      object.uv_scales.push_back(s);
    }
    if (object.uv_scales.empty()) scale->fail("an empty list: give a scale");
    if (object.uv_pass == matrender::UvPassMode::Never)
      scale->fail("the UV pass never runs (uv_pass: never), so there is no texel density to scale");
  }
  object.slots = read_slots(v, defaults, base);
  return object;
}

// [min, max] of numbers in [low, high], with min <= max.
std::pair<double, double> read_range(const DocumentNode& node, double low, double high) {
  const std::vector<double> ends = read_numbers(node, 2, low, high);
  if (ends[0] > ends[1]) node.fail("expected [min, max] with min <= max");
  return {ends[0], ends[1]};
}

void read_camera(const DocumentNode& v, CameraConfig& camera) {
  v.expect_keys({"grid", "phi_deg", "theta_deg", "fov_deg", "radius"});
  if (const std::optional<DocumentNode> grid = v.find("grid")) {
    const std::vector<DocumentNode> sides = grid->items(2, "[N_phi, N_theta]");
    camera.n_phi = sides[0].integer_in(1, kMaxGridSide);
    camera.n_theta = sides[1].integer_in(1, kMaxGridSide);
  }
  if (const std::optional<DocumentNode> phi = v.find("phi_deg"))
    std::tie(camera.phi_min_deg, camera.phi_max_deg) = read_range(*phi, 0.0, 180.0);
  if (const std::optional<DocumentNode> theta = v.find("theta_deg"))
    std::tie(camera.theta_min_deg, camera.theta_max_deg) = read_range(*theta, -360.0, 360.0);
  if (const std::optional<DocumentNode> fov = v.find("fov_deg")) camera.vertical_fov_deg = fov->number_in(0.0, 179.0, true);
  const std::optional<DocumentNode> radius = v.find("radius");
  if (!radius) return;
  radius->expect_keys({"rule", "fill", "metres", "factor", "min_metres"});
  constexpr RadiusRule kRules[] = {RadiusRule::Fit, RadiusRule::Fixed, RadiusRule::BoundingBox};
  camera.radius_rule = kRules[radius->required("rule").choice({"fit", "fixed", "bounding_box"})];
  if (camera.radius_rule == RadiusRule::Fit) {
    if (const std::optional<DocumentNode> fill = radius->find("fill")) camera.fill = fill->number_in(0.0, 1.0, true);
  } else if (camera.radius_rule == RadiusRule::Fixed) {
    camera.radius_m = radius->required("metres").number_in(0.0, 65536.0, true);
  } else {
    if (const std::optional<DocumentNode> factor = radius->find("factor"))
      camera.box_factor = factor->number_in(0.0, 1000.0, true);
    if (const std::optional<DocumentNode> least = radius->find("min_metres"))
      camera.min_radius_m = least->number_in(0.0, 65536.0);
  }
}

void read_render(const DocumentNode& v, RenderConfig& render) {
  std::vector<std::string> keys{"resolution"};
  for (const std::string& key : dataset_render_top_keys()) keys.push_back(key);
  keys.insert(keys.end(), {"exposure", "material_resolution", "hdr_images"});
  std::vector<const char*> allowed;
  for (const std::string& key : keys) allowed.push_back(key.c_str());
  v.expect_keys(allowed);
  if (const std::optional<DocumentNode> r = v.find("resolution")) {
    if (r->is_list()) {
      const std::vector<DocumentNode> sides = r->items(2, "a side or [width, height]");
      render.width = sides[0].integer_in(1, kMaxResolution);
      render.height = sides[1].integer_in(1, kMaxResolution);
    } else {
      render.width = render.height = r->integer_in(1, kMaxResolution);
    }
  }
  read_dataset_render_keys(v, render.settings);
  if (const std::optional<std::string> problem = matrender::denoising_problem(render.settings.denoise))
    v.required("denoise").fail(*problem);
  if (const std::optional<DocumentNode> exposure = v.find("exposure")) {
    if (exposure->is_word("auto"))
      render.exposure_stops = std::nullopt;
    else
      render.exposure_stops = exposure->number_where(
          [](double stops) { return std::abs(stops) <= matbase::kMaxExposureStops; },
          fmt::format("auto or a number of stops from {} to {}", -matbase::kMaxExposureStops, matbase::kMaxExposureStops));
  }
  if (const std::optional<DocumentNode> n = v.find("material_resolution"))
    render.material_resolution = n->integer_in(matmaterial::kMinLibraryResolution, matmaterial::kMaxLibraryResolution);
  if (const std::optional<DocumentNode> n = v.find("hdr_images")) render.hdr_images = n->boolean();
}

void read_splits(const DocumentNode& v, DatasetConfig& config) {
  v.expect_keys({"seed", "ratios", "paper_train_fraction"});
  if (const std::optional<DocumentNode> n = v.find("seed")) config.split_seed = n->seed();
  if (const std::optional<DocumentNode> n = v.find("ratios")) {
    const std::vector<double> r = read_numbers(*n, 3, 0.0, 1.0);
    if (std::abs(r[0] + r[1] + r[2] - 1.0) > 1e-6) n->fail("the three ratios must sum to 1");
    config.split_ratios = {r[0], r[1], r[2]};
  }
  if (const std::optional<DocumentNode> n = v.find("paper_train_fraction")) config.paper_train_fraction = n->unit_interval();
}

DatasetConfig read_config(const DocumentNode& root, const fs::path& base) {
  root.expect_keys({"output", "seed", "variants", "materials", "objects", "camera", "render", "lights", "splits",
                    "paper_texture_layout", "surroundings"});
  DatasetConfig config;
  if (const std::optional<DocumentNode> output = root.find("output")) {
    config.output = output->text();
    if (config.output.empty()) output->fail("an empty folder name; name the dataset's folder");
  }
  if (const std::optional<DocumentNode> n = root.find("seed")) config.seed = n->seed();
  if (const std::optional<DocumentNode> variants = root.find("variants")) {
    variants->expect_keys({"strategy", "max_variants", "seed"});
    if (const std::optional<DocumentNode> n = variants->find("strategy"))
      config.combination = n->choice({"cartesian", "zip"}) == 0 ? VariantCombination::Cartesian : VariantCombination::Zip;
    // null: no cap, as the default.
    if (!variants->is_null_at("max_variants"))
      if (const std::optional<DocumentNode> n = variants->find("max_variants"))
        config.max_variants = static_cast<uint64_t>(n->whole_number(1, 1000000));
    if (const std::optional<DocumentNode> n = variants->find("seed")) config.variant_seed = n->seed();
  }
  FolderNames names;
  if (!root.has("objects")) root.fail("no objects: the configuration needs an `objects` list");
  const DocumentNode objects = root.required("objects");
  const std::optional<DocumentNode> materials = root.find("materials");
  SurroundingsConfig surroundings;
  if (const std::optional<DocumentNode> node = root.find("surroundings")) surroundings = read_surroundings(*node, base);
  for (const DocumentNode& object : objects.items())
    config.objects.push_back(read_object(object, materials, surroundings, base, names));
  if (config.objects.empty()) objects.fail("the list is empty");
  if (const std::optional<DocumentNode> camera = root.find("camera")) read_camera(*camera, config.camera);
  if (const std::optional<DocumentNode> render = root.find("render")) read_render(*render, config.render);
  if (const std::optional<DocumentNode> lights = root.find("lights")) config.lighting = read_lighting(*lights, base);
  if (const std::optional<DocumentNode> splits = root.find("splits")) read_splits(*splits, config);
  if (const std::optional<DocumentNode> n = root.find("paper_texture_layout")) config.paper_texture_layout = n->boolean();
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
  // Before the overrides, which would pick one of a repeated key's values.
  matbase::yaml_document_value(root, source);
  matbase::DocumentSource sources(source, matbase::PathStyle::DottedKeys);
  for (const Override& o : overrides) {
    apply_override(root, o);
    sources.overridden(o.key, o.option);
  }
  const matbase::DocumentValue document = matbase::yaml_document_value(root, source);
  DatasetConfig config = read_config(DocumentNode(document, sources), base);
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

FrameContents frame_contents(const DatasetConfig& config, size_t object) {
  return {config.objects.at(object).surroundings.present(), config.render.hdr_images};
}

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
  DatasetConfig config = read_root(root, file, fs::absolute(file).parent_path(), overrides);
  config.folder = fs::absolute(file).lexically_normal().parent_path().string();
  return config;
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
