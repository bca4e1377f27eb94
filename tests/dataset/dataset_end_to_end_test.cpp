// make_dataset end to end on a tiny dataset: the built app run on a configuration with two
// MatSynth-style material folders of constant maps (written here as real PNGs), its output read
// back map by map with OpenImageIO and with libmatdataset's reader, and checked by --verify.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "matbase/pi.h"
#include "matdataset/format/dataset_index.h"
#include "matdataset/format/decoded_image.h"
#include "matdataset/format/sample_reader.h"
#include "matgeom/builtin/builtin_objects.h"
#include "matgeom/builtin/example_scan.h"
#include "matgeom/io/mesh_io.h"
#include "matgeom/mesh_parts.h"
#include "support/replica_ply.h"

namespace fs = std::filesystem;

namespace {

constexpr int kSize = 48;
// The folders' constant roughness and metallic, as 8-bit codes: the dataset must store the same.
constexpr int kWoodRoughness = 51, kMetalRoughness = 204;

void write_constant_png(const fs::path& path, int channels, const std::vector<uint8_t>& value) {
  std::vector<uint8_t> pixels;
  for (int p = 0; p < 8 * 8; ++p) pixels.insert(pixels.end(), value.begin(), value.end());
  OIIO::ImageSpec spec(8, 8, channels, OIIO::TypeDesc::UINT8);
  auto out = OIIO::ImageOutput::create(path.string());
  REQUIRE(out);
  REQUIRE(out->open(path.string(), spec));
  REQUIRE(out->write_image(OIIO::TypeDesc::UINT8, pixels.data()));
  REQUIRE(out->close());
}

void write_material_folder(const fs::path& folder, const std::vector<uint8_t>& base, uint8_t roughness,
                           uint8_t metallic) {
  fs::create_directories(folder);
  write_constant_png(folder / "basecolor.png", 3, base);
  write_constant_png(folder / "roughness.png", 1, {roughness});
  write_constant_png(folder / "metallic.png", 1, {metallic});
}

// The stored 8-bit code of a value libmatlearn's decode read.
int code(const matbase::FloatImage& map, int x, int y, int c) { return static_cast<int>(std::lround(map.at(x, y, c) * 255.0f)); }

// Runs make_dataset; its standard error goes to `errors` when given.
int run(const std::string& arguments, const fs::path& errors = "/dev/null") {
  const std::string command =
      std::string(MATPREDICT_MAKE_DATASET) + " " + arguments + " > /dev/null 2> " + errors.string();
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string text_of(const fs::path& file) {
  std::ifstream in(file);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// make_dataset --verify's exit code; what it printed goes to `report`.
int verify(const fs::path& root, const fs::path& report) {
  const std::string command =
      std::string(MATPREDICT_MAKE_DATASET) + " --verify " + root.string() + " > " + report.string() + " 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Replaces the first occurrence of `from` in a text file.
void replace_in_file(const fs::path& file, const std::string& from, const std::string& to) {
  std::string text = text_of(file);
  const size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  text.replace(at, from.size(), to);
  std::ofstream(file) << text;
}

// The tiny dataset, made once for all the checks below.
const fs::path& tiny_dataset() {
  static const fs::path root = [] {
    const fs::path dir = fs::temp_directory_path() / "matpredict_dataset_end_to_end";
    fs::remove_all(dir);
    write_material_folder(dir / "materials" / "wood_flat", {150, 90, 40}, kWoodRoughness, 0);
    write_material_folder(dir / "materials" / "metal_flat", {200, 200, 205}, kMetalRoughness, 255);
    std::ofstream(dir / "tiny.yaml") << R"(objects:
  - name: chair
    builtin: chair
    slots: {seat: [seat]}
    materials:
      seat: [{matsynth: materials/wood_flat}]
      rest: [{matsynth: materials/metal_flat}, {matsynth: materials/wood_flat}]
  - name: vase
    builtin: vase
    materials: {all: [{matsynth: materials/metal_flat}]}
camera: {grid: [2, 3]}
render: {resolution: 48, samples: 8}
)";
    REQUIRE(run("--config " + (dir / "tiny.yaml").string() + " --output " + (dir / "out").string()) == 0);
    return dir / "out";
  }();
  return root;
}

}  // namespace

TEST_CASE("The tiny dataset has every frame of the plan, and --verify finds no problem", "[dataset]") {
  const fs::path& root = tiny_dataset();
  // chair: 1 x 2 variants, vase: 1; 2 x 3 views each.
  const std::vector<matdataset::SampleId> samples = matdataset::index_dataset(root);
  CHECK(samples.size() == 18);
  CHECK(samples.front().str() == "chair/var000/000");
  CHECK(samples.back().str() == "vase/var000/005");
  CHECK(run("--verify " + root.string()) == 0);
  for (const char* split : {"object_disjoint_v1", "variance_disjoint_v1", "material_disjoint_v1", "paper_random_v1"}) {
    const matdataset::SplitFile file = matdataset::read_split_file(root / "config" / (std::string(split) + ".yaml"));
    CHECK(file.train.size() + file.val.size() + file.test.size() == 18);
  }
}

// Sets the depth (R, G and B) of the first `values.size()` covered pixels of a depth map.
void damage_depth(const fs::path& file, const std::vector<float>& values) {
  const matbase::FloatImage depth = matdataset::decode(file);
  std::vector<float> pixels = depth.values;
  size_t next = 0;
  for (size_t p = 0; p < pixels.size() / 4 && next < values.size(); ++p)
    if (pixels[4 * p + 3] > 0.0f) {
      for (int c = 0; c < 3; ++c) pixels[4 * p + static_cast<size_t>(c)] = values[next];
      ++next;
    }
  REQUIRE(next == values.size());
  OIIO::ImageSpec spec(depth.width, depth.height, 4, OIIO::TypeDesc::FLOAT);
  auto out = OIIO::ImageOutput::create(file.string());
  REQUIRE(out);
  REQUIRE(out->open(file.string(), spec));
  REQUIRE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
  REQUIRE(out->close());
}

TEST_CASE("--verify finds damaged depth, segmentation maps that contradict the labels, and split files that "
          "contradict the dataset", "[dataset]") {
  const fs::path dir = fs::temp_directory_path() / "matpredict_dataset_verify_records";
  fs::remove_all(dir);
  fs::copy(tiny_dataset(), dir, fs::copy_options::recursive);
  // Three covered pixels: NaN, 0, and 1 km behind an object a metre across.
  damage_depth(dir / "chair" / "var000" / "depth" / "001.exr", {std::nanf(""), 0.0f, 1000.0f});
  // Labels 4 and 7 (metal and wood) named the other way round.
  replace_in_file(dir / "vase" / "var000" / "material_segmentation_map.json", "\"4\": \"metal\"", "\"4\": \"wood\"");
  replace_in_file(dir / "material_segmentation_map.yaml", "metal: 4", "metal: 7");
  // A split file gone, and one whose counts contradict its lists.
  fs::remove(dir / "config" / "material_disjoint_v1.yaml");
  replace_in_file(dir / "config" / "object_disjoint_v1.yaml", "total: 18", "total: 17");
  // An image of another size, and an albedo whose header declares 60000 x 60000 pixels in 324
  // bytes: both refused from their headers.
  write_constant_png(dir / "chair" / "var001" / "images" / "002.png", 3, {10, 20, 30});
  const fs::path hostile = dir / "chair" / "var001" / "albedo" / "002.png";
  REQUIRE(std::system(("/usr/bin/python3 " + std::string(MATPREDICT_DECLARED_SIZE_PNG) + " 60000 60000 " +
                       hostile.string()).c_str()) == 0);
  // A second object copied in, as a second run into the same folder made it before: in no split.
  fs::copy(dir / "vase", dir / "vase_again", fs::copy_options::recursive);

  const fs::path report = dir / "report.txt";
  CHECK(verify(dir, report) == 1);
  const std::string text = text_of(report);
  INFO(text);
  const std::string depth = (dir / "chair" / "var000" / "depth" / "001.exr").string();
  CHECK_THAT(text, Catch::Contains(depth + ": 1 covered pixels have a depth that is NaN or infinite"));
  CHECK_THAT(text, Catch::Contains(depth + ": 1 covered pixels have a depth of 0 or less"));
  CHECK_THAT(text, Catch::Contains(depth + ": 1 of the object's pixels have a depth outside"));
  CHECK_THAT(text, Catch::Contains((dir / "chair" / "var001" / "images" / "002.png").string() +
                                   ": declares 8 x 8 pixels, but transforms.json says the frames are 48 x 48"));
  CHECK_THAT(text, Catch::Contains(hostile.string() + ": declares 60000 x 60000 pixels, 3.4 GiB of image data"));
  CHECK_THAT(text, Catch::Contains("vase/var000/material_segmentation_map.json: names label 4 \"wood\", but it is metal"));
  CHECK_THAT(text, Catch::Contains("material_segmentation_map.json: material_family_to_id is not the inverse"));
  CHECK_THAT(text, Catch::Contains("material_segmentation_map.yaml: label 7 is given to both metal and wood"));
  CHECK_THAT(text, Catch::Contains((dir / "config" / "material_disjoint_v1.yaml").string() + ": missing"));
  CHECK_THAT(text, Catch::Contains("object_disjoint_v1.yaml: counts.total is 17, but its three lists 18 frames"));
  CHECK_THAT(text, Catch::Contains("paper_random_v1.yaml: 6 frames of the dataset are in none of its lists (the "
                                   "first: vase_again/var000/000)"));
  CHECK_THAT(text, Catch::Contains("lighting_disjoint_v1.yaml: 6 frames of the dataset are in none of its lists"));
  // Nothing else: an undamaged frame, map or file is not reported.
  CHECK_THAT(text, Catch::Contains(": 16 problems"));
}

// Overwrites an image with zeros of the same size, channels and type: a frame without the object.
void zero_image(const fs::path& file) {
  auto in = OIIO::ImageInput::open(file.string());
  REQUIRE(in);
  const OIIO::ImageSpec spec = in->spec();
  in->close();
  std::vector<std::byte> zeros(spec.image_bytes());
  auto out = OIIO::ImageOutput::create(file.string());
  REQUIRE(out);
  REQUIRE(out->open(file.string(), spec));
  REQUIRE(out->write_image(spec.format, zeros.data()));
  REQUIRE(out->close());
}

TEST_CASE("A frame the object is in no pixel of is named by make_dataset and --verify, and 5 km away is refused",
          "[dataset]") {
  const fs::path dir = fs::temp_directory_path() / "matpredict_dataset_empty_frame";
  fs::remove_all(dir);
  fs::copy(tiny_dataset().parent_path(), dir, fs::copy_options::recursive);
  // The label, the depth's coverage and ORM's alpha all say: nothing here.
  const fs::path variant = dir / "out" / "vase" / "var000";
  for (const char* map : {"label/003.png", "depth/003.exr", "ORM/003.png"}) zero_image(variant / map);
  CHECK(verify(dir / "out", dir / "report.txt") == 1);
  const std::string text = text_of(dir / "report.txt");
  INFO(text);
  CHECK_THAT(text, Catch::Contains((variant / "label" / "003.png").string() + ": the object is in no pixel of the frame"));
  CHECK_THAT(text, Catch::Contains(": 1 problems"));
  // make_dataset run again finds every frame complete, and says that one frame shows nothing.
  CHECK(run("--config " + (dir / "tiny.yaml").string() + " --output " + (dir / "out").string(), dir / "errors.txt") == 1);
  CHECK_THAT(text_of(dir / "errors.txt"), Catch::Contains("1 frames show the object in no pixel (the first: vase/var000/003)"));
  // A camera 5 km from a vase would render nothing but background: refused before writing.
  CHECK(run("--objects vase --materials plastic:1 --grid 1x2 --resolution 16 --spp 1 --material-resolution 16 "
            "--set 'camera.radius={rule: fixed, metres: 5000}' --output " + (dir / "far").string(),
            dir / "errors.txt") == 2);
  CHECK_THAT(text_of(dir / "errors.txt"), Catch::Contains("camera.radius: the cameras are 5000 m from objects.0, which is"));
  CHECK_FALSE(fs::exists(dir / "far"));
}

TEST_CASE("A second run with other objects or fewer variants into a folder is refused before anything is written",
          "[dataset]") {
  const fs::path dir = fs::temp_directory_path() / "matpredict_dataset_second_run";
  fs::remove_all(dir);
  const std::string common = "--grid 1x2 --resolution 16 --spp 1 --material-resolution 16 --output " + (dir / "out").string();
  REQUIRE(run("--objects vase --materials plastic:1,wood:2 " + common) == 0);
  const std::string splits = text_of(dir / "out" / "config" / "object_disjoint_v1.yaml");
  CHECK(run("--objects mug --materials plastic:1,wood:2 " + common, dir / "errors.txt") == 2);
  CHECK_THAT(text_of(dir / "errors.txt"), Catch::Contains("holds vase/, which this configuration does not make"));
  CHECK(run("--objects vase --materials plastic:1 " + common, dir / "errors.txt") == 2);
  CHECK_THAT(text_of(dir / "errors.txt"), Catch::Contains("holds vase/var001/, which this configuration does not make"));
  CHECK(run("--objects vase --materials plastic:1,wood:3 " + common, dir / "errors.txt") == 2);
  CHECK_THAT(text_of(dir / "errors.txt"), Catch::Contains("var000/metadata.json: this variant was made with other settings"));
  CHECK(text_of(dir / "out" / "config" / "object_disjoint_v1.yaml") == splits);
  CHECK_FALSE(fs::exists(dir / "out" / "mug"));
  CHECK(verify(dir / "out", dir / "report.txt") == 0);
}

TEST_CASE("ORM's G is the material's roughness and the label its class at every covered pixel", "[dataset]") {
  const fs::path& root = tiny_dataset();
  size_t interior = 0;
  for (const matdataset::SampleId& id : matdataset::index_dataset(root)) {
    const fs::path variant = root / id.object / id.variant;
    const matbase::FloatImage orm = matdataset::decode(variant / "ORM" / (id.stem + ".png"));
    const matbase::FloatImage label = matdataset::decode(variant / "label" / (id.stem + ".png"));
    const matbase::FloatImage depth = matdataset::decode(variant / "depth" / (id.stem + ".exr"));
    REQUIRE((orm.width == kSize && label.width == kSize && depth.width == kSize));
    // The classes metadata.json says the variant uses.
    const nlohmann::json metadata = nlohmann::json::parse(std::ifstream(variant / "metadata.json"));
    std::set<int> used;
    for (const auto& [slot, material] : metadata["used_materials"].items()) used.insert(material["label_id"].get<int>());
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        const int l = code(label, x, y, 0);
        INFO(id.str() << " pixel (" << x << ", " << y << ") label " << l);
        // The label marks exactly the covered pixels, and only with the variant's classes.
        CHECK((l > 0) == (depth.at(x, y, 3) > 0.0f));
        if (l == 0) continue;
        CHECK(used.count(l) == 1);
        CHECK((l == 7 || l == 4));
        // Where one material covers the pixel and its neighbours, the maps hold its constants:
        // 8-bit codes exactly (no dither, no blend with the background).
        bool uniform = x > 0 && y > 0 && x + 1 < kSize && y + 1 < kSize;
        for (int dy = -1; uniform && dy <= 1; ++dy)
          for (int dx = -1; uniform && dx <= 1; ++dx) uniform = code(label, x + dx, y + dy, 0) == l;
        if (!uniform) continue;
        ++interior;
        CHECK(code(orm, x, y, 1) == (l == 7 ? kWoodRoughness : kMetalRoughness));
        CHECK(code(orm, x, y, 2) == (l == 7 ? 0 : 255));
        CHECK(code(orm, x, y, 3) == 255);
      }
  }
  CHECK(interior > 1000);
}

TEST_CASE("libmatdataset's reader reads the dataset: roughness is ORM's G, the mask is the label", "[dataset]") {
  const fs::path& root = tiny_dataset();
  matdataset::SampleSettings settings;
  settings.size = kSize;  // as stored: no resize
  for (const matdataset::SampleId& id : matdataset::index_dataset(root)) {
    const matdataset::MaterialSample sample = matdataset::read_sample(root, id, settings);
    const matbase::FloatImage orm = matdataset::decode(root / id.object / id.variant / "ORM" / (id.stem + ".png"));
    const matbase::FloatImage label = matdataset::decode(root / id.object / id.variant / "label" / (id.stem + ".png"));
    REQUIRE(sample.has_label);
    size_t mismatches = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        const size_t p = static_cast<size_t>(y * kSize + x);
        mismatches += std::abs(sample.roughness.values[p] - orm.at(x, y, 1)) > 1e-6f ? 1 : 0;
        mismatches += (sample.mask[p] > 0) != (code(label, x, y, 0) > 0) ? 1 : 0;
      }
    INFO(id.str());
    CHECK(mismatches == 0);
  }
}

