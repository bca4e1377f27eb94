#pragma once
// Measured normal-incidence reflectances (F0) of real metals, in linear sRGB/Rec. 709: the base
// colours the procedural library gives metallic materials. Gold, silver, copper, iron and
// aluminium are Hoffman's, "Background: Physics and Math of Shading", SIGGRAPH 2013 course
// "Physically Based Shading in Theory and Practice", table of metals' F0; chromium, nickel and
// titanium are Adobe's "Metal material references" (Substance 3D, Adobe Standard Material),
// computed from measured spectral indices of refraction. Both sources agree on chromium.
#include <array>

#include <glm/glm.hpp>

namespace matmaterial {

struct MetalReflectance {
  const char* name;
  glm::dvec3 f0;  // linear RGB
};

constexpr std::array<MetalReflectance, 8> kMetalReflectances = {{
    {"gold", {1.00, 0.71, 0.29}},
    {"silver", {0.95, 0.93, 0.88}},
    {"copper", {0.95, 0.64, 0.54}},
    {"iron", {0.56, 0.57, 0.58}},
    {"aluminium", {0.91, 0.92, 0.92}},
    {"chromium", {0.5496, 0.5561, 0.5531}},
    {"nickel", {0.7014, 0.6382, 0.5593}},
    {"titanium", {0.4432, 0.3993, 0.3599}},
}};

}  // namespace matmaterial
