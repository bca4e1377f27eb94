#pragma once
// Where the distractors of a frame stand (surroundings.h, `kind: distractors`): each one's
// footprint (the smallest circle about its vertices seen from above) apart from the target's and
// from every other's, so no two objects can intersect whatever their shapes, each standing on the
// floor at its lowest point, turned about the vertical.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

#include "matdataset/maker/seed_stream.h"
#include "matdataset/maker/surroundings.h"
#include "matgeom/mesh.h"
#include "matrender/scene_description.h"

namespace matdataset {

// An object seen from above: the smallest circle about its vertices, and its lowest point.
struct Footprint {
  glm::dvec2 center{0.0};
  double radius = 0.0;
  double lowest = 0.0;
};
Footprint footprint(const matgeom::TriangleMesh& mesh);

// An object's distractor slots (as many as the most a frame has), drawn once per object from the
// configuration's seed: each one of the configured objects, or of the built-ins but
// `target_builtin` (the target's own, when it is one), a built-in with a drawn shape seed, and
// its size: its bounding sphere's radius over the target's (`scale`). Frames move and turn them.
using DistractorObject = std::variant<matrender::MeshFile, matrender::BuiltinObject>;
struct DistractorSlot {
  DistractorObject object;
  double scale = 1.0;
};
std::vector<DistractorSlot> draw_distractor_slots(const DistractorsConfig& config,
                                                  const std::optional<std::string>& target_builtin, uint64_t seed,
                                                  size_t object);

// The slot's mesh (of footprint `own`) scaled by `factor` about its footprint's centre, which goes
// to the origin, and its lowest point, which goes to z = 0.
glm::dmat4 distractor_sizing(const Footprint& own, double factor);

// The material of each slot in variant `variant`, drawn as the floor's is.
std::vector<MaterialCandidate> draw_distractor_materials(const DistractorsConfig& config, size_t slots, uint64_t seed,
                                                         size_t object, size_t variant);

// One distractor in a frame: its slot, and the transform from its mesh as built to its place.
struct DistractorPlacement {
  size_t slot = 0;
  glm::dmat4 transform{1.0};
  glm::dvec2 center{0.0};  // its footprint's, placed
  double radius = 0.0;
};

// Draws how many distractors a frame has and where each stands, from `draws`: around the target's
// footprint at a drawn gap, angle and turn, each slot at its size (`sizings`: distractor_sizing,
// `radii`: its footprint's radius then), every footprint apart from the others and within `reach`
// of the target's centre, on the floor at `floor_height`. None when one of them finds no free
// place in a few dozen tries.
std::optional<std::vector<DistractorPlacement>> place_distractors(const DistractorsConfig& config,
                                                                  const Footprint& target,
                                                                  const std::vector<glm::dmat4>& sizings,
                                                                  const std::vector<double>& radii,
                                                                  double floor_height, double reach,
                                                                  SeedStream& draws);

// How far from the target's centre distractors may stand, as a share of the room's half width
// (the walls', or the floor's edge).
constexpr double kDistractorReachOfRoom = 0.95;

// The frame's draw stream: the configuration's seed and the frame's indices.
SeedStream distractor_draws(uint64_t seed, size_t object, size_t variant, size_t view);

// Whether the most distractors, at the largest scale and smallest gap, can stand apart around a
// target of footprint radius `target_radius` and bounding sphere radius `target_size` within
// `reach`: their footprints (at most their spheres' radius, `scale` times the target's size), each
// with half the smallest gap about it, may cover at most 70 % of the ring around the target (a
// random packing's limit is lower still). False: the configuration asks for more than the floor
// holds apart.
bool distractors_fit(const DistractorsConfig& config, double target_radius, double target_size, double reach);

}  // namespace matdataset