TEST_CASE("transforms.json places each camera on the grid's sphere, looking at its centre", "[dataset]") {
  const fs::path variant = tiny_dataset() / "chair" / "var000";
  const nlohmann::json transforms = nlohmann::json::parse(std::ifstream(variant / "transforms.json"));
  const nlohmann::json grid =
      nlohmann::json::parse(std::ifstream(variant / "metadata.json"))["provenance"]["camera"]["grid"];
  CHECK(transforms["w"] == kSize);
  CHECK(transforms["fl_x"].get<double>() == Approx(0.5 * kSize / std::tan(0.5 * 39.597752 * matbase::kPi / 180)));
  REQUIRE(transforms["frames"].size() == 6);
  for (const nlohmann::json& frame : transforms["frames"]) {
    const nlohmann::json& m = frame["transform_matrix"];
    double distance2 = 0.0, along = 0.0;
    for (int r = 0; r < 3; ++r) {
      const double to_centre = grid["center"][r].get<double>() - m[r][3].get<double>();
      distance2 += to_centre * to_centre;
      along += to_centre * -m[r][2].get<double>();  // the camera looks down its -Z
    }
    CHECK(std::sqrt(distance2) == Approx(grid["radius"].get<double>()));
    CHECK(along == Approx(std::sqrt(distance2)));
    CHECK(m[3][3].get<double>() == 1.0);
  }
}

