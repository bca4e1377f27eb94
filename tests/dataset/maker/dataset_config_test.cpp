// make_dataset's configuration as a library (matdataset/maker/dataset_config.h): the embedded
// default read key by key, overrides in order, paths against the file's folder, and refusals that
// name the source, the option and the key. Expected values are the configuration texts' own.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <variant>
#include <vector>

#include "matbase/input_error.h"
#include "matdataset/maker/dataset_checks.h"
#include "matdataset/maker/dataset_config.h"
#include "support/temp_dir.h"

namespace fs = std::filesystem;
using matdataset::DatasetConfig;
using matdataset::Override;
using matdataset::parse_config;

namespace {

// The refusal of `yaml` (read as the source "test.yaml") with `overrides`, or "" when it is read.
std::string refusal(const std::string& yaml, const std::vector<Override>& overrides = {}) {
  try {
    parse_config(yaml, "test.yaml", fs::current_path(), overrides);
  } catch (const matbase::InputError& e) {
    return e.what();
  }
  return "";
}

const std::string kOneVase = "objects:\n  - {name: vase, builtin: vase, materials: {all: [wood/raw:1]}}\n";

}  // namespace

TEST_CASE("The embedded default is six built-in objects in three library materials, 2 x 4 views", "[dataset]") {
  const DatasetConfig config = matdataset::load_config("", {});
  CHECK(config.source == "the embedded default");
  REQUIRE(config.objects.size() == 6);
  const std::vector<std::string> names = {"vase", "chair", "table", "stool", "mug", "pillow"};
  for (size_t o = 0; o < names.size(); ++o) {
    const matdataset::ObjectConfig& object = config.objects[o];
    CHECK(object.name == names[o]);
    REQUIRE(std::holds_alternative<matrender::BuiltinObject>(object.source));
    CHECK(std::get<matrender::BuiltinObject>(object.source).name == names[o]);
    REQUIRE(object.slots.size() == 1);
    CHECK(object.slots[0].key == "all");
    CHECK(object.slots[0].parts.empty());
    REQUIRE(object.slots[0].candidates.size() == 3);
    CHECK(object.slots[0].candidates[0].name == "wood_raw_1");
    CHECK(object.slots[0].candidates[1].name == "metal_brushed_2");
    CHECK(object.slots[0].candidates[2].name == "fabric_twill_3");
  }
  CHECK(config.camera.n_phi == 2);
  CHECK(config.camera.n_theta == 4);
  CHECK(config.camera.radius_rule == matdataset::RadiusRule::Fit);
  CHECK(config.camera.fill == 0.9);
  CHECK(config.render.width == 128);
  CHECK(config.render.height == 128);
  CHECK(config.render.settings.samples_per_pixel == 32);
  CHECK_FALSE(config.render.exposure_stops.has_value());  // auto
  CHECK(config.render.material_resolution == 256);
  CHECK(config.combination == matdataset::VariantCombination::Cartesian);
  CHECK_FALSE(config.max_variants.has_value());
  CHECK(config.variant_seed == 42);
  CHECK(config.seed == 0);
}

TEST_CASE("Overrides apply in order over the file and are recorded, the output excepted", "[dataset]") {
  const DatasetConfig config = parse_config(kOneVase + "render: {samples: 4}\n", "test.yaml", fs::current_path(),
                                            {{"render.samples", "16", "--spp"},
                                             {"camera.grid", "[1, 3]", "--grid"},
                                             {"render.samples", "8", "--set render.samples=8"},
                                             {"output", "elsewhere", "--output"}});
  CHECK(config.render.settings.samples_per_pixel == 8);
  CHECK(config.camera.n_phi == 1);
  CHECK(config.camera.n_theta == 3);
  CHECK(config.output == "elsewhere");
  // The recorded configuration is the one rendered: the last value of each key, no output.
  CHECK(config.canonical_yaml.find("samples: 8") != std::string::npos);
  CHECK(config.canonical_yaml.find("samples: 4") == std::string::npos);
  CHECK(config.canonical_yaml.find("elsewhere") == std::string::npos);
}

TEST_CASE("Paths in a configuration are relative to its folder", "[dataset]") {
  const TempDir dir;
  fs::create_directories(dir.path() / "meshes");
  std::ofstream(dir.file("meshes/box.obj")) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  const DatasetConfig config = parse_config(
      "output: out\nobjects:\n  - {mesh: meshes/box.obj, materials: {all: [wood/raw:1]}}\n", "test.yaml", dir.path(), {});
  REQUIRE(config.objects.size() == 1);
  REQUIRE(std::holds_alternative<matrender::MeshFile>(config.objects[0].source));
  CHECK(fs::path(std::get<matrender::MeshFile>(config.objects[0].source).path) == dir.path() / "meshes" / "box.obj");
  CHECK(config.objects[0].name == "box");  // the file's stem, without a `name`
  CHECK(fs::path(config.output) == dir.path() / "out");
  // Given on the command line, the output is relative to where the tool runs, as a shell's paths are.
  const DatasetConfig overridden =
      parse_config("objects:\n  - {mesh: meshes/box.obj, materials: {all: [wood/raw:1]}}\n", "test.yaml", dir.path(),
                   {{"output", "here", "--output"}});
  CHECK(overridden.output == "here");
}

