#pragma once
// The paper's light rig (section "Lighting rig and source parameters"), as plain data that the
// renderer turns into its own lights. Powers are Blender watts with Cycles' conventions.
#include <optional>
#include <vector>

#include <glm/glm.hpp>

namespace matgeom {

enum class RigLightKind { Area, Spot };

struct RigLight {
  RigLightKind kind = RigLightKind::Area;
  glm::dvec3 position{0.0};
  // Columns: lamp +X (long edge of an area light), +Y, +Z (backward: the lamp emits down its -Z,
  // toward the rig centre), translation. Blender's lamp convention.
  glm::dmat4 light_to_world{1.0};
  double size_x = 0.0;      // area light: long edge (m)
  double size_y = 0.0;      // area light: short edge (m)
  double spot_angle = 0.0;  // spot light: full cone angle (radians)
  double spot_blend = 0.0;  // spot light: Blender's spot_blend
  double power = 0.0;       // Blender watts
  glm::dvec3 color{0.8, 0.8, 0.8};
  bool accent = false;      // one of the two vertical accents
  double azimuth = 0.0;     // ring lights: theta_j of the formula; accents: 0
};

struct LightRigOptions {
  // When set, every power is scaled so the illuminance at the centre equals this (lux).
  std::optional<double> target_illuminance_lux;
};

struct LightRig {
  std::vector<RigLight> lights;
  int ring_count = 0;
  double illuminance_lux = 0.0;  // at the centre, after any rescaling (see light_rig.cpp)
  double power_scale = 1.0;      // 1 unless a target illuminance was asked for
};

// Rig for an object whose minimal enclosing sphere has `center` and `radius` (metres).
LightRig make_light_rig(const glm::dvec3& center, double radius, const LightRigOptions& options = {});

// Illuminance (lux) that the rig's lights give at `point` (see light_rig.cpp for the definition).
double rig_illuminance_lux(const std::vector<RigLight>& lights, const glm::dvec3& point);

// Luminous efficacy that defines the lumen: 683 lm per watt of 555 nm light. Blender watts are
// radiometric, so lux = 683 x (W/m^2 weighted by the lamp colour's Rec.709 luminance).
constexpr double kLuxPerWattPerSquareMetre = 683.0;

}  // namespace matgeom