TEST_CASE("A folder made with other settings is refused, not mixed with new frames", "[dataset]") {
  const fs::path dir = fs::temp_directory_path() / "matpredict_dataset_other_settings";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string common = "--objects vase --materials plastic:1 --grid 1x2 --resolution 16 --material-resolution 16 "
                             "--output " + (dir / "out").string();
  REQUIRE(run(common + " --spp 2") == 0);
  const std::string before = text_of(dir / "out" / "vase" / "var000" / "metadata.json");
  CHECK(run(common + " --spp 3", dir / "errors.txt") == 2);
  CHECK_THAT(text_of(dir / "errors.txt"), Catch::Contains("this variant was made with other settings"));
  CHECK(text_of(dir / "out" / "vase" / "var000" / "metadata.json") == before);
  CHECK(run(common + " --spp 2") == 0);  // the same settings resume
}

// A frame's sample counts, decoded from its 16-bit map.
std::vector<int> sample_counts(const fs::path& variant, const std::string& stem) {
  const matbase::FloatImage map = matdataset::decode(variant / "sample_count" / (stem + ".png"));
  REQUIRE(map.channels == 1);
  std::vector<int> counts;
  for (const float v : map.values) counts.push_back(static_cast<int>(std::lround(v * 65535.0f)));
  return counts;
}

TEST_CASE("Every pixel of a fixed-sample dataset took the samples the render states", "[dataset]") {
  const fs::path& root = tiny_dataset();
  for (const matdataset::SampleId& id : matdataset::index_dataset(root))
    for (const int count : sample_counts(root / id.object / id.variant, id.stem)) REQUIRE(count == 8);
}

TEST_CASE("With a noise threshold, pixels stop where the image has converged", "[dataset]") {
  // Threshold 0.05: Cycles' automatic minimum is ceil(16 / 0.05^0.3) = 40 samples, so pixels are
  // first checked after 48; the bare background has no noise and stops there. Denoised too: the
  // filter changes the image only.
  const fs::path dir = fs::temp_directory_path() / "matpredict_dataset_adaptive";
  fs::remove_all(dir);
  REQUIRE(run("--objects vase --materials plastic:1 --grid 1x2 --resolution 40 --material-resolution 16 --spp 256 "
              "--noise-threshold 0.05 --denoise filter --output " + (dir / "out").string()) == 0);
  CHECK(run("--verify " + (dir / "out").string()) == 0);
  const fs::path variant = dir / "out" / "vase" / "var000";
  const nlohmann::json render = nlohmann::json::parse(std::ifstream(variant / "metadata.json"))["provenance"]["render"];
  CHECK(render["noise_threshold"].get<double>() == 0.05);
  CHECK(render["fewest_samples"].get<int>() == 48);
  CHECK(render["denoise"] == "filter");
  size_t object_pixels = 0;
  double object_samples = 0.0;
  for (const char* stem : {"000", "001"}) {
    const std::vector<int> counts = sample_counts(variant, stem);
    const matbase::FloatImage depth = matdataset::decode(variant / "depth" / (std::string(stem) + ".exr"));
    for (int y = 1; y + 1 < depth.height; ++y)
      for (int x = 1; x + 1 < depth.width; ++x) {
        const int count = counts[static_cast<size_t>(y * depth.width + x)];
        REQUIRE(count >= 48);
        REQUIRE(count <= 256);
        bool background = true, object = true;  // the whole 3 x 3 neighbourhood
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const float coverage = depth.at(x + dx, y + dy, 3);
            background &= coverage == 0.0f;
            object &= coverage == 1.0f;
          }
        if (background) CHECK(count == 48);
        if (object) ++object_pixels, object_samples += count;
      }
  }
  REQUIRE(object_pixels > 50);
  CHECK(object_samples / static_cast<double>(object_pixels) > 64.0);
}

