// A tool's changes to a described scene (matrender/scene_overrides.h): each lands where the scene
// keeps it, and the ones the scene cannot take are refused by the name of what asked.
#include <catch2/catch.hpp>

#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "matbase/input_error.h"
#include "matrender/paper_setup.h"
#include "matrender/scene_overrides.h"

using matrender::SceneDescription;
using matrender::SceneOverrides;

namespace {

SceneDescription two_vases() {
  matrender::ObjectDescription vase;
  vase.source = matrender::BuiltinObject{"vase", 0};
  vase.material = "scene's own";
  vase.part_materials["neck"] = "another";
  SceneDescription scene = matrender::paper_object_scene(vase);
  scene.objects.push_back(vase);
  return scene;
}

// The refusal of `overrides` on `scene`, or "" when it applies.
std::string refusal(const SceneOverrides& overrides, SceneDescription scene) {
  try {
    matrender::apply_scene_overrides(overrides, scene);
  } catch (const matbase::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("No override leaves the scene as described", "[render]") {
  SceneDescription scene = two_vases();
  matrender::apply_scene_overrides(SceneOverrides{}, scene);
  REQUIRE(std::holds_alternative<matrender::GridPlacement>(scene.camera.placement));
  const auto& grid = std::get<matrender::GridPlacement>(scene.camera.placement);
  CHECK(grid.i == matrender::paper_grid_placement().i);
  CHECK(grid.spec.n_phi == matrender::paper_grid_placement().spec.n_phi);
  REQUIRE(std::holds_alternative<matrender::LightRigDescription>(scene.lights));
  CHECK(std::get<matrender::LightRigDescription>(scene.lights).target_illuminance_lux ==
        matrender::kPaperTargetIlluminanceLux);
  CHECK(std::holds_alternative<glm::vec3>(scene.background));
  CHECK(scene.objects[1].material == "scene's own");
  CHECK(scene.objects[1].part_materials.at("neck") == "another");
}

TEST_CASE("Camera overrides: a placement replaces the scene's, grid options make a grid camera", "[render]") {
  SceneDescription scene = two_vases();
  SceneOverrides look_at;
  look_at.placement = matrender::LookAtPlacement{glm::dvec3(1.0, 2.0, 3.0), glm::dvec3(0.0), glm::dvec3(0.0, 0.0, 1.0)};
  look_at.vertical_fov = 0.5;
  look_at.width = 64;
  look_at.height = 48;
  matrender::apply_scene_overrides(look_at, scene);
  REQUIRE(std::holds_alternative<matrender::LookAtPlacement>(scene.camera.placement));
  CHECK(std::get<matrender::LookAtPlacement>(scene.camera.placement).position == glm::dvec3(1.0, 2.0, 3.0));
  CHECK(scene.camera.vertical_fov == 0.5);
  CHECK(scene.camera.width == 64);
  CHECK(scene.camera.height == 48);

  // On a look-at camera a grid option brings the paper's grid, with what it sets.
  SceneOverrides grid;
  grid.grid = {{4, 6}, "--grid"};
  grid.grid_radius = {2.5, "--radius"};
  grid.cell = {{3, 5}, "--cell"};
  matrender::apply_scene_overrides(grid, scene);
  REQUIRE(std::holds_alternative<matrender::GridPlacement>(scene.camera.placement));
  const auto& placed = std::get<matrender::GridPlacement>(scene.camera.placement);
  CHECK(placed.spec.n_phi == 4);
  CHECK(placed.spec.n_theta == 6);
  CHECK(placed.spec.radius == 2.5);
  CHECK(placed.i == 3);
  CHECK(placed.j == 5);
  CHECK(placed.center_on_centroid);
  CHECK(scene.camera.width == 64);  // what the grid options do not set stays

  // A cell outside its grid is refused by the option that asked for the cell, else the grid.
  SceneOverrides outside;
  outside.cell = {{4, 0}, "--cell"};
  CHECK(refusal(outside, scene) == "--cell: camera cell 4,0 is outside the 4 x 6 grid");
  SceneOverrides smaller;
  smaller.grid = {{2, 2}, "camera.grid"};
  CHECK(refusal(smaller, scene) == "camera.grid: camera cell 3,5 is outside the 2 x 2 grid");
}

TEST_CASE("Illuminance overrides scale only the paper's rig", "[render]") {
  SceneOverrides brighter;
  brighter.illuminance_lux = {2500.0, "--illuminance"};
  SceneDescription scene = two_vases();
  matrender::apply_scene_overrides(brighter, scene);
  CHECK(std::get<matrender::LightRigDescription>(scene.lights).target_illuminance_lux == 2500.0);

  SceneOverrides given_powers;
  given_powers.rig_at_given_powers = true;
  given_powers.illuminance_lux = {2500.0, "--illuminance"};  // the rig's own powers win
  matrender::apply_scene_overrides(given_powers, scene);
  CHECK_FALSE(std::get<matrender::LightRigDescription>(scene.lights).target_illuminance_lux.has_value());

  SceneDescription listed = two_vases();
  listed.lights = std::vector<matrender::Lamp>{matrender::PointLamp{}};
  CHECK(refusal(brighter, listed) ==
        "--illuminance: rescales only the paper's light rig, and the scene file lists its own lights");
  CHECK(refusal(given_powers, listed).empty());  // a scene's own lights are at their powers anyway
}

TEST_CASE("Environment overrides need a map: the one given or the scene's", "[render]") {
  SceneOverrides stronger;
  stronger.environment_strength = {0.5, "--environment-strength"};
  stronger.environment_rotation_z = {1.0, "--environment-rotation"};
  CHECK(refusal(stronger, two_vases()) == "--environment-strength: the scene has no environment map (add one to the scene)");
  SceneOverrides turned;
  turned.environment_rotation_z = {1.0, "--environment-rotation"};
  CHECK(refusal(turned, two_vases()) == "--environment-rotation: the scene has no environment map (add one to the scene)");

  stronger.environment = matrender::EnvironmentDescription{"sky.hdr", std::nullopt, 1.0, 0.0, {}};
  SceneDescription scene = two_vases();
  matrender::apply_scene_overrides(stronger, scene);
  REQUIRE(std::holds_alternative<matrender::EnvironmentDescription>(scene.background));
  const auto& environment = std::get<matrender::EnvironmentDescription>(scene.background);
  CHECK(environment.path == "sky.hdr");
  CHECK(environment.strength == 0.5);
  CHECK(environment.rotation_z == 1.0);
}

TEST_CASE("Material overrides add materials and may put one on every part", "[render]") {
  SceneOverrides added;
  added.materials["oak"] = matrender::MaterialDescription{};
  SceneDescription scene = two_vases();
  matrender::apply_scene_overrides(added, scene);
  CHECK(scene.materials.count("oak") == 1);
  CHECK(scene.objects[0].material == "scene's own");  // added, not put on anything

  added.material_everywhere = "oak";
  matrender::apply_scene_overrides(added, scene);
  for (const matrender::ObjectDescription& object : scene.objects) {
    CHECK(object.material == "oak");
    CHECK(object.part_materials.empty());
  }
  SceneOverrides unknown;
  unknown.material_everywhere = "walnut";
  CHECK_THROWS_AS(matrender::apply_scene_overrides(unknown, scene), std::invalid_argument);
}
