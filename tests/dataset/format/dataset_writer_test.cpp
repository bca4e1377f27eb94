// Writing the dataset layout (matdataset/format/dataset_writer.h, dataset_splits.h): one frame's maps read
// back from the files with OpenImageIO and with libmatlearn's own reader, the per-variant
// records parsed, and the splits against their independent references: CPython's own
// random.Random, and the split the repository released (docs/matpredict_repository.md, section 5).
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "matdataset/format/dataset_splits.h"
#include "matdataset/format/dataset_writer.h"
#include "matdataset/format/decoded_image.h"
#include "matdataset/format/python_random.h"
#include "matdataset/format/sample_reader.h"

using namespace matdataset;
namespace fs = std::filesystem;

namespace {

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// What `command` prints on stdout.
std::string output_of(const std::string& command) {
  std::string text;
  FILE* pipe = popen(command.c_str(), "r");
  REQUIRE(pipe);
  std::array<char, 4096> buffer{};
  while (const size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe)) text.append(buffer.data(), n);
  REQUIRE(pclose(pipe) == 0);
  return text;
}

// The stored values of an image file, straight as written, and its size.
std::vector<float> stored_values(const fs::path& path, int& width, int& height, int& channels) {
  matbase::FloatImage map = matdataset::decode(path);
  width = map.width;
  height = map.height;
  channels = map.channels;
  return std::move(map.values);
}

constexpr int kWidth = 5, kHeight = 4;

// A frame whose pixel p = y * 5 + x: covered fully on the left three columns, a quarter in
// column 3, not at all in column 4. Every parameter differs by pixel.
matdataset::FrameMaps test_frame() {
  matdataset::FrameMaps maps;
  maps.width = kWidth;
  maps.height = kHeight;
  const size_t n = kWidth * kHeight;
  for (size_t p = 0; p < n; ++p) {
    const size_t x = p % kWidth;
    const float coverage = x < 3 ? 1.0f : x == 3 ? 0.25f : 0.0f;
    const bool hit = coverage > 0.0f;
    maps.coverage.push_back(coverage);
    for (int c = 0; c < 3; ++c) {
      maps.color.push_back(0.5f * coverage);  // premultiplied, as rendered
      maps.base_color.push_back(hit ? 0.2f : 0.0f);
    }
    maps.roughness.push_back(hit ? 0.05f * static_cast<float>(p) : 0.0f);
    maps.metallic.push_back(hit ? 1.0f : 0.0f);
    maps.ambient_occlusion.push_back(hit ? 0.75f : 0.0f);
    const std::array<float, 3> n_world = {0.6f, 0.0f, 0.8f}, n_tangent = {0.0f, 0.0f, 1.0f};
    for (int c = 0; c < 3; ++c) {
      maps.normal_world.push_back(hit ? n_world[static_cast<size_t>(c)] : 0.0f);
      maps.normal_tangent.push_back(hit ? n_tangent[static_cast<size_t>(c)] : 0.0f);
    }
    maps.depth.push_back(hit ? 2.0f + 0.001f * static_cast<float>(p) : 0.0f);
    maps.label.push_back(hit ? 7 : 0);
    maps.sample_count.push_back(hit ? 300 + static_cast<int32_t>(p) : 48);  // beyond 8 bits
  }
  return maps;
}

}  // namespace

TEST_CASE("Frame stems are zero-padded to the largest index, at least 3 digits, and sort for any count", "[learn]") {
  CHECK(matdataset::frame_stem(7, 120) == "007");
  CHECK(matdataset::frame_stem(0, 1) == "000");
  CHECK(matdataset::frame_stem(999, 1000) == "999");
  CHECK(matdataset::frame_stem(7, 1001) == "0007");
  CHECK(matdataset::frame_stem(12345, 100000) == "12345");
  CHECK(matdataset::variant_folder_name(3, 14) == "var003");
  std::vector<std::string> stems;
  for (size_t k = 0; k < 1500; ++k) stems.push_back(matdataset::frame_stem(k, 1500));
  CHECK(std::is_sorted(stems.begin(), stems.end()));
}