TEST_CASE("Images are exposed by the grey-card rule unless an exposure is given", "[dataset]") {
  // A near-white plaster vase: with the rule, the lit object sits well inside the 8-bit range
  // (it rendered at about code 62 at exposure 0); a number given instead is applied as it is.
  const fs::path dir = fs::temp_directory_path() / "matpredict_dataset_exposure";
  fs::remove_all(dir);
  write_material_folder(dir / "materials" / "plaster_white", {240, 240, 240}, 200, 0);
  std::ofstream(dir / "white.yaml")
      << "objects: [{builtin: vase, materials: {all: [{matsynth: materials/plaster_white}]}}]\n"
         "camera: {grid: [1, 2]}\nrender: {resolution: 40, samples: 16}\n";
  struct Exposed {
    double stops = 0.0;
    std::string rule;
    double median_code = 0.0;
    double clipped = 0.0;  // fraction of the object's pixels with a channel at 255
  };
  auto make = [&](const std::string& name, const std::string& options) {
    REQUIRE(run("--config " + (dir / "white.yaml").string() + " --output " + (dir / name).string() + " " + options) == 0);
    const fs::path variant = dir / name / "vase" / "var000";
    const nlohmann::json render = nlohmann::json::parse(std::ifstream(variant / "metadata.json"))["provenance"]["render"];
    Exposed exposed{render["exposure_stops"].get<double>(), render["exposure_rule"].get<std::string>()};
    std::vector<int> codes;
    size_t clipped = 0;
    for (const char* stem : {"000", "001"}) {
      const matbase::FloatImage image = matdataset::decode(variant / "images" / (std::string(stem) + ".png"));
      for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
          if (image.at(x, y, 3) < 1.0f) continue;
          codes.push_back(code(image, x, y, 1));
          for (int c = 0; c < 3; ++c)
            if (code(image, x, y, c) == 255) {
              ++clipped;
              break;
            }
        }
    }
    REQUIRE(codes.size() > 100);
    std::nth_element(codes.begin(), codes.begin() + static_cast<long>(codes.size() / 2), codes.end());
    exposed.median_code = codes[codes.size() / 2];
    exposed.clipped = static_cast<double>(clipped) / static_cast<double>(codes.size());
    return exposed;
  };
  const Exposed automatic = make("auto", ""), given = make("given", "--exposure 0");
  CAPTURE(automatic.stops, automatic.median_code, automatic.clipped, given.median_code);
  CHECK(automatic.rule.rfind("grey card", 0) == 0);
  CHECK(automatic.stops > 0.5);
  CHECK(automatic.median_code > 110.0);
  CHECK(automatic.median_code < 245.0);
  CHECK(automatic.clipped < 0.05);
  CHECK(given.rule == "configured");
  CHECK(given.stops == 0.0);
  CHECK(given.median_code < automatic.median_code);
}

TEST_CASE("A material folder with no class is refused before anything is written", "[dataset]") {
  const fs::path dir = fs::temp_directory_path() / "matpredict_dataset_no_class";
  fs::remove_all(dir);
  write_material_folder(dir / "materials" / "mystery", {100, 100, 100}, 128, 0);
  std::ofstream(dir / "no_class.yaml") << "objects: [{builtin: vase, materials: {all: [{matsynth: materials/mystery}]}}]\n";
  CHECK(run("--config " + (dir / "no_class.yaml").string() + " --output " + (dir / "out").string(),
            dir / "errors.txt") == 2);
  CHECK_THAT(text_of(dir / "errors.txt"),
             Catch::Contains("objects.0.materials.all: material folder \"materials/mystery\" has no material class"));
  CHECK_FALSE(fs::exists(dir / "out"));
}

TEST_CASE("The paper's texture-target layout: cropped screenshots on white and flat reference maps", "[dataset]") {
  const fs::path dir = fs::temp_directory_path() / "matpredict_dataset_paper_layout";
  fs::remove_all(dir);
  write_material_folder(dir / "materials" / "wood_flat", {150, 90, 40}, kWoodRoughness, 0);
  write_material_folder(dir / "materials" / "metal_flat", {200, 200, 205}, kMetalRoughness, 255);
  std::ofstream(dir / "paper.yaml") << R"(objects:
  - {builtin: vase, materials: {all: [{matsynth: materials/wood_flat}, {matsynth: materials/metal_flat}]}}
camera: {grid: [1, 3]}
render: {resolution: 40, samples: 4}
paper_texture_layout: true
)";
  REQUIRE(run("--config " + (dir / "paper.yaml").string() + " --output " + (dir / "out").string()) == 0);
  const fs::path root = dir / "out" / "paper_textures";
  REQUIRE(matdataset::dataset_layout(root) == matdataset::DatasetLayout::paper_textures);
  const std::vector<matdataset::SampleId> samples = matdataset::index_dataset(root);
  REQUIRE(samples.size() == 6);
  CHECK(samples.front().str() == "vase/metal_flat/000");
  // The references are the folders' constant maps.
  const matbase::FloatImage roughness = matdataset::decode(root / "ground_truth_roughness" / "wood_flat.png");
  CHECK(code(roughness, 0, 0, 0) == kWoodRoughness);
  CHECK(code(roughness, 7, 7, 2) == kWoodRoughness);
  CHECK(code(matdataset::decode(root / "ground_truth_metallic" / "metal_flat.png"), 3, 3, 1) == 255);
  CHECK(code(matdataset::decode(root / "ground_truth_basecolour" / "wood_flat.png"), 0, 0, 0) == 150);
  for (const matdataset::SampleId& id : samples) {
    INFO(id.str());
    const matbase::FloatImage shot = matdataset::decode(root / "rendered_cropped" / id.object / id.variant / (id.stem + ".png"));
    // Square, cropped (smaller than the frame or the frame itself), white in the corners.
    CHECK(shot.width == shot.height);
    CHECK(shot.width <= 44);
    CHECK(shot.channels == 3);
    CHECK(code(shot, 0, 0, 0) == 255);
    CHECK(code(shot, shot.width - 1, shot.height - 1, 1) == 255);
    matdataset::SampleSettings settings;
    settings.size = 16;
    const matdataset::MaterialSample sample = matdataset::read_sample(root, id, settings);
    CHECK(sample.roughness.values[0] == Approx((id.variant == "wood_flat" ? kWoodRoughness : kMetalRoughness) / 255.0));
  }
  // The repository layout is there as well, and the resumed run finds every frame whole.
  CHECK(matdataset::index_dataset(dir / "out").size() == 6);
  CHECK(run("--verify " + (dir / "out").string()) == 0);
  fs::remove(root / "rendered_cropped" / "vase" / "wood_flat" / "001.png");
  REQUIRE(run("--config " + (dir / "paper.yaml").string() + " --output " + (dir / "out").string()) == 0);
  CHECK(fs::is_regular_file(root / "rendered_cropped" / "vase" / "wood_flat" / "001.png"));
}

namespace {

// The dataset `config` makes in the temporary folder `name`, made once for all the checks below.
fs::path made_dataset(const std::string& config, const std::string& name) {
  static std::map<std::string, fs::path> made;
  if (const auto found = made.find(name); found != made.end()) return found->second;
  const fs::path folder = fs::temp_directory_path() / name;
  fs::remove_all(folder);
  REQUIRE(run("--config " + config + " --output " + folder.string() + " --threads 2") == 0);
  return made.emplace(name, folder).first->second;
}

// Every image of a dataset, in order.
std::vector<fs::path> images_of(const fs::path& root) {
  std::vector<fs::path> images;
  for (const auto& entry : fs::recursive_directory_iterator(root))
    if (entry.path().parent_path().filename() == "images") images.push_back(entry.path());
  std::sort(images.begin(), images.end());
  return images;
}

// The lighting configuration's dataset.
fs::path lit_dataset() { return made_dataset(MATPREDICT_LIT_CONFIG, "matpredict_lit_dataset"); }
std::vector<fs::path> lit_images() { return images_of(lit_dataset()); }

// How many channel values of a dataset image render_object --dataset-frame gives otherwise,
// rendered into `again`. The dataset's images are RGBA; render_object writes an opaque frame (a
// visible environment) as RGB, whose alpha is 1.
int differing_when_rendered_again(const fs::path& image, const fs::path& again) {
  const std::string command = std::string(MATPREDICT_RENDER_OBJECT) + " --dataset-frame " + image.string() +
                              " --threads 1 --output " + again.string() + " > /dev/null 2>&1";
  REQUIRE(std::system(command.c_str()) == 0);
  const matbase::FloatImage dataset = matdataset::decode(image);
  const matbase::FloatImage rendered = matdataset::decode(again / "view_color.png");
  REQUIRE(dataset.width == rendered.width);
  REQUIRE(dataset.height == rendered.height);
  int differing = 0;
  for (int y = 0; y < dataset.height; ++y)
    for (int x = 0; x < dataset.width; ++x)
      for (int c = 0; c < 4; ++c)
        differing += code(dataset, x, y, c) != (c < rendered.channels ? code(rendered, x, y, c) : 255);
  return differing;
}

}  // namespace