TEST_CASE("A configuration that says one thing twice, or nothing, or something unknown is refused by name",
          "[dataset]") {
  CHECK(refusal(kOneVase).empty());
  CHECK(refusal(kOneVase + "seed: 1\nseed: 2\n").rfind("test.yaml: seed: given twice (lines 3 and 4)", 0) == 0);
  CHECK(refusal(kOneVase + "render: {sampels: 4}\n")
            .rfind("test.yaml: render.sampels: unknown key (allowed here: \"resolution\", \"samples\", ", 0) == 0);
  CHECK(refusal(kOneVase + "render:\n  samples:\n").rfind("test.yaml: render.samples: no value given", 0) == 0);
  CHECK(refusal(kOneVase, {{"render.samples", "0", "--spp"}}) ==
        "--spp (render.samples): expected a whole number from 1 to 65,535, got 0");
  CHECK(refusal("- just\n- a list\n") == "test.yaml: expected a mapping of keys at the top");
  CHECK(refusal("objects: [").rfind("test.yaml: not valid YAML or JSON", 0) == 0);
  CHECK(refusal("objects:\n  - {name: vase, builtin: sofa2, materials: {all: [wood]}}\n")
            .rfind("test.yaml: objects.0.builtin: expected one of \"basket\", ", 0) == 0);
  CHECK(refusal("objects:\n  - {name: vase, builtin: vase, mesh: a.glb, materials: {all: [wood]}}\n")
            .find("give exactly one of `builtin`") != std::string::npos);
  // Quoted, a value is text, in YAML as in JSON; unquoted, it is what its key reads.
  CHECK(refusal(kOneVase + "render: {samples: \"64\"}\n") ==
        "test.yaml: render.samples: expected a whole number from 1 to 65,535, got \"64\"");
  CHECK(refusal(kOneVase + "render: {samples: 64.0}\n").empty());
  // The renderer's range for the ambient occlusion error, stated once (its declaration): refused
  // here before anything is written, not by the first render. A dataset refuses 0 (render_keys.h).
  CHECK(refusal(kOneVase, {{"render.ambient_occlusion.error", "0.0005", "--ao-error"}}) ==
        "--ao-error (render.ambient_occlusion.error): expected a number from 0.001 to 0.5, got 0.0005");
  CHECK(refusal(kOneVase, {{"render.ambient_occlusion.error", "0.001", "--ao-error"}}).empty());
  // An object's Auto Smooth angle is a mesh's, in (0, 180].
  CHECK(refusal("objects:\n  - {name: vase, builtin: vase, auto_smooth_deg: 30, materials: {all: [wood/raw:1]}}\n")
            .find("only a mesh file's faces can be smoothed") != std::string::npos);
  // An alias inside the list it names nests without end; it is refused, not followed.
  CHECK(refusal(kOneVase + "camera: {grid: &a [*a, 1]}\n").find("nest deeper than 256 levels") != std::string::npos);
}

TEST_CASE("An object's uv_scale is the UV pass's density scale, only where the pass runs", "[dataset]") {
  const std::string pillow = "objects:\n  - {name: pillow, builtin: pillow, uv_pass: always, uv_scale: 0.5, "
                             "materials: {all: [fabric/twill:1]}}\n";
  const DatasetConfig config = parse_config(pillow, "test.yaml", fs::current_path(), {});
  CHECK(config.objects[0].uv_scales == std::vector<double>{0.5});
  CHECK(matdataset::check_before_writing(config).empty());
  CHECK(refusal(pillow, {{"objects.0.uv_scale", "0", "--set objects.0.uv_scale=0"}}) ==
        "--set objects.0.uv_scale=0 (objects.0.uv_scale): expected a number from 0.01 to 100, got 0");
  CHECK(refusal("objects:\n  - {name: vase, builtin: vase, uv_pass: never, uv_scale: 2, materials: {all: [wood/raw:1]}}\n") ==
        "test.yaml: objects.0.uv_scale: the UV pass never runs (uv_pass: never), so there is no texel density to scale");
  // A built-in object has UVs of its own: when_missing (the default) does not run the pass.
  const DatasetConfig builtin_uvs =
      parse_config("objects:\n  - {name: vase, builtin: vase, uv_scale: 2, materials: {all: [wood/raw:1]}}\n",
                   "test.yaml", fs::current_path(), {});
  try {
    matdataset::check_before_writing(builtin_uvs);
    FAIL("no refusal");
  } catch (const matbase::InputError& e) {
    CHECK(std::string(e.what()).find("objects.0.uv_scale: the mesh has texture coordinates of its own") !=
          std::string::npos);
  }
}