TEST_CASE("A frame's eight maps hold the documented encodings", "[learn]") {
  const fs::path variant = fresh_dir("matpredict_writer_frame") / "vase" / "var000";
  const matdataset::FrameMaps maps = test_frame();
  matdataset::write_frame_maps(variant, "000", maps);
  int w = 0, h = 0, channels = 0;
  const auto at = [&](const std::vector<float>& values, size_t p, int c) { return values[p * static_cast<size_t>(channels) + static_cast<size_t>(c)]; };

  const std::vector<float> orm = stored_values(variant / "ORM" / "000.png", w, h, channels);
  REQUIRE((w == kWidth && h == kHeight && channels == 4));
  for (size_t p = 0; p < maps.coverage.size(); ++p) {
    INFO("pixel " << p);
    const bool hit = maps.coverage[p] > 0.0f;
    // 8-bit codes of the values, exactly: no dither (the repository's W7).
    CHECK(at(orm, p, 0) * 255.0f == Approx(hit ? std::round(0.75 * 255) : 0));
    CHECK(at(orm, p, 1) * 255.0f == Approx(std::round(maps.roughness[p] * 255.0)));
    CHECK(at(orm, p, 2) == Approx(hit ? 1.0 : 0.0));
    CHECK(at(orm, p, 3) == Approx(hit ? 1.0 : 0.0));
  }
  const std::vector<float> label = stored_values(variant / "label" / "000.png", w, h, channels);
  REQUIRE(channels == 1);
  for (size_t p = 0; p < maps.coverage.size(); ++p) CHECK((label[p] * 255.0f > 0.5f) == (maps.coverage[p] > 0.0f));

  // Depth: 32-bit float, the hit's depth even where the pixel is a quarter covered (W8).
  const std::vector<float> depth = stored_values(variant / "depth" / "000.exr", w, h, channels);
  REQUIRE(channels == 4);
  for (size_t p = 0; p < maps.coverage.size(); ++p) {
    for (int c = 0; c < 3; ++c) CHECK(at(depth, p, c) == maps.depth[p]);
    CHECK(at(depth, p, 3) == maps.coverage[p]);
  }

  // The image and the albedo keep the surface's colour where it is partly covered: straight
  // alpha of the coverage, sRGB of the un-premultiplied colour (no white halo, W6).
  const std::vector<float> image = stored_values(variant / "images" / "000.png", w, h, channels);
  const std::vector<float> albedo = stored_values(variant / "albedo" / "000.png", w, h, channels);
  const double srgb_half = 1.055 * std::pow(0.5, 1 / 2.4) - 0.055, srgb_fifth = 1.055 * std::pow(0.2, 1 / 2.4) - 0.055;
  for (size_t p : {size_t{0}, size_t{3}}) {
    CHECK(at(image, p, 0) * 255.0f == Approx(std::round(srgb_half * 255)));
    CHECK(at(albedo, p, 1) * 255.0f == Approx(std::round(srgb_fifth * 255)));
    CHECK(at(image, p, 3) * 255.0f == Approx(std::round(maps.coverage[p] * 255)));
  }
  CHECK(at(image, 4, 3) == 0.0f);
  const std::vector<float> normal = stored_values(variant / "normal_obj" / "000.png", w, h, channels);
  CHECK(at(normal, 0, 0) * 255.0f == Approx(std::round(0.8 * 255)));
  CHECK(at(normal, 0, 2) * 255.0f == Approx(std::round(static_cast<double>(0.5f * 0.8f + 0.5f) * 255)));
  const std::vector<float> normal_mat = stored_values(variant / "normal_mat" / "000.png", w, h, channels);
  CHECK(at(normal_mat, 0, 0) * 255.0f == Approx(128));
  CHECK(at(normal_mat, 0, 2) == 1.0f);

  // Sample counts: 16-bit, exact, at every pixel.
  const std::vector<float> samples = stored_values(variant / "sample_count" / "000.png", w, h, channels);
  REQUIRE(channels == 1);
  for (size_t p = 0; p < maps.coverage.size(); ++p) CHECK(std::lround(samples[p] * 65535.0f) == maps.sample_count[p]);

  // The repository loader's rule finds the frame as a sample.
  CHECK(matdataset::index_dataset(variant.parent_path().parent_path()).size() == 1);
}