TEST_CASE("Every frame under varied light renders again from its records: render_object --dataset-frame gives "
          "the dataset's image",
          "[dataset]") {
  const std::vector<fs::path> images = lit_images();
  REQUIRE(images.size() == 36);
  std::set<std::string> setups;
  for (size_t k = 0; k < images.size(); ++k) {
    INFO(images[k]);
    CHECK(differing_when_rendered_again(images[k], fs::temp_directory_path() / "matpredict_lit_again" / std::to_string(k)) == 0);
  }
  // Each frame's transforms.json entry names its setup.
  for (const auto& entry : fs::recursive_directory_iterator(lit_dataset()))
    if (entry.path().filename() == "transforms.json") {
      const nlohmann::json transforms = nlohmann::json::parse(text_of(entry.path()));
      for (const nlohmann::json& frame : transforms["frames"]) setups.insert(frame["lighting"]["setup"].get<std::string>());
    }
  CHECK(setups.size() == 5);
  for (const char* setup : {"rig", "environment", "city_sun", "spot+area+point", "sky"}) CHECK(setups.count(setup) == 1);
  const std::string missing = std::string(MATPREDICT_RENDER_OBJECT) + " --dataset-frame " +
                              (lit_dataset() / "vase" / "var000" / "999").string() + " > /dev/null 2>&1";
  const int status = std::system(missing.c_str());
  CHECK((WIFEXITED(status) ? WEXITSTATUS(status) : -1) == 2);
}

TEST_CASE("The grey-card rule exposes the object well under every setup: no frame black or clipped", "[dataset]") {
  for (const fs::path& image : lit_images()) {
    const matbase::FloatImage color = matdataset::decode(image);
    const matbase::FloatImage label =
        matdataset::decode(image.parent_path().parent_path() / "label" / image.filename());
    std::vector<double> luma;
    int clipped = 0;
    for (int y = 0; y < color.height; ++y)
      for (int x = 0; x < color.width; ++x) {
        if (label.at(x, y, 0) <= 0.0f) continue;
        const double r = color.at(x, y, 0), g = color.at(x, y, 1), b = color.at(x, y, 2);
        luma.push_back(0.2126 * r + 0.7152 * g + 0.0722 * b);
        clipped += std::max({r, g, b}) >= 1.0;
      }
    REQUIRE(luma.size() > 20);
    std::sort(luma.begin(), luma.end());
    const double median = luma[luma.size() / 2], lit = luma[luma.size() * 9 / 10];
    INFO(image << ": the object's median sRGB value " << median << ", its 90th percentile " << lit << ", "
               << clipped << " of " << luma.size() << " pixels clipped");
    // Mid-grey in sRGB is 0.46; the rule puts a grey card a stop below it. A mug seen from above
    // shows mostly its unlit inside and a metal mostly the black it reflects, so the lit tenth
    // of the object is held to being seen, and the middle of it to being below white.
    CHECK(lit > 0.15);
    CHECK(median < 0.8);
    CHECK(clipped < static_cast<int>(luma.size() / 4));
  }
}

TEST_CASE("The lighting split holds lighting out: no environment image and no lamp setup lights frames of two "
          "splits",
          "[dataset]") {
  // Each frame's lighting as transforms.json records it: its environment image, else its setup.
  std::map<std::string, std::string> lighting_of;
  for (const auto& entry : fs::recursive_directory_iterator(lit_dataset()))
    if (entry.path().filename() == "transforms.json") {
      const fs::path variant = entry.path().parent_path();
      const std::string prefix = variant.parent_path().filename().string() + "/" + variant.filename().string() + "/";
      const nlohmann::json transforms = nlohmann::json::parse(text_of(entry.path()));
      for (const nlohmann::json& frame : transforms["frames"]) {
        const std::string stem = fs::path(frame["file_path"].get<std::string>()).stem().string();
        lighting_of[prefix + stem] = frame["envmap"].is_null() ? "setup " + frame["lighting"]["setup"].get<std::string>()
                                                               : "image " + frame["envmap"].dump();
      }
    }
  REQUIRE(lighting_of.size() == 36);
  const matdataset::SplitFile split = matdataset::read_split_file(lit_dataset() / "config" / "lighting_disjoint_v1.yaml");
  CHECK(split.strategy == "lighting_disjoint");
  CHECK(split.train.size() + split.val.size() + split.test.size() == 36);
  CHECK(!split.train.empty());
  CHECK(!split.test.empty());
  std::map<std::string, std::set<std::string>> splits_of;
  for (const auto& [name, list] : {std::pair{"train", &split.train}, {"val", &split.val}, {"test", &split.test}})
    for (const std::string& id : *list) {
      REQUIRE(lighting_of.count(id) == 1);
      splits_of[lighting_of[id]].insert(name);
    }
  // Five setups, the second with four images: eight lightings, of which the draws use several.
  CHECK(splits_of.size() >= 4);
  for (const auto& [lighting, names] : splits_of) {
    INFO(lighting);
    CHECK(names.size() == 1);
  }
}

TEST_CASE("A list of UV scales makes a variant per scale: each recorded, each with its own texture scale", "[dataset]") {
  // The mug: wood then metal, each at scales 0.5 and 2 (var000 to var003).
  const std::vector<double> scales = {0.5, 2.0, 0.5, 2.0};
  for (size_t v = 0; v < scales.size(); ++v) {
    const fs::path variant = lit_dataset() / "mug" / ("var00" + std::to_string(v));
    const nlohmann::json metadata = nlohmann::json::parse(text_of(variant / "metadata.json"));
    CHECK(metadata["provenance"]["object"]["source"]["uv_scale"].get<double>() == scales[v]);
  }
  // The same view of the same wood at the two scales: the grain repeats four times as often at
  // 2 (four times the texels per metre) as at 0.5, so the albedo differs over much of the mug.
  const matbase::FloatImage coarse = matdataset::decode(lit_dataset() / "mug" / "var000" / "albedo" / "002.png");
  const matbase::FloatImage fine = matdataset::decode(lit_dataset() / "mug" / "var001" / "albedo" / "002.png");
  REQUIRE(coarse.width == fine.width);
  int covered = 0, differing = 0;
  for (int y = 0; y < coarse.height; ++y)
    for (int x = 0; x < coarse.width; ++x) {
      if (coarse.at(x, y, 3) < 1.0f || fine.at(x, y, 3) < 1.0f) continue;
      ++covered;
      differing += std::abs(coarse.at(x, y, 0) - fine.at(x, y, 0)) > 2.0f / 255.0f;
    }
  REQUIRE(covered > 50);
  CHECK(differing > covered / 4);
}

