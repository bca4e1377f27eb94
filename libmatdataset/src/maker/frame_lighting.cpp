#include "matdataset/maker/frame_lighting.h"

#include <cmath>
#include <filesystem>

#include "matbase/pi.h"
#include "matdataset/maker/drawn_number.h"
#include "matdataset/maker/seed_stream.h"
#include "matrender/light_meter.h"
#include "matrender/scene_file.h"
#include "matrender/sky.h"

namespace matdataset {
namespace {

using nlohmann::ordered_json;
constexpr double kDegree = matbase::kPi / 180.0;
// Keeps the lighting's draws apart from the samples' seeds made from the same configuration seed.
constexpr uint64_t kLightingSalt = 0x6c69676874696e67ull;  // "lighting"

// The frame's stream of lighting draws: one per view, or one per variant that all its views
// share (its view index left out).
SeedStream lighting_draws(const LightingConfig& lighting, uint64_t seed, const FrameRef& frame) {
  uint64_t h = splitmix64(seed ^ kLightingSalt);
  h = splitmix64(h ^ frame.object);
  h = splitmix64(h ^ frame.variant);
  if (lighting.assignment != LightingAssignment::PerVariant) h = splitmix64(h ^ frame.view);
  return SeedStream(h);
}

LightingChoice choose(const LightingConfig& lighting, const FrameRef& frame, size_t grid_views, SeedStream& draws) {
  LightingChoice choice;
  const double u = draws.uniform();
  if (lighting.assignment == LightingAssignment::EverySetup) {
    choice.setup = frame.view / grid_views;
  } else {
    double total = 0.0;
    for (const LightingSetup& setup : lighting.setups) total += setup.weight;
    double below = 0.0;
    choice.setup = lighting.setups.size() - 1;
    for (size_t k = 0; k < lighting.setups.size(); ++k) {
      below += lighting.setups[k].weight;
      if (u * total < below) {
        choice.setup = k;
        break;
      }
    }
  }
  const double v = draws.uniform();
  if (const auto& environment = lighting.setups[choice.setup].environment) {
    const size_t count = environment->images.size();
    choice.image = std::min(static_cast<size_t>(v * static_cast<double>(count)), count - 1);
  }
  return choice;
}

ordered_json vec3_json(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

ordered_json color_json(const DrawnColor& color, SeedStream& draws) {
  const double kelvin = draw(color.kelvin, draws);
  if (color.rgb) return vec3_json(*color.rgb);
  return {{"blackbody", kelvin}};
}

// The unit direction at `elevation` above the horizon and `azimuth` from +X toward +Y.
glm::dvec3 shell_direction(double elevation_deg, double azimuth_deg) {
  const double elevation = elevation_deg * kDegree, azimuth = azimuth_deg * kDegree;
  return {std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth), std::sin(elevation)};
}

void add_group(const LampGroup& group, const matgeom::Sphere& bounds, SeedStream& draws, ordered_json& lights) {
  const int count = group.at.empty() ? draw_count(group.count, draws) : static_cast<int>(group.at.size());
  const glm::dvec3 centre = bounds.center;
  for (int k = 0; k < count; ++k) {
    const double distance = draw(group.distance, draws);
    const glm::dvec3 direction = shell_direction(draw(group.elevation_deg, draws), draw(group.azimuth_deg, draws));
    const glm::dvec3 offset = group.at.empty() ? distance * direction : group.at[static_cast<size_t>(k)];
    const glm::dvec3 position = centre + bounds.radius * offset;
    ordered_json lamp = {{"type", lamp_kind_name(group.kind)}, {"position", vec3_json(position)}};
    if (group.kind != LampKind::Point) lamp["look_at"] = vec3_json(centre);
    const double power = draw(group.power_w, draws), strength = draw(group.strength, draws);
    const double angle = draw(group.angle_deg, draws), cone = draw(group.cone_deg, draws);
    const double blend = draw(group.blend, draws), size = draw(group.size, draws);
    switch (group.kind) {
      case LampKind::Sun:
        lamp["strength"] = strength;
        lamp["angle_deg"] = angle;
        break;
      case LampKind::Spot:
        lamp["spot_angle_deg"] = cone;
        lamp["blend"] = blend;
        lamp["power"] = power;
        break;
      case LampKind::Point:
        lamp["power"] = power;
        break;
      case LampKind::Area: {
        // Its size_x edge horizontal; straight above or below, along +X.
        const glm::dvec3 toward = glm::normalize(centre - position);
        lamp["up"] = std::abs(toward.z) > 0.999 ? vec3_json({0.0, 1.0, 0.0}) : vec3_json({0.0, 0.0, 1.0});
        lamp["size"] = size * bounds.radius;
        lamp["power"] = power;
        break;
      }
    }
    lamp["color"] = color_json(group.color, draws);
    lights.push_back(std::move(lamp));
  }
}

// The ceiling lamp (lighting_setups.h, CeilingSetup): where it hangs, how large it is and its
// colour drawn, then its power set for the drawn illuminance at the centre.
ordered_json ceiling_lamp(const CeilingSetup& ceiling, const matgeom::Sphere& bounds, std::optional<double> ceiling_z,
                          SeedStream& draws) {
  const double lux = draw(ceiling.illuminance_lux, draws), height = draw(ceiling.height, draws);
  const double offset = draw(ceiling.offset, draws), bearing = draw(DrawnNumber{0.0, 360.0, false}, draws) * kDegree;
  const double size = draw(ceiling.size, draws) * bounds.radius;
  const glm::dvec3 centre = bounds.center;
  glm::dvec3 position = centre + bounds.radius * glm::dvec3(offset * std::cos(bearing), offset * std::sin(bearing), height);
  // Just under the ceiling (a hundredth of the drop to the centre), and never below the centre.
  if (ceiling_z && position.z > *ceiling_z - 0.01 * (*ceiling_z - centre.z))
    position.z = std::max(*ceiling_z - 0.01 * (*ceiling_z - centre.z), centre.z + 0.01 * bounds.radius);
  ordered_json lamp = {{"type", "area"},
                       {"position", vec3_json(position)},
                       {"look_at", vec3_json(position - glm::dvec3(0.0, 0.0, 1.0))},
                       {"up", vec3_json({0.0, 1.0, 0.0})},
                       {"size", size},
                       {"power", 1.0},
                       {"color", color_json(ceiling.color, draws)}};
  // The lux a watt gives, read as a scene file reads the lamp (its colour's luminance included).
  const matrender::SceneLighting unit =
      matrender::read_lighting_text(ordered_json{{"lights", {lamp}}}.dump(), "the ceiling lamp", ".");
  const double per_watt =
      matrender::lamp_card_illuminance_lux(std::get<std::vector<matrender::Lamp>>(unit.lights).front(), centre,
                                           glm::dvec3(0.0, 0.0, 1.0));
  lamp["power"] = per_watt > 0.0 ? lux / per_watt : 0.0;
  return lamp;
}

}  // namespace

LightingChoice choose_lighting(const LightingConfig& lighting, uint64_t seed, const FrameRef& frame,
                               size_t grid_views) {
  SeedStream draws = lighting_draws(lighting, seed, frame);
  return choose(lighting, frame, grid_views, draws);
}

std::string lighting_key(const LightingConfig& lighting, const LightingChoice& choice) {
  const LightingSetup& setup = lighting.setups[choice.setup];
  if (!choice.image) return setup.name;
  // A built-in name, or the file's path: images of one stem in two folders stay apart.
  return "environment:" + setup.environment->images[*choice.image];
}

FrameLighting draw_frame_lighting(const LightingConfig& lighting, uint64_t seed, const FrameRef& frame,
                                  size_t grid_views, const matgeom::Sphere& bounds, std::optional<double> ceiling_z) {
  SeedStream draws = lighting_draws(lighting, seed, frame);
  const LightingChoice choice = choose(lighting, frame, grid_views, draws);
  const LightingSetup& setup = lighting.setups[choice.setup];
  FrameLighting result;
  result.setup = setup.name;
  result.lights = ordered_json::array();
  if (setup.rig) {
    ordered_json rig = ordered_json::object();
    if (setup.rig->illuminance_lux) rig["target_illuminance_lux"] = draw(*setup.rig->illuminance_lux, draws);
    result.lights = {{"rig", rig}};
  }
  result.background = {0.0, 0.0, 0.0};
  if (setup.environment) {
    const EnvironmentSetup& environment = *setup.environment;
    const double strength = draw(environment.strength, draws);
    const double rotation = draw(environment.rotation_deg, draws);
    result.background = {{"environment", environment.images[*choice.image]},
                         {"strength", strength},
                         {"rotation_z_deg", rotation}};
    result.background_visible = environment.visible;
  }
  if (setup.sky) {
    const SkySetup& sky = *setup.sky;
    ordered_json settings = ordered_json::object();
    for (const matrender::SkySetting& setting : matrender::sky_settings())
      if (const auto given = sky.settings.find(setting.key); given != sky.settings.end())
        settings[setting.key] = draw(given->second, draws);
    settings["sun_disc"] = sky.sun_disc;
    result.background = {{"sky", settings}, {"strength", draw(sky.strength, draws)}};
    result.background_visible = sky.visible;
  }
  if (setup.ceiling) result.lights.push_back(ceiling_lamp(*setup.ceiling, bounds, ceiling_z, draws));
  for (const LampGroup& group : setup.lamps) add_group(group, bounds, draws, result.lights);
  return result;
}

ordered_json scene_lighting_json(const FrameLighting& lighting) {
  return {{"lights", lighting.lights}, {"background", lighting.background}};
}

}  // namespace matdataset