TEST_CASE("A frame is complete only when every map decodes whole at its size", "[learn]") {
  const fs::path variant = fresh_dir("matpredict_writer_complete") / "o" / "var000";
  matdataset::write_frame_maps(variant, "000", test_frame());
  CHECK(matdataset::frame_is_complete(variant, "000", kWidth, kHeight, {}));
  CHECK_FALSE(matdataset::frame_is_complete(variant, "000", kWidth + 1, kHeight, {}));
  CHECK_FALSE(matdataset::frame_is_complete(variant, "001", kWidth, kHeight, {}));
  // A file cut short since it was written.
  const fs::path orm = variant / "ORM" / "000.png";
  const auto size = fs::file_size(orm);
  fs::resize_file(orm, size / 2);
  CHECK_FALSE(matdataset::frame_is_complete(variant, "000", kWidth, kHeight, {}));
  matdataset::write_frame_maps(variant, "000", test_frame());
  CHECK(matdataset::frame_is_complete(variant, "000", kWidth, kHeight, {}));
  fs::remove(variant / "depth" / "000.exr");
  CHECK_FALSE(matdataset::frame_is_complete(variant, "000", kWidth, kHeight, {}));
  // No temporary is left beside the maps.
  for (const auto& entry : fs::recursive_directory_iterator(variant))
    CHECK(entry.path().filename().string().rfind(".", 0) != 0);
}

TEST_CASE("Frame maps of the wrong size, with a label beyond 8 bits or a sample count beyond 16 are refused, nothing written", "[learn]") {
  const fs::path variant = fresh_dir("matpredict_writer_refused") / "o" / "var000";
  matdataset::FrameMaps maps = test_frame();
  maps.depth.pop_back();
  CHECK_THROWS_WITH(matdataset::write_frame_maps(variant, "000", maps), Catch::Contains("depth holds 19 values, expected 20"));
  maps = test_frame();
  maps.label[0] = 300;
  CHECK_THROWS_WITH(matdataset::write_frame_maps(variant, "000", maps), Catch::Contains("label 300 does not fit"));
  for (const int32_t count : {0, 65536}) {
    maps = test_frame();
    maps.sample_count[3] = count;
    CHECK_THROWS_WITH(matdataset::write_frame_maps(variant, "000", maps),
                      Catch::Contains("sample count " + std::to_string(count) + " does not fit"));
  }
  CHECK_FALSE(fs::exists(variant / "images" / "000.png"));
}

