#include "scene_description/lamp_reading.h"

#include <stdexcept>
#include <utility>
#include <variant>

#include <glm/glm.hpp>

#include "matgeom/camera_grid.h"
#include "matrender/blackbody.h"
#include "scene_description/scene_file_values.h"

namespace matrender {
namespace {

using matbase::DocumentNode;

// What a described lamp brings to a scene file: its "type" and the reading of its keys.
template <class Description>
struct SceneFileLamp;

// A lamp's "color": [r, g, b], each at least 0, or {"blackbody": kelvin}, the colour of Blender's
// Blackbody node at that temperature.
glm::dvec3 read_lamp_color(const DocumentNode& node) {
  if (!node.is_mapping()) return read_color(node);
  node.expect_keys({"blackbody"});
  return blackbody_color(node.required("blackbody").number_in(kMinBlackbodyKelvin, kMaxBlackbodyKelvin));
}

// What the scene file gives every lamp at a point, after its own keys: "power" (required),
// "color" and "radius".
template <class LampAtPoint>
void read_lamp_at_point_emission(const DocumentNode& node, LampAtPoint& lamp) {
  lamp.power = node.required("power").non_negative();
  if (auto color = node.find("color")) lamp.color = read_lamp_color(*color);
  if (auto radius = node.find("radius")) lamp.radius = radius->non_negative();
}

// "area": position, look_at, up, size, power, color, visible_to_camera.
template <>
struct SceneFileLamp<RectLamp> {
  static constexpr const char* kType = "area";
  static RectLamp read(const DocumentNode& node) {
    node.expect_keys({"type", "position", "look_at", "up", "size", "power", "color", "visible_to_camera"});
    RectLamp lamp;
    const glm::dvec3 position = read_vec3(node.required("position"));
    const glm::dvec3 target = read_target(node, position);
    const glm::dvec3 up = node.has("up") ? read_direction(node.required("up")) : glm::dvec3(0.0, 0.0, 1.0);
    // A lamp emits down its -Z like a camera looks down its -Z, so the same frame aims both.
    try {
      lamp.light_to_world = matgeom::look_at_camera_to_world(position, target, up);
    } catch (const std::invalid_argument& e) {
      node.required("look_at").fail(e.what());
    }
    const DocumentNode size = node.required("size");
    if (size.is_number()) {
      lamp.size_x = lamp.size_y = size.positive();
    } else {
      const std::vector<DocumentNode> sides = size.items(2, "a positive number or [size_x, size_y]");
      lamp.size_x = sides[0].positive();
      lamp.size_y = sides[1].positive();
    }
    lamp.power = node.required("power").non_negative();
    if (auto color = node.find("color")) lamp.color = read_lamp_color(*color);
    if (auto visible = node.find("visible_to_camera")) lamp.visible_to_camera = visible->boolean();
    return lamp;
  }
};

// "point": position, power, color, radius.
template <>
struct SceneFileLamp<PointLamp> {
  static constexpr const char* kType = "point";
  static PointLamp read(const DocumentNode& node) {
    node.expect_keys({"type", "position", "power", "color", "radius"});
    PointLamp lamp;
    lamp.position = read_vec3(node.required("position"));
    read_lamp_at_point_emission(node, lamp);
    return lamp;
  }
};

// "spot": position, look_at, spot_angle_deg, blend, power, color, radius.
template <>
struct SceneFileLamp<SpotLamp> {
  static constexpr const char* kType = "spot";
  static SpotLamp read(const DocumentNode& node) {
    node.expect_keys({"type", "position", "look_at", "spot_angle_deg", "blend", "power", "color", "radius"});
    SpotLamp lamp;
    lamp.position = read_vec3(node.required("position"));
    lamp.direction = glm::normalize(read_target(node, lamp.position) - lamp.position);
    if (auto angle = node.find("spot_angle_deg")) lamp.spot_angle = glm::radians(angle->number_in(0.0, 180.0, true));
    if (auto blend = node.find("blend")) lamp.blend = blend->unit_interval();
    read_lamp_at_point_emission(node, lamp);
    return lamp;
  }
};

// "sun": position, look_at (only the direction between them matters), strength, color, angle_deg.
template <>
struct SceneFileLamp<SunLamp> {
  static constexpr const char* kType = "sun";
  static SunLamp read(const DocumentNode& node) {
    node.expect_keys({"type", "position", "look_at", "strength", "color", "angle_deg"});
    SunLamp lamp;
    const glm::dvec3 position = read_vec3(node.required("position"));
    lamp.direction = glm::normalize(read_target(node, position) - position);
    lamp.strength = node.required("strength").non_negative();
    if (auto color = node.find("color")) lamp.color = read_lamp_color(*color);
    if (auto angle = node.find("angle_deg")) lamp.angle = glm::radians(angle->number_in(0.0, glm::degrees(kMaxSunAngle)));
    return lamp;
  }
};

template <size_t... kKinds>
std::vector<std::string> lamp_types(std::index_sequence<kKinds...>) {
  return {SceneFileLamp<std::variant_alternative_t<kKinds, Lamp>>::kType...};
}

template <size_t kKind = 0>
Lamp read_lamp_of_kind(size_t kind, const DocumentNode& node) {
  if constexpr (kKind + 1 < std::variant_size_v<Lamp>)
    if (kind != kKind) return read_lamp_of_kind<kKind + 1>(kind, node);
  return SceneFileLamp<std::variant_alternative_t<kKind, Lamp>>::read(node);
}

}  // namespace

const std::vector<std::string>& scene_file_lamp_types() {
  static const std::vector<std::string> types = lamp_types(std::make_index_sequence<std::variant_size_v<Lamp>>());
  return types;
}

Lamp read_lamp(const DocumentNode& node) {
  return read_lamp_of_kind(node.required("type").choice(scene_file_lamp_types()), node);
}

}  // namespace matrender
