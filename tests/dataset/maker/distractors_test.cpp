// Distractors on the floor: wherever a frame's draw puts them, each one's footprint (recomputed
// here from its placed vertices) is apart from the target's and from every other's, inside the
// floor's reach, its lowest point on the floor; the same draw gives the same places; a
// configuration asking for more than the floor holds apart, or spelling them wrong, is refused.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "matbase/input_error.h"
#include "matdataset/maker/dataset_checks.h"
#include "matdataset/maker/dataset_config.h"
#include "matdataset/maker/distractors.h"
#include "matgeom/builtin/builtin_objects.h"

using namespace matdataset;

namespace {

matgeom::TriangleMesh builtin(const std::string& name, uint32_t seed = 0) {
  return matgeom::make_builtin_object(name, seed).mesh;
}

matgeom::TriangleMesh placed(matgeom::TriangleMesh mesh, const glm::dmat4& transform) {
  matgeom::transform_mesh(mesh, transform);
  return mesh;
}

DatasetConfig config_of(const std::string& surroundings) {
  return parse_config("objects: [{builtin: vase}]\nmaterials: {all: [wood]}\nsurroundings: " + surroundings + "\n",
                      "test.yaml", ".", {});
}

}  // namespace

TEST_CASE("Every drawn place keeps the distractors' footprints apart from the target's and each other's", "[dataset]") {
  DistractorsConfig config;
  config.count = {3.0, 5.0};
  config.scale = {0.5, 1.5};
  config.gap = {0.0, 1.0};
  const matgeom::TriangleMesh target = builtin("vase");
  const Footprint target_print = footprint(target);
  const std::vector<std::string> names = {"chair", "mug", "lamp", "book", "basket"};
  std::vector<matgeom::TriangleMesh> meshes;
  std::vector<glm::dmat4> sizings;
  std::vector<double> radii;
  for (size_t k = 0; k < names.size(); ++k) {
    meshes.push_back(builtin(names[k], static_cast<uint32_t>(k)));
    const double scale = 0.5 + 0.25 * static_cast<double>(k);
    const Footprint own = footprint(meshes.back());
    const double factor = scale * target_print.radius / own.radius;
    sizings.push_back(distractor_sizing(own, factor));
    radii.push_back(own.radius * factor);
  }
  const double reach = 8.0 * target_print.radius, floor = -0.3;
  size_t placed_frames = 0, distractors = 0;
  for (size_t view = 0; view < 200; ++view) {
    SeedStream draws = distractor_draws(7, 0, 0, view);
    const auto placements = place_distractors(config, target_print, sizings, radii, floor, reach, draws);
    if (!placements) continue;
    ++placed_frames;
    SeedStream again = distractor_draws(7, 0, 0, view);
    const auto repeated = place_distractors(config, target_print, sizings, radii, floor, reach, again);
    REQUIRE(repeated);
    REQUIRE(repeated->size() == placements->size());
    CHECK(placements->size() >= 3);
    std::vector<Footprint> prints = {target_print};
    for (size_t k = 0; k < placements->size(); ++k) {
      const DistractorPlacement& p = (*placements)[k];
      CHECK(p.transform == (*repeated)[k].transform);
      const matgeom::TriangleMesh mesh = placed(meshes[p.slot], p.transform);
      const Footprint print = footprint(mesh);
      CHECK(print.lowest == Approx(floor).margin(1e-5));
      CHECK(print.radius == Approx(radii[p.slot]).epsilon(1e-4));
      CHECK(glm::length(print.center - target_print.center) + print.radius <= reach * (1.0 + 1e-6));
      prints.push_back(print);
      ++distractors;
    }
    for (size_t a = 0; a < prints.size(); ++a)
      for (size_t b = a + 1; b < prints.size(); ++b)
        CHECK(glm::length(prints[a].center - prints[b].center) >= (prints[a].radius + prints[b].radius) * (1.0 - 1e-5));
  }
  CHECK(placed_frames > 150);
  CHECK(distractors > 600);
}

TEST_CASE("A frame's draw depends on its indices alone; slots and materials on the object's and variant's", "[dataset]") {
  DistractorsConfig config;
  config.count = {2.0, 3.0};
  config.materials = {library_candidate(matmaterial::parse_library_material("plastic"), "plastic"),
                      library_candidate(matmaterial::parse_library_material("wood/raw:4"), "wood/raw:4")};
  config.materials[1].seed_given = true;
  const auto slots = draw_distractor_slots(config, std::string("vase"), 3, 1);
  REQUIRE(slots.size() == 3);
  for (const DistractorSlot& slot : slots) {
    CHECK(std::get<matrender::BuiltinObject>(slot.object).name != "vase");
    CHECK(slot.scale >= config.scale.low);
    CHECK(slot.scale <= config.scale.high);
  }
  CHECK(draw_distractor_slots(config, std::string("vase"), 3, 1)[2].scale == slots[2].scale);
  const auto materials = draw_distractor_materials(config, 3, 3, 1, 0);
  CHECK(draw_distractor_materials(config, 3, 3, 1, 0)[1].name == materials[1].name);
  // A plastic without a seed gets one drawn; the wood keeps its own.
  std::set<std::string> names;
  for (size_t variant = 0; variant < 20; ++variant)
    for (const MaterialCandidate& m : draw_distractor_materials(config, 3, 3, 1, variant)) names.insert(m.name);
  CHECK(names.count("wood_raw_4") == 1);
  CHECK(names.size() > 10);
}

TEST_CASE("Distractors the floor cannot hold apart, or spelled wrong, are refused naming the key", "[dataset]") {
  const auto refusal = [](const std::string& surroundings) {
    try {
      check_before_writing(config_of(surroundings));
    } catch (const matbase::InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const std::string ok = "{kind: distractors, floor_materials: [wood], distractors: {materials: [plastic]}}";
  CHECK(refusal(ok) == "accepted");
  CHECK(refusal("{kind: distractors, floor_materials: [wood], size: 1.2, distractors: {count: 40, scale: 2, "
                "materials: [plastic]}}")
            .find("objects.0.surroundings.distractors.count") != std::string::npos);
  // A distractor's mesh file that cannot be read is refused before the first file, not when its
  // object's turn comes.
  const std::filesystem::path broken = std::filesystem::temp_directory_path() / "matpredict_broken_distractor.ply";
  std::ofstream(broken) << "ply\nformat ascii 1.0\nelement vertex 3\nend_header\n0 0\n";
  CHECK(refusal("{kind: distractors, floor_materials: [wood], distractors: {objects: [{mesh: " + broken.string() +
                "}], materials: [plastic]}}")
            .find("objects.0.surroundings.distractors.objects: ") != std::string::npos);
  const auto parse_refusal = [](const std::string& surroundings) {
    try {
      config_of(surroundings);
    } catch (const matbase::InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  CHECK(parse_refusal("{kind: distractors, floor_materials: [wood]}").find("distractors") != std::string::npos);
  CHECK(parse_refusal("{kind: distractors, floor_materials: [wood], distractors: {count: 2}}").find("materials") !=
        std::string::npos);
  CHECK(parse_refusal("{kind: distractors, floor_materials: [wood], distractors: {count: 2.5, materials: [wood]}}")
            .find("surroundings.distractors.count") != std::string::npos);
  CHECK(parse_refusal("{kind: distractors, floor_materials: [wood], distractors: {objects: [spaceship], materials: [wood]}}")
            .find("surroundings.distractors.objects") != std::string::npos);
  CHECK(parse_refusal("{kind: floor, floor_materials: [wood], distractors: {materials: [wood]}}")
            .find("surroundings.distractors") != std::string::npos);
}
