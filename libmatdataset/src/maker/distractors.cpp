#include "matdataset/maker/distractors.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "matbase/pi.h"
#include "matgeom/bounding_sphere.h"
#include "matgeom/builtin/builtin_objects.h"

namespace matdataset {
namespace {

// Keep these draws apart from every other draw made from the same indices.
constexpr uint64_t kSlotSalt = 0x534c'4f54'5345'4c45ull;       // "SLOTSELE"
constexpr uint64_t kMaterialSalt = 0x4449'534d'4154'4552ull;   // "DISMATER"
constexpr uint64_t kPlacementSalt = 0x504c'4143'494e'4753ull;  // "PLACINGS"
// Built-in shape seeds drawn for slots: the built-ins vary their shape with them.
constexpr uint64_t kShapeSeeds = 10;
// Tries for one distractor's place before the frame's draw is given up.
constexpr int kPlaceTries = 48;
// The share of the ring around the target that the distractors' discs may cover.
constexpr double kPackingDensity = 0.7;

uint64_t mixed(uint64_t seed, uint64_t salt, std::initializer_list<size_t> indices) {
  uint64_t h = splitmix64(seed ^ salt);
  for (const size_t index : indices) h = splitmix64(h ^ static_cast<uint64_t>(index));
  return h;
}

}  // namespace

Footprint footprint(const matgeom::TriangleMesh& mesh) {
  std::vector<glm::vec3> flat(mesh.positions);
  Footprint print;
  print.lowest = mesh.positions.empty() ? 0.0 : static_cast<double>(mesh.positions.front().z);
  for (glm::vec3& p : flat) {
    print.lowest = std::min(print.lowest, static_cast<double>(p.z));
    p.z = 0.0f;
  }
  const matgeom::Sphere circle = matgeom::minimal_enclosing_sphere(flat);
  print.center = glm::dvec2(circle.center);
  print.radius = circle.radius;
  return print;
}

std::vector<DistractorSlot> draw_distractor_slots(const DistractorsConfig& config,
                                                  const std::optional<std::string>& target_builtin, uint64_t seed,
                                                  size_t object) {
  std::vector<DistractorObject> choices = config.objects;
  if (choices.empty())
    for (const std::string& name : matgeom::builtin_object_names())
      if (name != target_builtin) choices.push_back(matrender::BuiltinObject{name, 0});
  SeedStream draws(mixed(seed, kSlotSalt, {object}));
  std::vector<DistractorSlot> slots;
  for (int k = 0; k < static_cast<int>(config.count.high); ++k) {
    DistractorObject chosen = choices[draws.next() % choices.size()];
    const uint64_t shape = draws.next() % kShapeSeeds;
    if (auto* builtin = std::get_if<matrender::BuiltinObject>(&chosen)) builtin->seed = static_cast<uint32_t>(shape);
    slots.push_back({std::move(chosen), draw(config.scale, draws)});
  }
  return slots;
}

glm::dmat4 distractor_sizing(const Footprint& own, double factor) {
  return glm::scale(glm::dmat4(1.0), glm::dvec3(factor)) * glm::translate(glm::dmat4(1.0), -glm::dvec3(own.center, own.lowest));
}

std::vector<MaterialCandidate> draw_distractor_materials(const DistractorsConfig& config, size_t slots, uint64_t seed,
                                                         size_t object, size_t variant) {
  SeedStream draws(mixed(seed, kMaterialSalt, {object, variant}));
  std::vector<MaterialCandidate> materials;
  for (size_t k = 0; k < slots; ++k) materials.push_back(drawn_candidate(config.materials, draws));
  return materials;
}

SeedStream distractor_draws(uint64_t seed, size_t object, size_t variant, size_t view) {
  return SeedStream(mixed(seed, kPlacementSalt, {object, variant, view}));
}

std::optional<std::vector<DistractorPlacement>> place_distractors(const DistractorsConfig& config,
                                                                  const Footprint& target,
                                                                  const std::vector<glm::dmat4>& sizings,
                                                                  const std::vector<double>& radii,
                                                                  double floor_height, double reach,
                                                                  SeedStream& draws) {
  const int count = std::min(draw_count(config.count, draws), static_cast<int>(sizings.size()));
  std::vector<DistractorPlacement> placed;
  for (int k = 0; k < count; ++k) {
    const double radius = radii[static_cast<size_t>(k)];
    bool found = false;
    for (int attempt = 0; attempt < kPlaceTries && !found; ++attempt) {
      // Three numbers a try, whether it is kept or not, so the draws stay in step.
      const double gap = draw(config.gap, draws) * target.radius;
      const double angle = 2.0 * matbase::kPi * draws.uniform();
      const double turn = 2.0 * matbase::kPi * draws.uniform();
      const double distance = target.radius + gap + radius;
      if (distance + radius > reach) continue;
      const glm::dvec2 center = target.center + distance * glm::dvec2(std::cos(angle), std::sin(angle));
      bool apart = true;
      for (const DistractorPlacement& other : placed)
        apart = apart && glm::length(center - other.center) >= radius + other.radius;
      if (!apart) continue;
      DistractorPlacement placement;
      placement.slot = static_cast<size_t>(k);
      placement.center = center;
      placement.radius = radius;
      // At its size, turned about the vertical through its footprint's centre, that centre to the
      // drawn one and its lowest point to the floor.
      placement.transform = glm::translate(glm::dmat4(1.0), glm::dvec3(center, floor_height)) *
                            glm::rotate(glm::dmat4(1.0), turn, glm::dvec3(0.0, 0.0, 1.0)) * sizings[static_cast<size_t>(k)];
      placed.push_back(placement);
      found = true;
    }
    if (!found) return std::nullopt;
  }
  return placed;
}

bool distractors_fit(const DistractorsConfig& config, double target_radius, double target_size, double reach) {
  const double radius = config.scale.high * target_size, half_gap = 0.5 * config.gap.low * target_radius;
  const double inner = target_radius + 2.0 * half_gap;
  if (inner + 2.0 * radius > reach) return false;
  const double discs = config.count.high * matbase::kPi * (radius + half_gap) * (radius + half_gap);
  return discs <= kPackingDensity * matbase::kPi * (reach * reach - inner * inner);
}

}  // namespace matdataset