TEST_CASE("With render.hdr_images a frame has its image in floats too, the colour as rendered", "[learn]") {
  const fs::path variant = fresh_dir("matpredict_writer_hdr") / "o" / "var000";
  matdataset::FrameMaps maps = test_frame();
  maps.hdr_image = true;
  maps.exposure_stops = 1.5;  // the display image's, not the HDR image's
  maps.color[0] = 37.25f;     // beyond what a display image holds
  matdataset::write_frame_maps(variant, "000", maps);
  int w = 0, h = 0, channels = 0;
  const std::vector<float> hdr = stored_values(variant / "images_hdr" / "000.exr", w, h, channels);
  REQUIRE(channels == 4);
  REQUIRE(w * h == static_cast<int>(maps.coverage.size()));
  for (size_t p = 0; p < maps.coverage.size(); ++p) {
    for (size_t c = 0; c < 3; ++c) CHECK(hdr[4 * p + c] == maps.color[3 * p + c]);
    CHECK(hdr[4 * p + 3] == maps.coverage[p]);
  }
  CHECK(matdataset::frame_is_complete(variant, "000", kWidth, kHeight, {false, true}));
  fs::remove(variant / "images_hdr" / "000.exr");
  CHECK_FALSE(matdataset::frame_is_complete(variant, "000", kWidth, kHeight, {false, true}));
  CHECK(matdataset::frame_is_complete(variant, "000", kWidth, kHeight, {}));
  // transforms.json lists it where the frames have it.
  matdataset::FramePose pose;
  pose.stem = "000";
  matdataset::write_transforms(variant, matdataset::pinhole_intrinsics(kWidth, kHeight, 0.7), {pose}, {false, true});
  const nlohmann::json json = nlohmann::json::parse(std::ifstream(variant / "transforms.json"));
  CHECK(json["frames"][0]["file_path_hdr"] == "images_hdr/000");
  CHECK_FALSE(json["frames"][0].contains("file_path_region"));
}

TEST_CASE("transforms.json has the repository's keys, full intrinsics and a pose per frame", "[learn]") {
  const fs::path variant = fresh_dir("matpredict_writer_transforms");
  const double fov = 0.691111;
  const matdataset::CameraIntrinsics k = matdataset::pinhole_intrinsics(512, 384, fov);
  matdataset::FramePose pose;
  pose.stem = "000";
  for (int r = 0; r < 4; ++r) pose.camera_to_world[static_cast<size_t>(r)][static_cast<size_t>(r)] = 1.0;
  pose.camera_to_world[0][3] = 2.5;
  matdataset::write_transforms(variant, k, {pose});
  const nlohmann::json json = nlohmann::json::parse(std::ifstream(variant / "transforms.json"));
  CHECK(json["camera_angle_y"].get<double>() == Approx(fov));
  // A horizontal field from the vertical one through the aspect ratio.
  CHECK(json["camera_angle_x"].get<double>() == Approx(2 * std::atan(512.0 / 384.0 * std::tan(fov / 2))));
  CHECK(json["fl_x"].get<double>() == Approx(192.0 / std::tan(fov / 2)));
  CHECK(json["cx"].get<double>() == 256.0);
  CHECK(json["h"].get<int>() == 384);
  const nlohmann::json& frame = json["frames"][0];
  CHECK(frame["file_path"] == "images/000");
  CHECK(frame["file_path_orm"] == "ORM/000");
  CHECK(frame["file_path_normal"] == "normal_obj/000");
  CHECK(frame["file_path_depth"] == "depth/000");
  CHECK(frame["file_path_label"] == "label/000");
  CHECK(frame["envmap"].is_null());
  CHECK(frame["transform_matrix"][0][3].get<double>() == 2.5);
}

TEST_CASE("metadata.json records the slots' classes and the provenance; a slot without a class is refused", "[learn]") {
  const fs::path variant = fresh_dir("matpredict_writer_metadata");
  matdataset::VariantMetadata metadata;
  metadata.materials = {{"mat2", "metal_brushed_1", 4}, {"mat1", "wood_raw_3", 7}};
  metadata.width = metadata.height = 64;
  metadata.samples = 16;
  metadata.provenance_json = R"({"object": {"builtin": "chair", "seed": 2}})";
  matdataset::write_variant_metadata(variant, metadata);
  const nlohmann::json json = nlohmann::json::parse(std::ifstream(variant / "metadata.json"));
  CHECK(json["variant_map"]["mat1"] == "wood_raw_3");
  CHECK(json["used_materials"]["mat2"]["material_family"] == "metal");
  CHECK(json["used_materials"].begin().key() == "mat1");  // sorted by key
  CHECK(json["render_summary"]["resolution"]["width"] == 64);
  CHECK(json["provenance"]["object"]["seed"] == 2);
  metadata.materials[0].label_id = 0;
  CHECK_THROWS_WITH(matdataset::write_variant_metadata(variant, metadata),
                    Catch::Contains("material \"metal_brushed_1\" has label 0, which is no material class"));
  metadata.materials[0].label_id = 4;
  metadata.provenance_json = "[1]";
  CHECK_THROWS_WITH(matdataset::write_variant_metadata(variant, metadata), Catch::Contains("not a JSON object"));

  matdataset::write_segmentation_map_json(variant);
  const nlohmann::json map = nlohmann::json::parse(std::ifstream(variant / "material_segmentation_map.json"));
  CHECK(map["id_to_material_family"]["7"] == "wood");
  CHECK(map["material_family_to_id"]["glass"] == 14);
}

