// The plan of a dataset (matdataset/maker/dataset_plan.h): every frame in one fixed order, the
// variant cap, the frame limit, shards that partition the frames, and frame seeds that follow
// from the configuration's seed and the frame's indices alone.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "matbase/input_error.h"
#include "matdataset/maker/dataset_config.h"
#include "matdataset/maker/dataset_plan.h"

using matdataset::DatasetPlan;
using matdataset::FrameRef;
using matdataset::Shard;

TEST_CASE("The default plan lists object by object, variant by variant, view by view", "[dataset]") {
  const matdataset::DatasetConfig config = matdataset::load_config("", {});
  const DatasetPlan plan = matdataset::plan_dataset(config);
  CHECK(plan.views == 8);  // the 2 x 4 grid
  REQUIRE(plan.variants.size() == 6);
  for (const std::vector<matdataset::MaterialVariant>& variants : plan.variants) {
    REQUIRE(variants.size() == 3);  // one slot of three candidates
    for (size_t v = 0; v < 3; ++v) CHECK(variants[v] == matdataset::MaterialVariant{v});
  }
  REQUIRE(plan.frames.size() == 6 * 3 * 8);
  for (size_t k = 0; k < plan.frames.size(); ++k) {
    CHECK(plan.frames[k].object == k / 24);
    CHECK(plan.frames[k].variant == k / 8 % 3);
    CHECK(plan.frames[k].view == k % 8);
  }
  CHECK(matdataset::variant_folder(config, plan, 4, 2) == std::filesystem::path("dataset_out") / "mug" / "var002");
  CHECK(matdataset::view_stem(plan, 7) == "007");
  CHECK(matdataset::variant_material_names(config.objects[0], plan.variants[0][1]) ==
        std::vector<std::string>{"metal_brushed_2"});
}

TEST_CASE("A variant cap keeps a seeded subset in the full list's order", "[dataset]") {
  const std::string yaml =
      "objects:\n  - {name: vase, builtin: vase}\n"
      "materials:\n  all: [wood/raw:1, wood/raw:2, wood/raw:3, wood/raw:4, wood/raw:5]\n"
      "camera: {grid: [1, 2]}\n";
  auto plan_with = [&](const std::string& variants) {
    return matdataset::plan_dataset(
        matdataset::parse_config(yaml + variants, "test.yaml", std::filesystem::current_path(), {}));
  };
  const DatasetPlan capped = plan_with("variants: {max_variants: 3, seed: 7}\n");
  REQUIRE(capped.variants.size() == 1);
  REQUIRE(capped.variants[0].size() == 3);
  CHECK(capped.frames.size() == 3 * 2);
  std::set<size_t> seen;
  for (size_t v = 0; v < 3; ++v) {
    REQUIRE(capped.variants[0][v].size() == 1);
    seen.insert(capped.variants[0][v][0]);
    if (v > 0) CHECK(capped.variants[0][v - 1][0] < capped.variants[0][v][0]);
  }
  CHECK(seen.size() == 3);
  CHECK(plan_with("variants: {max_variants: 3, seed: 7}\n").variants == capped.variants);
  // A cap at or above the count keeps them all.
  CHECK(plan_with("variants: {max_variants: 9}\n").variants[0].size() == 5);
}

TEST_CASE("A list of UV scales renders every material variant once per scale, the scales varying fastest", "[dataset]") {
  const std::string yaml =
      "objects:\n  - {name: pillow, builtin: pillow, uv_pass: always, uv_scale: [0.1, 0.5, 2]}\n"
      "  - {name: vase, builtin: vase}\n"
      "materials:\n  all: [fabric:1, leather:2]\n"
      "camera: {grid: [1, 2]}\n";
  const matdataset::DatasetConfig config =
      matdataset::parse_config(yaml, "test.yaml", std::filesystem::current_path(), {});
  const DatasetPlan plan = matdataset::plan_dataset(config);
  REQUIRE(plan.variants[0].size() == 6);
  CHECK(plan.variants[1].size() == 2);
  CHECK(plan.frames.size() == (6 + 2) * 2);
  const matdataset::ObjectConfig& pillow = config.objects[0];
  const std::vector<double> scales = {0.1, 0.5, 2.0, 0.1, 0.5, 2.0};
  for (size_t v = 0; v < 6; ++v) {
    CHECK(plan.variants[0][v][0] == v / 3);  // the material
    CHECK(pillow.uv_scale_of(plan.variants[0][v]) == scales[v]);
  }
  CHECK(config.objects[1].uv_scale_of(plan.variants[1][0]) == 1.0);
  auto refusal = [&](const std::string& scale) -> std::string {
    try {
      matdataset::parse_config("objects:\n  - {name: pillow, builtin: pillow, uv_pass: always, uv_scale: " + scale +
                                   "}\n",
                               "test.yaml", std::filesystem::current_path(), {});
    } catch (const matbase::InputError& e) {
      return e.what();
    }
    return "";
  };
  CHECK_THAT(refusal("[0.5, 0.5]"), Catch::Contains("objects.0.uv_scale.1") && Catch::Contains("listed twice"));
  CHECK_THAT(refusal("[]"), Catch::Contains("objects.0.uv_scale") && Catch::Contains("empty"));
  CHECK_THAT(refusal("[0.5, 1000]"), Catch::Contains("objects.0.uv_scale.1"));
}

