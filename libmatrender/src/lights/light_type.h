#pragma once
// What kind of emitter a light is, in pbrt-v4's terms (section 12.1, LightType). The integrator
// decides from it alone: a delta light is reached only by light sampling (no MIS, no ray hits it),
// an area light is sampled and also hit by rays (MIS between the two), and an infinite light is
// what a ray that leaves the scene sees.
namespace matrender {

enum class LightType {
  DeltaPosition,   // point and spot lamps
  DeltaDirection,  // sun-like lamps from one direction
  Area,            // rectangles
  Infinite,        // the background
};

constexpr bool is_delta(LightType type) {
  return type == LightType::DeltaPosition || type == LightType::DeltaDirection;
}

}  // namespace matrender