TEST_CASE("PythonRandom draws what CPython's random.Random draws for the same seed", "[learn]") {
  for (const uint64_t seed : {uint64_t{42}, uint64_t{0}, (uint64_t{1} << 40) + 5}) {
    INFO("seed " << seed);
    const std::string python = output_of(std::string(MATPREDICT_DEBIAN_PYTHON) +
                                         " -c \"import random; r = random.Random(" + std::to_string(seed) +
                                         "); x = list(range(50)); r.shuffle(x); print(*x); "
                                         "print(*[r.getrandbits(k) for k in (1, 7, 32, 33, 64)])\"");
    matdataset::PythonRandom random(seed);
    std::vector<int> items(50);
    for (int k = 0; k < 50; ++k) items[static_cast<size_t>(k)] = k;
    random.shuffle(items);
    std::ostringstream ours;
    for (size_t k = 0; k < items.size(); ++k) ours << (k ? " " : "") << items[k];
    ours << "\n";
    bool first = true;
    for (const int k : {1, 7, 32, 33, 64}) ours << (first ? "" : " ") << random.getrandbits(k), first = false;
    ours << "\n";
    CHECK(ours.str() == python);
  }
}

TEST_CASE("The object-disjoint split of the released dataset's objects is the repository's", "[learn]") {
  // Views per object in the release (docs/matpredict_repository.md, section 5): with seed 42 and
  // 70/15/15 the repository's generate_splits.py put them as object_disjoint_v1.yaml lists.
  const std::map<std::string, int> views = {
      {"bin_03", 189},   {"bowl_01", 35},      {"bowl_07", 35},        {"box", 913},       {"cabinet", 755},
      {"chair_01", 3819}, {"chair_04", 2520},  {"chair_05", 1080},     {"cup_01", 219},    {"cushion_03", 594},
      {"refrigerator", 613}, {"sofa", 4045},   {"stool_02", 1089},     {"table_01", 722},  {"table_03", 1304},
      {"table_04", 624}, {"towel", 360},       {"vase_02", 40}};
  std::vector<matdataset::SampleId> samples;
  for (const auto& [object, count] : views)
    for (int k = 0; k < count; ++k) samples.push_back({object, "var000", matdataset::frame_stem(static_cast<size_t>(k), 120)});
  const matdataset::SplitFile split = matdataset::object_disjoint_split(samples, matdataset::SplitRatios{}, 42);
  CHECK(split.train.size() == 13287);
  CHECK(split.val.size() == 2828);
  CHECK(split.test.size() == 2841);
  const auto objects = [](const std::vector<std::string>& ids) {
    std::set<std::string> names;
    for (const std::string& id : ids) names.insert(matdataset::SampleId::parse(id).object);
    return names;
  };
  CHECK(objects(split.train) == std::set<std::string>{"bin_03", "bowl_07", "chair_01", "chair_04", "refrigerator",
                                                      "sofa", "table_01", "table_03", "vase_02"});
  CHECK(objects(split.val) == std::set<std::string>{"cabinet", "stool_02", "table_04", "towel"});
  CHECK(objects(split.test) == std::set<std::string>{"bowl_01", "box", "chair_05", "cup_01", "cushion_03"});
  CHECK(std::is_sorted(split.train.begin(), split.train.end()));
}

