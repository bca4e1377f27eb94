#include "matdataset/maker/lighting_setups.h"

#include <algorithm>
#include <map>

#include <fmt/format.h>

#include "matbase/file/input_file.h"
#include "matrender/blackbody.h"
#include "matrender/builtin_environments.h"
#include "matrender/lamp.h"
#include "matrender/sky.h"

namespace matdataset {
namespace {

namespace fs = std::filesystem;
using matbase::DocumentNode;

// The widest ranges the keys take: far beyond any indoor scene, short of what single precision or
// the lamps' own definitions refuse.
constexpr double kMaxPower = 1e9;         // W; also W/m^2 and lux
constexpr double kMaxDistance = 1000.0;   // in bounding radii
constexpr double kMaxLampsPerGroup = 64;  // a frame's lamps of one group
constexpr double kMaxWeight = 1e6;

// The extensions of a folder's images that an environment list takes.
const std::vector<std::string> kEnvironmentExtensions = {".exr", ".hdr"};

DrawnColor read_color(const DocumentNode& node) {
  DrawnColor color;
  if (node.is_mapping()) {
    node.expect_keys({"blackbody"});
    color.kelvin = read_drawn_number(node.required("blackbody"), matrender::kMinBlackbodyKelvin, matrender::kMaxBlackbodyKelvin,
                              false);
    return color;
  }
  const std::vector<DocumentNode> rgb = node.items(3, "[r, g, b] or {blackbody: kelvin or [min, max]}");
  color.rgb = glm::dvec3(rgb[0].number_in(0.0, 1e6), rgb[1].number_in(0.0, 1e6), rgb[2].number_in(0.0, 1e6));
  return color;
}

// The images an environment's `images` names: built-in names, files, and folders (their .exr and
// .hdr files, sorted), each checked to be there.
std::vector<std::string> read_environment_images(const DocumentNode& node, const fs::path& base) {
  std::vector<DocumentNode> items;
  if (node.is_list()) items = node.items("a list of images, folders or built-in names");
  else items.push_back(node);
  std::vector<std::string> images;
  for (const DocumentNode& item : items) {
    const std::string spelled = item.text();
    if (matrender::is_builtin_environment(spelled)) {
      try {
        matrender::builtin_environment_path(spelled);
      } catch (const std::exception& e) {
        item.fail(e.what());
      }
      images.push_back(spelled);
      continue;
    }
    const fs::path path = (fs::path(spelled).is_absolute() ? fs::path(spelled) : base / spelled).lexically_normal();
    if (fs::is_directory(path)) {
      std::vector<std::string> found;
      for (const fs::directory_entry& entry : fs::directory_iterator(path)) {
        std::string extension = entry.path().extension().string();
        std::transform(extension.begin(), extension.end(), extension.begin(),
                       [](char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); });
        if (entry.is_regular_file() &&
            std::find(kEnvironmentExtensions.begin(), kEnvironmentExtensions.end(), extension) !=
                kEnvironmentExtensions.end())
          found.push_back(entry.path().string());
      }
      if (found.empty()) item.fail("the folder " + path.string() + " holds no .exr or .hdr image");
      std::sort(found.begin(), found.end());
      images.insert(images.end(), found.begin(), found.end());
      continue;
    }
    try {
      matbase::require_input_file(path.string());
    } catch (const std::exception& e) {
      item.fail(std::string(e.what()) + fmt::format(" (a relative path is looked up in {}; the built-in names are {})",
                                                    base.string(), fmt::join(matrender::builtin_environment_names(), ", ")));
    }
    images.push_back(path.string());
  }
  if (images.empty()) node.fail("no images: name at least one");
  return images;
}

EnvironmentSetup read_environment(const DocumentNode& node, const fs::path& base) {
  node.expect_keys({"images", "strength", "rotation_deg", "visible"});
  EnvironmentSetup environment;
  environment.images = read_environment_images(node.required("images"), base);
  if (const auto n = node.find("strength")) environment.strength = read_drawn_number(*n, 0.0, kMaxPower, true, true);
  if (const auto n = node.find("rotation_deg")) environment.rotation_deg = read_drawn_number(*n, -360.0, 720.0, false);
  if (const auto n = node.find("visible")) environment.visible = n->boolean();
  return environment;
}

RigSetup read_rig(const DocumentNode& node) {
  node.expect_keys({"illuminance_lux", "powers"});
  RigSetup rig;
  const std::optional<DocumentNode> lux = node.find("illuminance_lux"), powers = node.find("powers");
  if (lux && powers) powers->fail("give the rig an illuminance_lux or the formula's powers (powers: paper), not both");
  if (lux) rig.illuminance_lux = read_drawn_number(*lux, 0.0, kMaxPower, true, true);
  if (powers) {
    powers->choice({"paper"});
    rig.illuminance_lux.reset();
  }
  return rig;
}

// The keys each kind of lamp takes beyond the placement and colour.
const std::map<LampKind, std::vector<const char*>> kLampKeys = {
    {LampKind::Sun, {"strength", "angle_deg"}},
    {LampKind::Spot, {"power_w", "cone_deg", "blend"}},
    {LampKind::Point, {"power_w"}},
    {LampKind::Area, {"power_w", "size"}}};

LampGroup read_lamp_group(const DocumentNode& node) {
  LampGroup group;
  constexpr LampKind kKinds[] = {LampKind::Sun, LampKind::Spot, LampKind::Point, LampKind::Area};
  group.kind = kKinds[node.required("type").choice({"sun", "spot", "point", "area"})];
  std::vector<const char*> keys = {"type", "count", "distance", "elevation_deg", "azimuth_deg", "at", "color"};
  for (const char* key : kLampKeys.at(group.kind)) keys.push_back(key);
  node.expect_keys(keys);
  const bool sun = group.kind == LampKind::Sun;
  if (const auto n = node.find("at")) {
    for (const char* placement : {"count", "distance", "elevation_deg", "azimuth_deg"})
      if (node.has(placement))
        node.required(placement).fail("a group placed `at` given points takes no " + std::string(placement));
    for (const DocumentNode& point : n->items("a list of points [x, y, z]")) {
      const std::vector<DocumentNode> xyz = point.items(3, "[x, y, z] in bounding radii from the object's centre");
      const glm::dvec3 p(xyz[0].number_in(-kMaxDistance, kMaxDistance), xyz[1].number_in(-kMaxDistance, kMaxDistance),
                         xyz[2].number_in(-kMaxDistance, kMaxDistance));
      if (!(glm::length(p) > 1.0))
        point.fail(fmt::format("a lamp at {:.4g} bounding radii from the object's centre is inside its bounding sphere; "
                               "place it beyond 1",
                               glm::length(p)));
      group.at.push_back(p);
    }
    if (group.at.empty()) n->fail("an empty list: give at least one point");
  }
  if (const auto n = node.find("count")) group.count = read_drawn_number(*n, 0.0, kMaxLampsPerGroup, false);
  if (group.count.low != std::floor(group.count.low) || group.count.high != std::floor(group.count.high))
    node.required("count").fail("a whole number or a range of whole numbers");
  if (const auto n = node.find("distance")) {
    if (sun) n->fail("a sun has no distance, only a direction (its elevation and azimuth)");
    group.distance = read_drawn_number(*n, 1.0, kMaxDistance, false, true);
  }
  if (const auto n = node.find("elevation_deg")) group.elevation_deg = read_drawn_number(*n, -90.0, 90.0, false);
  if (const auto n = node.find("azimuth_deg")) group.azimuth_deg = read_drawn_number(*n, -360.0, 720.0, false);
  if (const auto n = node.find("power_w")) group.power_w = read_drawn_number(*n, 0.0, kMaxPower, true, true);
  if (const auto n = node.find("strength")) group.strength = read_drawn_number(*n, 0.0, kMaxPower, true, true);
  if (const auto n = node.find("angle_deg"))
    group.angle_deg = read_drawn_number(*n, 0.0, glm::degrees(matrender::kMaxSunAngle), false);
  if (const auto n = node.find("cone_deg")) group.cone_deg = read_drawn_number(*n, 0.0, 180.0, false, true);
  if (const auto n = node.find("blend")) group.blend = read_drawn_number(*n, 0.0, 1.0, false);
  if (const auto n = node.find("size")) group.size = read_drawn_number(*n, 0.0, kMaxDistance, false, true);
  if (const auto n = node.find("color")) group.color = read_color(*n);
  return group;
}

// The scene file's sky keys (matrender::sky_settings, each in its range) as values or ranges.
SkySetup read_sky(const DocumentNode& node) {
  std::vector<const char*> keys = {"sun_disc", "strength", "visible"};
  for (const matrender::SkySetting& setting : matrender::sky_settings()) keys.push_back(setting.key);
  node.expect_keys(keys);
  SkySetup sky;
  for (const matrender::SkySetting& setting : matrender::sky_settings())
    if (const auto n = node.find(setting.key))
      sky.settings[setting.key] = read_drawn_number(*n, setting.low, setting.high, false, setting.low_open);
  if (const auto n = node.find("sun_disc")) sky.sun_disc = n->boolean();
  if (const auto n = node.find("strength")) sky.strength = read_drawn_number(*n, 0.0, kMaxPower, true, true);
  if (const auto n = node.find("visible")) sky.visible = n->boolean();
  return sky;
}

CeilingSetup read_ceiling(const DocumentNode& node) {
  CeilingSetup ceiling;
  if (node.is_word("room")) return ceiling;
  node.expect_keys({"illuminance_lux", "height", "offset", "size", "color"});
  if (const auto n = node.find("illuminance_lux")) ceiling.illuminance_lux = read_drawn_number(*n, 0.0, kMaxPower, true, true);
  if (const auto n = node.find("height")) ceiling.height = read_drawn_number(*n, 1.0, kMaxDistance, false, true);
  if (const auto n = node.find("offset")) ceiling.offset = read_drawn_number(*n, 0.0, kMaxDistance, false);
  if (const auto n = node.find("size")) ceiling.size = read_drawn_number(*n, 0.0, kMaxDistance, false, true);
  if (const auto n = node.find("color")) ceiling.color = read_color(*n);
  return ceiling;
}

LightingSetup read_setup(const DocumentNode& node, const fs::path& base) {
  node.expect_keys({"name", "weight", "rig", "environment", "sky", "ceiling", "lamps"});
  LightingSetup setup;
  if (const auto n = node.find("rig")) setup.rig = n->is_word("paper") ? RigSetup{} : read_rig(*n);
  if (const auto n = node.find("environment")) setup.environment = read_environment(*n, base);
  if (const auto n = node.find("sky")) {
    if (setup.environment) n->fail("a setup has one world: an environment or a sky, not both");
    setup.sky = read_sky(*n);
  }
  if (const auto n = node.find("ceiling")) setup.ceiling = read_ceiling(*n);
  if (const auto n = node.find("lamps"))
    for (const DocumentNode& group : n->items("a list of lamp groups")) setup.lamps.push_back(read_lamp_group(group));
  // A scene file's lights are the rig or a list of lamps (docs/scene_format.md), as a frame records them.
  for (const char* lamps : {"ceiling", "lamps"})
    if (setup.rig && node.has(lamps))
      node.required(lamps).fail(
          "the rig lights alone (or with an environment or a sky): put these lamps in a setup of their own");
  if (!setup.rig && !setup.environment && !setup.sky && !setup.ceiling && setup.lamps.empty())
    node.fail("a setup with no light: give it a rig, an environment, a sky, a ceiling lamp or lamps");
  std::vector<std::string> parts;
  if (setup.rig) parts.push_back("rig");
  if (setup.environment) parts.push_back("environment");
  if (setup.sky) parts.push_back("sky");
  if (setup.ceiling) parts.push_back("ceiling");
  for (const LampGroup& group : setup.lamps)
    if (std::find(parts.begin(), parts.end(), lamp_kind_name(group.kind)) == parts.end())
      parts.push_back(lamp_kind_name(group.kind));
  setup.name = fmt::format("{}", fmt::join(parts, "+"));
  if (const auto n = node.find("name")) {
    setup.name = n->text();
    if (setup.name.empty()) n->fail("an empty name");
  }
  if (const auto n = node.find("weight")) setup.weight = n->number_in(0.0, kMaxWeight, true);
  return setup;
}

}  // namespace