namespace {

// The dataset with surroundings (room.yaml): a floor, a box room and a cyclorama.
fs::path room_dataset() { return made_dataset(MATPREDICT_ROOM_CONFIG, "matpredict_room_dataset"); }
std::vector<fs::path> room_images() { return images_of(room_dataset()); }

nlohmann::json json_of(const fs::path& file) { return nlohmann::json::parse(text_of(file)); }

}  // namespace

TEST_CASE("With surroundings the label is the target's first hits alone, the region map says what each pixel is, "
          "and --verify agrees",
          "[dataset]") {
  const std::vector<fs::path> images = room_images();
  // Four objects, two variants each, 2 x 2 views.
  REQUIRE(images.size() == 32);
  const fs::path report = fs::temp_directory_path() / "matpredict_room_verify.txt";
  CHECK(verify(room_dataset(), report) == 0);
  INFO(text_of(report));
  for (const fs::path& image : images) {
    const fs::path variant = image.parent_path().parent_path();
    const std::string stem = image.stem().string();
    INFO(image);
    const matdataset::DecodedIds label = matdataset::decode_ids(variant / "label" / (stem + ".png"));
    const matdataset::DecodedIds region = matdataset::decode_ids(variant / "region" / (stem + ".png"));
    const matbase::FloatImage depth = matdataset::decode(variant / "depth" / (stem + ".exr"));
    size_t target = 0, surroundings = 0, mismatched = 0;
    for (size_t p = 0; p < label.ids.size(); ++p) {
      target += region.ids[p] == 2;
      surroundings += region.ids[p] == 1;
      mismatched += (label.ids[p] > 0) != (region.ids[p] == 2);
      // The data maps cover the surroundings too: depth there is the floor's or the wall's.
      if (region.ids[p] == 1) CHECK(depth.values[4 * p + 3] > 0.0f);
    }
    CHECK(mismatched == 0);
    CHECK(target > 20);         // the object is the subject
    CHECK(surroundings > 20);   // and the floor is seen around it
    const nlohmann::json transforms = json_of(variant / "transforms.json");
    CHECK(transforms["frames"][0]["file_path_region"] == "region/" + transforms["frames"][0]["file_path"].get<std::string>().substr(7));
  }
  // The objects alone in empty space have no region map, and old readers' folders are as they were.
  const nlohmann::json metadata = json_of(room_dataset() / "vase" / "var000" / "metadata.json");
  const nlohmann::json& structure = metadata["render_summary"]["output_structure"];
  CHECK(std::find(structure.begin(), structure.end(), "region") != structure.end());
}

TEST_CASE("Surroundings are drawn per variant and recorded: the room, its materials, and a frame renders again from "
          "its records",
          "[dataset]") {
  std::set<std::string> floors;
  for (const char* object : {"vase", "mug", "chair", "lamp"})
    for (const char* variant : {"var000", "var001"}) {
      const nlohmann::json metadata = json_of(room_dataset() / object / variant / "metadata.json");
      const nlohmann::json& surroundings = metadata["provenance"]["surroundings"];
      REQUIRE(surroundings.is_object());
      CHECK(surroundings["kind"] == (std::string(object) == "lamp" ? "distractors" : "floor"));
      floors.insert(surroundings["materials"]["floor"]["name"].get<std::string>());
      const std::string walls = surroundings["room"]["walls"];
      CHECK(walls == (std::string(object) == "mug" ? "box" : std::string(object) == "chair" ? "cyclorama" : "none"));
      CHECK(surroundings["materials"].contains("walls") == (walls != "none"));
    }
  // Library candidates without a seed get one drawn: the eight variants do not all share a floor.
  CHECK(floors.size() >= 3);
  // render_object renders a frame again from its records, bit for bit.
  const std::vector<fs::path> images = room_images();
  for (const size_t k : {size_t{0}, size_t{9}, size_t{14}, size_t{31}}) {
    INFO(images[k]);
    CHECK(differing_when_rendered_again(images[k], fs::temp_directory_path() / "matpredict_room_again" / std::to_string(k)) == 0);
  }
}

TEST_CASE("--verify finds a region map that contradicts the label, and a missing one", "[dataset]") {
  const fs::path copy = fs::temp_directory_path() / "matpredict_room_tampered";
  fs::remove_all(copy);
  fs::copy(room_dataset(), copy, fs::copy_options::recursive);
  const fs::path region = copy / "mug" / "var000" / "region" / "000.png";
  // Every pixel said to be the target: the label disagrees wherever the floor is.
  const int width = 40;
  std::vector<uint8_t> all_target(static_cast<size_t>(width * width), 2);
  OIIO::ImageSpec spec(width, width, 1, OIIO::TypeDesc::UINT8);
  auto out = OIIO::ImageOutput::create(region.string());
  REQUIRE(out);
  REQUIRE(out->open(region.string(), spec));
  REQUIRE(out->write_image(OIIO::TypeDesc::UINT8, all_target.data()));
  REQUIRE(out->close());
  fs::remove(copy / "chair" / "var001" / "region" / "001.png");
  const fs::path report = fs::temp_directory_path() / "matpredict_room_tampered.txt";
  CHECK(verify(copy, report) != 0);
  const std::string text = text_of(report);
  CHECK(text.find("mug/var000/label/000.png: at ") != std::string::npos);
  CHECK(text.find("chair/var001/region/001.png: missing") != std::string::npos);
}

TEST_CASE("Surroundings that cannot be made are refused before the first file, naming the key", "[dataset]") {
  const fs::path dir = fs::temp_directory_path() / "matpredict_room_refusals";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"surroundings: {kind: floor, floor_materials: [granite]}", "surroundings.floor_materials"},
      {"surroundings: {kind: floor}", "floor_materials"},
      {"surroundings: {kind: floor, floor_materials: [wood], walls: box}", "wall_materials"},
      {"surroundings: {kind: floor, floor_materials: [wood], walls: cyclorama, wall_materials: [plaster], ceiling: "
       "true}",
       "surroundings.ceiling"},
      {"surroundings: {kind: floor, floor_materials: [{matsynth: nowhere}]}", "nowhere"},
      {"surroundings: {kind: floor, floor_materials: [wood], size: 0.5}", "surroundings.size"},
      {"surroundings: {kind: sand}", "surroundings.kind"},
  };
  for (size_t k = 0; k < cases.size(); ++k) {
    const fs::path config = dir / ("case" + std::to_string(k) + ".yaml");
    std::ofstream(config) << "objects: [{builtin: vase}]\nmaterials: {all: [wood]}\n" << cases[k].first << "\n";
    const fs::path errors = dir / ("case" + std::to_string(k) + ".txt");
    INFO(cases[k].first);
    CHECK(run("--config " + config.string() + " --output " + (dir / "out").string(), errors) == 2);
    const std::string text = text_of(errors);
    INFO(text);
    CHECK(text.find(cases[k].second) != std::string::npos);
    CHECK_FALSE(fs::exists(dir / "out"));
  }
}