TEST_CASE("No material is in two splits of the material-disjoint split", "[learn]") {
  // Variants of two slots: a+b and b+c share b, so they go together; d+e and f+g stand alone.
  const std::vector<std::vector<std::string>> variant_materials = {
      {"a", "b"}, {"b", "c"}, {"d", "e"}, {"f", "g"}, {"h", "i"}, {"j", "k"}, {"l", "a"}};
  std::vector<matdataset::SampleId> samples;
  std::vector<std::vector<std::string>> materials_of;
  for (size_t v = 0; v < variant_materials.size(); ++v)
    for (size_t k = 0; k < 10; ++k) {
      samples.push_back({"chair", matdataset::variant_folder_name(v, variant_materials.size()), matdataset::frame_stem(k, 10)});
      materials_of.push_back(variant_materials[v]);
    }
  const matdataset::SplitFile split = matdataset::material_disjoint_split(samples, materials_of, matdataset::SplitRatios{0.6, 0.2, 0.2}, 42);
  std::map<std::string, std::set<std::string>> splits_of_material;
  const std::array<std::pair<const char*, const std::vector<std::string>*>, 3> lists = {
      {{"train", &split.train}, {"val", &split.val}, {"test", &split.test}}};
  for (const auto& [name, ids] : lists)
    for (const std::string& id : *ids) {
      const size_t v = static_cast<size_t>(std::stoi(matdataset::SampleId::parse(id).variant.substr(3)));
      for (const std::string& material : variant_materials[v]) splits_of_material[material].insert(name);
    }
  for (const auto& [material, names] : splits_of_material) {
    INFO(material);
    CHECK(names.size() == 1);
  }
  CHECK(split.train.size() + split.val.size() + split.test.size() == samples.size());
  CHECK_FALSE(split.val.empty());
  CHECK_FALSE(split.test.empty());
}

TEST_CASE("Split files round-trip through read_split_file, and the random split is 80/20 of every sample", "[learn]") {
  std::vector<matdataset::SampleId> samples;
  for (size_t k = 0; k < 37; ++k) samples.push_back({"vase", "var000", matdataset::frame_stem(k, 37)});
  const matdataset::SplitFile split = matdataset::random_split(samples, 0.8, 42);
  CHECK(split.train.size() == 29);
  CHECK(split.test.size() == 8);
  CHECK(split.val.empty());
  const fs::path dir = fresh_dir("matpredict_writer_splits");
  matdataset::write_split_file(dir / "paper_random_v1.yaml", split, matdataset::SplitRatios{0.8, 0.0, 0.2}, "..");
  const matdataset::SplitFile read = matdataset::read_split_file(dir / "paper_random_v1.yaml");
  CHECK(read.train == split.train);
  CHECK(read.test == split.test);
  CHECK(read.val.empty());
  CHECK(read.seed == 42);
  CHECK(read.strategy == "random");
  // The same ids shuffled by CPython, first 29 for training.
  std::string ids;
  for (const matdataset::SampleId& id : samples) ids += "'" + id.str() + "',";
  const std::string python = output_of(std::string(MATPREDICT_DEBIAN_PYTHON) + " -c \"import random; x = [" + ids +
                                       "]; random.Random(42).shuffle(x); print(*sorted(x[:29]))\"");
  std::string ours;
  for (const std::string& id : split.train) ours += (ours.empty() ? "" : " ") + id;
  CHECK(ours + "\n" == python);
}

TEST_CASE("docs/dataset_format.md holds the table of maps the writer writes", "[learn]") {
  std::ifstream in(MATPREDICT_DATASET_FORMAT_DOC);
  REQUIRE(in);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(text.find(matdataset::dataset_maps_markdown()) != std::string::npos);
}