bool lights_every_frame_alike(const LightingConfig& lighting) {
  if (lighting.setups.size() != 1) return false;
  const LightingSetup& setup = lighting.setups.front();
  return setup.rig && !setup.environment && !setup.sky && setup.lamps.empty() &&
         (!setup.rig->illuminance_lux || setup.rig->illuminance_lux->low == setup.rig->illuminance_lux->high);
}

bool any_background_visible(const LightingConfig& lighting) {
  for (const LightingSetup& setup : lighting.setups)
    if ((setup.environment && setup.environment->visible) || (setup.sky && setup.sky->visible)) return true;
  return false;
}

const char* lamp_kind_name(LampKind kind) {
  constexpr const char* kNames[] = {"sun", "spot", "point", "area"};
  return kNames[static_cast<int>(kind)];
}

LightingConfig read_lighting(const DocumentNode& lights, const fs::path& base) {
  lights.expect_keys({"rig", "illuminance_lux", "setups", "assign"});
  LightingConfig config;
  if (const auto setups = lights.find("setups")) {
    for (const char* short_form : {"rig", "illuminance_lux"})
      if (lights.has(short_form))
        lights.required(short_form).fail("give the rig as one of the `setups` ({rig: {illuminance_lux: ...}}), not beside them");
    config.setups.clear();
    std::map<std::string, size_t> seen;
    for (const DocumentNode& node : setups->items("a list of lighting setups")) {
      LightingSetup setup = read_setup(node, base);
      // Unnamed setups of the same parts are numbered; a name given twice is refused.
      if (const size_t times = seen[setup.name]++; times > 0) {
        if (node.has("name")) node.required("name").fail("two setups are named \"" + setup.name + "\"");
        setup.name = fmt::format("{}_{}", setup.name, times + 1);
      }
      config.setups.push_back(std::move(setup));
    }
    if (config.setups.empty()) setups->fail("the list is empty: give at least one setup");
  } else {
    if (const auto rig = lights.find("rig")) rig->choice({"paper"});
    if (const auto lux = lights.find("illuminance_lux"))
      config.setups.front().rig->illuminance_lux = DrawnNumber::value(lux->number_in(0.0, 1e9, true), true);
  }
  if (const auto assign = lights.find("assign")) {
    constexpr LightingAssignment kRules[] = {LightingAssignment::PerView, LightingAssignment::PerVariant,
                                             LightingAssignment::EverySetup};
    config.assignment = kRules[assign->choice({"per_view", "per_variant", "every_setup"})];
  }
  return config;
}

}  // namespace matdataset
