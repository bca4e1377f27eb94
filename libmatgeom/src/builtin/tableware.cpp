// Turned and moulded objects: each body is a vessel or solid of revolution (lathe_mesh), with
// handles as tube arcs. Sizes are those of ordinary household items.
#include <array>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "builtin/object_builder.h"
#include "builtin/objects.h"
#include "builtin/shapes.h"

namespace matgeom::builtin {
namespace {

constexpr int kAround = 48;       // segments around turned bodies
constexpr int kWallSamples = 16;  // samples up a vessel wall

// A handle: the right half of a tube circle in the xz plane (ends pointing at -x), turned about
// z by `azimuth` and centred at `centre`.
TriangleMesh handle(double radius, double thickness, const glm::dvec3& centre, double azimuth) {
  glm::dmat4 m = glm::translate(glm::dmat4(1.0), centre);
  m = glm::rotate(m, azimuth, glm::dvec3(0.0, 0.0, 1.0));
  return transformed(torus_arc_mesh(radius, thickness, -0.5 * kPi, 0.5 * kPi, 24, 12), m);
}

}  // namespace

ObjectAsset make_mug(uint32_t seed) {
  ObjectBuilder b(seed);
  matbase::UniformSource& r = b.random();
  const double height = r.between(0.085, 0.11), radius = r.between(0.037, 0.045);
  const double taper = r.between(-0.05, 0.08);  // radius change per metre of height
  const auto outer = [=](double z) { return radius + taper * z; };
  const uint32_t body = b.add_part("body", Finish::Ceramic);
  const uint32_t grip = b.add_part("handle", Finish::Ceramic);
  b.add(body, lathe_mesh(vessel_profile(outer, height, 0.0045, 0.008, kWallSamples), kAround));
  const double handle_radius = r.between(0.022, 0.03);
  // The handle's ends sink into the wall (its centre line starts a tube radius inside it).
  b.add(grip, handle(handle_radius, 0.0055, glm::dvec3(outer(0.5 * height) - 0.004, 0.0, 0.5 * height), 0.0));
  return b.finish();
}

ObjectAsset make_bowl(uint32_t seed) {
  ObjectBuilder b(seed);
  matbase::UniformSource& r = b.random();
  const double height = r.between(0.055, 0.09), rim = r.between(0.07, 0.1), foot = r.between(0.03, 0.042);
  // The wall flares out fast from the foot and turns vertical at the rim.
  const auto outer = [=](double z) {
    const double t = z / height;
    return foot + (rim - foot) * (1.0 - (1.0 - t) * (1.0 - t));
  };
  const uint32_t body = b.add_part("body", r.next() < 0.7 ? Finish::Ceramic : Finish::Wood);
  b.add(body, lathe_mesh(vessel_profile(outer, height, 0.005, 0.007, kWallSamples), kAround));
  return b.finish();
}

ObjectAsset make_bottle(uint32_t seed) {
  ObjectBuilder b(seed);
  matbase::UniformSource& r = b.random();
  const double radius = r.between(0.03, 0.04), body_height = r.between(0.14, 0.19);
  const double shoulder = r.between(0.04, 0.06), neck_radius = r.between(0.011, 0.015), neck = r.between(0.025, 0.04);
  const double top = body_height + shoulder + neck;
  // A closed solid: out along the base, up the body, in over the shoulder, up the neck.
  std::vector<ProfilePoint> profile = {{0.0, 0.0}, {radius - 0.004, 0.0}};
  for (int k = 1; k <= 4; ++k) {  // rounded foot
    const double a = -0.5 * kPi + 0.5 * kPi * k / 4;
    profile.push_back({radius - 0.004 + 0.004 * std::cos(a), 0.004 + 0.004 * std::sin(a)});
  }
  profile.push_back({radius, body_height});
  for (int k = 1; k <= 10; ++k) {  // shoulder: a quarter ellipse from the body to the neck
    const double a = 0.5 * kPi * k / 10;
    profile.push_back({neck_radius + (radius - neck_radius) * std::cos(a), body_height + shoulder * std::sin(a)});
  }
  profile.push_back({neck_radius, top});
  profile.push_back({0.0, top});
  const uint32_t body = b.add_part("body", Finish::Plastic);
  const uint32_t cap = b.add_part("cap", r.next() < 0.5 ? Finish::BrushedMetal : Finish::Plastic);
  b.add(body, lathe_mesh(profile, kAround));
  b.add(cap, cylinder_mesh(neck_radius + 0.0025, top - 0.012, top + 0.006, kAround));
  return b.finish();
}

ObjectAsset make_plant_pot(uint32_t seed) {
  ObjectBuilder b(seed);
  matbase::UniformSource& r = b.random();
  const double height = r.between(0.12, 0.22), base = r.between(0.05, 0.08);
  const double flare = r.between(0.15, 0.3);  // radius gained per metre of height
  const auto outer = [=](double z) { return base + flare * z; };
  const Finish finish = std::array<Finish, 3>{Finish::Ceramic, Finish::Concrete, Finish::Plastic}[r.choice(3)];
  const uint32_t pot = b.add_part("pot", finish);
  const uint32_t soil = b.add_part("soil", Finish::Concrete);
  const double wall = 0.007;
  b.add(pot, lathe_mesh(vessel_profile(outer, height, wall, 0.012, kWallSamples), kAround));
  // A thick rim band round the top, as moulded pots have.
  const double rim = outer(height);
  b.add(pot, lathe_mesh({{rim - 0.5 * wall, height - 0.025},
                         {rim + 0.006, height - 0.025},
                         {rim + 0.006, height},
                         {rim - 0.5 * wall, height},
                         {rim - 0.5 * wall, height - 0.025}},
                        kAround));
  const double soil_level = height - r.between(0.015, 0.03);
  b.add(soil, cylinder_mesh(outer(soil_level) - wall - 0.0005, soil_level - 0.02, soil_level, kAround));
  return b.finish();
}

ObjectAsset make_basket(uint32_t seed) {
  ObjectBuilder b(seed);
  matbase::UniformSource& r = b.random();
  const double height = r.between(0.12, 0.2), rim = r.between(0.14, 0.2), bottom = rim * r.between(0.7, 0.85);
  const auto outer = [=](double z) { return bottom + (rim - bottom) * std::sqrt(z / height); };
  const uint32_t weave = b.add_part("weave", Finish::Wicker);
  const uint32_t grip = b.add_part("handle", r.next() < 0.5 ? Finish::Leather : Finish::Wicker);
  b.add(weave, lathe_mesh(vessel_profile(outer, height, 0.008, 0.01, kWallSamples), kAround));
  // An arched handle from rim to rim over the top.
  const glm::dmat4 arch = glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.0, height - 0.01));
  b.add(grip, transformed(torus_arc_mesh(rim - 0.004, 0.008, 0.0, kPi, 32, 12), arch));
  return b.finish();
}

}  // namespace matgeom::builtin