TEST_CASE("Distractors stand around the target, move from frame to frame, and hide no more of it than allowed",
          "[dataset]") {
  std::set<std::string> placements;
  size_t distractor_pixels = 0;
  for (const char* variant : {"var000", "var001"}) {
    const fs::path folder = room_dataset() / "lamp" / variant;
    const nlohmann::json metadata = json_of(folder / "metadata.json");
    const nlohmann::json& slots = metadata["provenance"]["surroundings"]["distractors"]["slots"];
    REQUIRE(slots.size() == 3);
    for (const nlohmann::json& slot : slots) CHECK(slot["object"]["builtin"] != "lamp");
    const nlohmann::json transforms = json_of(folder / "transforms.json");
    for (const nlohmann::json& frame : transforms["frames"]) {
      const nlohmann::json& drawn = frame["surroundings"];
      const size_t count = drawn["distractors"].size();
      CHECK(count >= 2);
      CHECK(count <= 3);
      placements.insert(drawn["distractors"].dump());
      // Kept at the first draw that shows enough of the lamp, or named by make_dataset.
      CHECK(drawn["visible_fraction"].get<double>() >= 0.7);
      CHECK(drawn["enough_visible"] == true);
      const std::string stem = frame["file_path"].get<std::string>().substr(7);
      const matdataset::DecodedIds region = matdataset::decode_ids(folder / "region" / (stem + ".png"));
      const matbase::FloatImage normals = matdataset::decode(folder / "normal_obj" / (stem + ".png"));
      // Surroundings that do not face up: the distractors standing on the floor.
      for (size_t p = 0; p < region.ids.size(); ++p)
        distractor_pixels += region.ids[p] == 1 && 2.0f * normals.values[4 * p + 2] - 1.0f < 0.9f;
    }
  }
  CHECK(placements.size() == 8);  // every frame draws its own
  CHECK(distractor_pixels > 0);
}

namespace {

// The scan configuration (scan.yaml) copied beside the example scan it names, written as Replica
// lays out a scan; the dataset it makes.
fs::path scan_config() {
  const fs::path folder = fs::temp_directory_path() / "matpredict_scan_config";
  if (!fs::exists(folder / "scan" / "mesh_semantic.ply")) {
    fs::create_directories(folder / "scan");
    write_replica_ply(matgeom::example_scan(), (folder / "scan" / "mesh_semantic.ply").string());
  }
  fs::copy_file(MATPREDICT_SCAN_CONFIG, folder / "scan.yaml", fs::copy_options::overwrite_existing);
  return folder / "scan.yaml";
}
fs::path scan_dataset() { return made_dataset(scan_config().string(), "matpredict_scan_dataset"); }

}  // namespace

TEST_CASE("Back in its scan, the target is labelled by its first hits alone, the rest of the scan shows in its own "
          "colours, and every frame renders again",
          "[dataset]") {
  const std::vector<fs::path> images = images_of(scan_dataset());
  REQUIRE(images.size() == 16);  // two objects, two variants, 2 x 2 views
  const fs::path report = fs::temp_directory_path() / "matpredict_scan_verify.txt";
  CHECK(verify(scan_dataset(), report) == 0);
  double lowest_table_fraction = 1.0;
  for (const fs::path& image : images) {
    const fs::path variant = image.parent_path().parent_path();
    const std::string object = variant.parent_path().filename().string(), stem = image.stem().string();
    INFO(image);
    const matdataset::DecodedIds label = matdataset::decode_ids(variant / "label" / (stem + ".png"));
    const matdataset::DecodedIds region = matdataset::decode_ids(variant / "region" / (stem + ".png"));
    const matbase::FloatImage albedo = matdataset::decode(variant / "albedo" / (stem + ".png"));
    size_t target = 0, scan = 0, mismatched = 0;
    double red = 0.0, blue = 0.0;
    for (size_t p = 0; p < label.ids.size(); ++p) {
      target += region.ids[p] == 2;
      mismatched += (label.ids[p] > 0) != (region.ids[p] == 2);
      if (region.ids[p] != 1) continue;
      ++scan;
      red += albedo.values[4 * p];
      blue += albedo.values[4 * p + 2];
    }
    CHECK(mismatched == 0);
    CHECK(target > 20);
    CHECK(scan > 20);
    // Around the vase: the table and the floor in the scan's browns, not Blender's grey.
    if (object == "vase_in_scan") CHECK(red > 1.1 * blue);
    const nlohmann::json transforms = json_of(variant / "transforms.json");
    for (const nlohmann::json& frame : transforms["frames"]) {
      const double fraction = frame["surroundings"]["visible_fraction"];
      CHECK(fraction >= 0.0);
      CHECK(fraction <= 1.0);
      if (object == "table_in_scan") lowest_table_fraction = std::min(lowest_table_fraction, fraction);
    }
    const nlohmann::json metadata = json_of(variant / "metadata.json");
    const nlohmann::json& surroundings = metadata["provenance"]["surroundings"];
    CHECK(surroundings["kind"] == "scan");
    CHECK(surroundings["scan"]["target"] ==
          nlohmann::json::array({object == "vase_in_scan" ? matgeom::kExampleScanVase : matgeom::kExampleScanTable}));
  }
  // The vase on the table hides part of it.
  CHECK(lowest_table_fraction < 0.99);
  for (const size_t k : {size_t{0}, size_t{5}, size_t{10}, size_t{15}}) {
    INFO(images[k]);
    CHECK(differing_when_rendered_again(images[k], fs::temp_directory_path() / "matpredict_scan_again" / std::to_string(k)) == 0);
  }
}

TEST_CASE("A scan that cannot hold its target is refused before the first file, naming the key", "[dataset]") {
  const fs::path dir = fs::temp_directory_path() / "matpredict_scan_refusals";
  fs::remove_all(dir);
  fs::create_directories(dir);
  fs::copy_file(scan_config().parent_path() / "scan" / "mesh_semantic.ply", dir / "scan.ply");
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {"{mesh: scan.ply, surroundings: {kind: scan, target: [object_99]}}",
       {"objects.0.surroundings.target", "object_99", "\"object_1\", \"object_2\""}},
      {"{mesh: scan.ply, surroundings: {kind: scan, target: [object_1, object_2, object_3, object_4, object_5, "
       "object_6, object_7]}}",
       {"objects.0.surroundings.target", "no room is left"}},
      {"{builtin: vase, surroundings: {kind: scan, target: [object_5]}}", {"surroundings", "give the scan"}},
      {"{mesh: scan.ply, surroundings: {kind: scan}}", {"surroundings", "needs `target`"}},
      {"{mesh: scan.ply, surroundings: {kind: scan, target: []}}", {"surroundings.target", "empty list"}},
      {"{mesh: scan.ply, surroundings: {kind: scan, target: [object_5], floor_materials: [wood]}}",
       {"floor_materials"}},
  };
  for (size_t k = 0; k < cases.size(); ++k) {
    const fs::path config = dir / ("case" + std::to_string(k) + ".yaml");
    std::ofstream(config) << "objects: [" << cases[k].first << "]\nmaterials: {all: [wood]}\n";
    const fs::path errors = dir / ("case" + std::to_string(k) + ".txt");
    INFO(cases[k].first);
    CHECK(run("--config " + config.string() + " --output " + (dir / "out").string(), errors) == 2);
    const std::string text = text_of(errors);
    INFO(text);
    for (const std::string& expected : cases[k].second) CHECK(text.find(expected) != std::string::npos);
    CHECK_FALSE(fs::exists(dir / "out"));
  }
}