TEST_CASE("A plan beyond 50 million frames is refused with its size before it is listed", "[dataset]") {
  matdataset::DatasetConfig config = matdataset::load_config("", {});
  config.camera.n_phi = 10000;
  config.camera.n_theta = 1000;  // 10^7 views x 18 variants
  try {
    matdataset::plan_dataset(config);
    FAIL("planned");
  } catch (const matbase::InputError& e) {
    CHECK(std::string(e.what()).rfind(
              "the embedded default: the plan has 1.8e+08 frames, more than the 50,000,000 one dataset may have", 0) == 0);
  }
}

TEST_CASE("A shard is K/N with 0 <= K < N, and the shards of N partition the frames", "[dataset]") {
  const std::optional<Shard> two_of_three = matdataset::parse_shard("2/3");
  REQUIRE(two_of_three);
  CHECK(two_of_three->index == 2);
  CHECK(two_of_three->count == 3);
  REQUIRE(matdataset::parse_shard("0/1"));
  REQUIRE(matdataset::parse_shard("999999/1000000"));
  for (const char* bad : {"3/3", "-1/3", "1/0", "0/-2", "1/1000001", "a/3", "1/b", "1", "1/2/3", "/3", "1/", "", " 1/3"})
    CHECK_FALSE(matdataset::parse_shard(bad));
  for (const int count : {1, 2, 3, 7}) {
    std::vector<size_t> sizes(static_cast<size_t>(count), 0);
    for (size_t frame = 0; frame < 144; ++frame) {
      int owners = 0;
      for (int index = 0; index < count; ++index)
        if (Shard{index, count}.owns(frame)) {
          ++owners;
          ++sizes[static_cast<size_t>(index)];
        }
      CHECK(owners == 1);
    }
    // Round robin: the shards' sizes differ by one at most.
    CHECK(*std::max_element(sizes.begin(), sizes.end()) - *std::min_element(sizes.begin(), sizes.end()) <= 1);
  }
}

TEST_CASE("A frame's seed is SplitMix64 folded over the seed and the frame's indices", "[dataset]") {
  // Expected: the high 32 bits of h after h = m(seed), then h = m(h ^ index) for object, variant
  // and view, with m the SplitMix64 output function (Steele, Lea, Flood 2014), computed
  // independently in Python; m(0) = 0xe220a8397b1dcdaf is SplitMix64's published first output.
  CHECK(matdataset::frame_seed(0, FrameRef{0, 0, 0}) == 556823690u);
  CHECK(matdataset::frame_seed(42, FrameRef{1, 2, 3}) == 1069113463u);
  CHECK(matdataset::frame_seed(UINT64_MAX, FrameRef{5, 2, 7}) == 2387958400u);
  // render.seed folds in last, h = m(h ^ sample_seed), and 0 leaves the seed as it was.
  CHECK(matdataset::frame_seed(42, FrameRef{1, 2, 3}, 7) == 761160942u);
  CHECK(matdataset::frame_seed(42, FrameRef{1, 2, 3}, 0) == 1069113463u);
  // Every frame of the default plan gets its own seed, and a new base seed changes them all.
  const DatasetPlan plan = matdataset::plan_dataset(matdataset::load_config("", {}));
  std::set<uint32_t> seeds;
  for (const FrameRef& frame : plan.frames) {
    seeds.insert(matdataset::frame_seed(0, frame));
    CHECK(matdataset::frame_seed(1, frame) != matdataset::frame_seed(0, frame));
  }
  CHECK(seeds.size() == plan.frames.size());
}

TEST_CASE("Cameras under an object's floor are left out of its views, in every lighting round, and counted", "[dataset]") {
  // A vase on a floor and one alone, seen from 1 m on a 4 x 2 grid reaching straight down: the
  // rings at 112.5 and 157.5 degrees from +Z stand at z = c + cos(phi) below the floor at the
  // vase's lowest point (c, the vase's centroid height, is under 0.38 m).
  const std::string yaml =
      "objects:\n"
      "  - {name: on_floor, builtin: vase, surroundings: {kind: floor, floor_materials: [wood]}}\n"
      "  - {name: in_space, builtin: vase}\n"
      "materials: {all: [wood/raw:1, wood/raw:2]}\n"
      "camera: {grid: [4, 2], phi_deg: [0, 180], radius: {rule: fixed, metres: 1}}\n"
      "lights: {assign: every_setup, setups: [{rig: {}}, {environment: {images: [interior]}}]}\n";
  const matdataset::DatasetConfig config = matdataset::parse_config(yaml, "test.yaml", std::filesystem::current_path(), {});
  const DatasetPlan plan = matdataset::plan_dataset(config);
  CHECK(plan.grid_views == 8);
  CHECK(plan.views == 16);  // two rounds of lighting
  CHECK(plan.grid_views_under_floor[0] == std::vector<size_t>{4, 5, 6, 7});
  CHECK(plan.grid_views_under_floor[1].empty());
  CHECK(plan.object_views[0] == std::vector<size_t>{0, 1, 2, 3, 8, 9, 10, 11});
  CHECK(plan.object_views[1].size() == 16);
  REQUIRE(plan.frames.size() == 2 * 8 + 2 * 16);
  for (const FrameRef& frame : plan.frames)
    if (frame.object == 0) CHECK(frame.view % 8 < 4);
  // Above the horizon nothing is left out, and nothing is read to find that out.
  const DatasetPlan above = matdataset::plan_dataset(matdataset::parse_config(
      yaml, "test.yaml", std::filesystem::current_path(), {{"camera.phi_deg", "[0, 90]", "--set"}}));
  CHECK(above.grid_views_under_floor[0].empty());
  CHECK(above.frames.size() == 2 * 16 + 2 * 16);
}