TEST_CASE("A grid reaching below an object's floor renders only the cameras above it, in shards as whole, and says so",
          "[dataset]") {
  const fs::path dir = fs::temp_directory_path() / "matpredict_under_floor";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "config.yaml")
      << "seed: 2\nobjects:\n  - {builtin: vase, surroundings: {kind: floor, floor_materials: [wood]}}\n"
         "materials: {all: [plastic:1]}\ncamera: {grid: [4, 2], phi_deg: [0, 180], radius: {rule: fixed, metres: 1}}\n"
         "render: {resolution: 24, samples: 4, material_resolution: 16}\n";
  const fs::path said = dir / "said.txt";
  const std::string command = std::string(MATPREDICT_MAKE_DATASET) + " --config " + (dir / "config.yaml").string() +
                              " --output " + (dir / "whole").string() + " > " + said.string() + " 2>&1";
  REQUIRE(std::system(command.c_str()) == 0);
  CHECK_THAT(text_of(said), Catch::Contains("vase: 4 of the grid's 8 cameras are under its floor and left out (4 frames fewer)"));
  const fs::path variant = dir / "whole" / "vase" / "var000";
  std::vector<std::string> stems;
  for (const fs::path& image : images_of(dir / "whole")) stems.push_back(image.stem().string());
  CHECK(stems == std::vector<std::string>{"000", "001", "002", "003"});
  const nlohmann::json transforms = json_of(variant / "transforms.json");
  REQUIRE(transforms["frames"].size() == 4);
  for (const nlohmann::json& frame : transforms["frames"]) {
    // Every camera kept is above the floor at the vase's lowest point, z = 0.
    CHECK(frame["transform_matrix"][2][3].get<double>() > 0.0);
  }
  const nlohmann::json metadata = json_of(variant / "metadata.json");
  CHECK(metadata["provenance"]["camera"]["under_floor"]["grid_views"] == nlohmann::json::array({"004", "005", "006", "007"}));
  CHECK(metadata["provenance"]["render"]["frame_seeds"].size() == 4);
  CHECK(verify(dir / "whole", dir / "report.txt") == 0);
  // Two shards write the same files.
  for (const char* shard : {"0/2", "1/2"})
    REQUIRE(run("--config " + (dir / "config.yaml").string() + " --output " + (dir / "sharded").string() + " --shard " + shard) == 0);
  const std::vector<fs::path> whole = images_of(dir / "whole"), sharded = images_of(dir / "sharded");
  REQUIRE(whole.size() == sharded.size());
  for (size_t k = 0; k < whole.size(); ++k) CHECK(text_of(whole[k]) == text_of(sharded[k]));
  CHECK(text_of(variant / "metadata.json") == text_of(dir / "sharded" / "vase" / "var000" / "metadata.json"));
}

TEST_CASE("In a closed room a lamp outside the walls leaves frames black and make_dataset says so; a ceiling lamp "
          "lights the object, metered in the room",
          "[dataset]") {
  const fs::path dir = fs::temp_directory_path() / "matpredict_ceiling";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string head =
      "seed: 4\nobjects:\n  - {builtin: vase, surroundings: {kind: floor, floor_materials: [wood], walls: box, "
      "wall_materials: [plaster], ceiling: true}}\nmaterials: {all: [ceramic:1]}\ncamera: {grid: [1, 2]}\n"
      "render: {resolution: 32, samples: 16, material_resolution: 16}\n";
  std::ofstream(dir / "outside.yaml") << head << "lights: {setups: [{lamps: [{type: point, at: [[0, 0, 100]]}]}]}\n";
  std::ofstream(dir / "ceiling.yaml") << head << "lights: {setups: [{ceiling: room}]}\n";
  CHECK(run("--config " + (dir / "outside.yaml").string() + " --output " + (dir / "outside").string(), dir / "outside.txt") == 1);
  CHECK_THAT(text_of(dir / "outside.txt"), Catch::Contains("2 frames are black") && Catch::Contains("vase/var000/000"));

  REQUIRE(run("--config " + (dir / "ceiling.yaml").string() + " --output " + (dir / "lit").string(), dir / "lit.txt") == 0);
  for (const fs::path& image : images_of(dir / "lit")) {
    INFO(image);
    const fs::path variant = image.parent_path().parent_path();
    const matbase::FloatImage colour = matdataset::decode(image);
    const matdataset::DecodedIds label = matdataset::decode_ids(variant / "label" / (image.stem().string() + ".png"));
    double sum = 0.0;
    size_t count = 0;
    for (size_t p = 0; p < label.ids.size(); ++p)
      if (label.ids[p] > 0) {
        sum += colour.values[4 * p] + colour.values[4 * p + 1] + colour.values[4 * p + 2];
        count += 3;
      }
    REQUIRE(count > 0);
    // Exposed by the card: the vase neither black nor white (sRGB 0.15 to 0.85 on average).
    CHECK(sum / count > 0.15);
    CHECK(sum / count < 0.85);
    const nlohmann::json transforms = json_of(variant / "transforms.json");
    CHECK(transforms["frames"][0]["lighting"]["setup"] == "ceiling");
    CHECK(transforms["frames"][0]["lighting"]["lights"][0]["type"] == "area");
  }
}

namespace {

// One asset of several: their parts side by side, each in its own material with its images.
matgeom::ObjectAsset scene_of(const std::vector<matgeom::ObjectAsset>& assets) {
  matgeom::ObjectAsset scene;
  std::vector<matgeom::MeshPart> parts;
  for (const matgeom::ObjectAsset& asset : assets) {
    const int offset = static_cast<int>(scene.images.size());
    scene.images.insert(scene.images.end(), asset.images.begin(), asset.images.end());
    for (matmaterial::MaterialInputs material : asset.materials) {
      for (matmaterial::MaterialInput& input : material.inputs)
        if (input.image >= 0) input.image += offset;
      if (material.normal_image >= 0) material.normal_image += offset;
      scene.materials.push_back(material);
    }
    for (matgeom::MeshPart& part : matgeom::split_parts(asset.mesh)) parts.push_back(std::move(part));
  }
  scene.mesh = matgeom::merge_parts(parts);
  return scene;
}

}  // namespace

TEST_CASE("A glTF scene is a scan too: its target parts get the variant's materials, the rest keeps its own textures",
          "[dataset]") {
  const fs::path dir = fs::temp_directory_path() / "matpredict_gltf_scan";
  fs::remove_all(dir);
  fs::create_directories(dir);
  // The built-in vase standing on the built-in table, each in its built-in textured materials.
  const matgeom::ObjectAsset table = matgeom::make_builtin_object("table");
  matgeom::ObjectAsset vase = matgeom::make_builtin_object("vase");
  matgeom::transform_mesh(vase.mesh, glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.0, matgeom::mesh_bounds(table.mesh).upper.z)));
  matgeom::write_object(scene_of({table, vase}), (dir / "scene.glb").string());
  std::ofstream(dir / "config.yaml")
      << "objects:\n  - {name: vase_on_table, mesh: scene.glb, surroundings: {kind: scan, target: [body, glaze_band]}}\n"
         "materials: {all: [plastic:1]}\ncamera: {grid: [1, 2], phi_deg: [40, 70]}\n"
         "render: {resolution: 32, samples: 8, material_resolution: 16}\n";
  REQUIRE(run("--config " + (dir / "config.yaml").string() + " --output " + (dir / "out").string(), dir / "errors.txt") == 0);
  CHECK(verify(dir / "out", dir / "report.txt") == 0);
  const std::vector<fs::path> images = images_of(dir / "out");
  REQUIRE(images.size() == 2);
  for (const fs::path& image : images) {
    INFO(image);
    const fs::path variant = image.parent_path().parent_path();
    const matdataset::DecodedIds region = matdataset::decode_ids(variant / "region" / (image.stem().string() + ".png"));
    const matbase::FloatImage albedo = matdataset::decode(variant / "albedo" / (image.stem().string() + ".png"));
    size_t target = 0;
    std::set<int> table_albedo;  // the table's own textures vary; one drawn constant would not
    for (size_t p = 0; p < region.ids.size(); ++p) {
      target += region.ids[p] == 2;
      if (region.ids[p] == 1) table_albedo.insert(static_cast<int>(std::lround(255.0f * albedo.values[4 * p])));
    }
    CHECK(target > 20);
    CHECK(table_albedo.size() > 5);
    CHECK(differing_when_rendered_again(image, dir / ("again_" + image.stem().string())) == 0);
  }
}
