// The MatPredict dataset layout (matdataset/format/dataset_index.h) and one sample's decoding
// (matdataset/format/sample_reader.h), on a small dataset written here as real PNG files, and the resize
// against Pillow's.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include <OpenImageIO/imageio.h>

#include "matdataset/format/dataset_index.h"
#include "matdataset/format/decoded_image.h"
#include "matdataset/format/resample.h"
#include "matdataset/format/sample_loader.h"
#include "matdataset/format/sample_reader.h"
#include "support/synthetic_png.h"

using namespace matdataset;
namespace fs = std::filesystem;

namespace {

constexpr int kSize = 16;

template <class Value>
void write_png(const fs::path& path, int channels, Value value) {
  write_synthetic_png(path, kSize, channels, value);
}

// The object: a disc of radius 5 px centred in the frame.
bool inside_object(int x, int y) { return (x - 7.5) * (x - 7.5) + (y - 7.5) * (y - 7.5) < 25.0; }

// The normal map's unit normal at column x: (sin t, 0, cos t) with t = 0.1 x radians.
std::array<double, 3> normal_at(int x) { return {std::sin(0.1 * x), 0.0, std::cos(0.1 * x)}; }

// Stored as 8-bit 0.5 n + 0.5.
std::array<uint8_t, 3> encoded_normal(int x) {
  std::array<uint8_t, 3> bytes{};
  for (int c = 0; c < 3; ++c) bytes[static_cast<size_t>(c)] = static_cast<uint8_t>(std::lround(255.0 * (0.5 * normal_at(x)[static_cast<size_t>(c)] + 0.5)));
  return bytes;
}

// The stored alpha: opaque on the object but for its centre pixel (8, 8), a quarter covered.
uint8_t coverage(int x, int y) { return x == 8 && y == 8 ? 64 : inside_object(x, y) ? 255 : 0; }

// A frame: RGBA image and albedo, ORM with roughness 0.2 (51) and metallic 0.8 (204) on the
// object, label 7 (wood) on it, and a normal map whose normal tilts with x; background 0
// everywhere, as the generator writes it.
void write_frame(const fs::path& variant, const std::string& stem, bool with_label, bool with_orm = true) {
  write_png(variant / "images" / (stem + ".png"), 4, [](int x, int y, int c) -> uint8_t {
    return c == 3 ? coverage(x, y) : inside_object(x, y) ? static_cast<uint8_t>(40 * c + 60) : 0;
  });
  write_png(variant / "albedo" / (stem + ".png"), 4, [](int x, int y, int c) -> uint8_t {
    return c == 3 ? coverage(x, y) : inside_object(x, y) ? 200 : 0;
  });
  write_png(variant / "normal_obj" / (stem + ".png"), 4, [](int x, int y, int c) -> uint8_t {
    if (c == 3) return coverage(x, y);
    return inside_object(x, y) ? encoded_normal(x)[c] : 0;
  });
  if (with_orm)
    write_png(variant / "ORM" / (stem + ".png"), 4, [](int x, int y, int c) -> uint8_t {
      const uint8_t on_object[4] = {255, 51, 204, 255};
      return inside_object(x, y) ? on_object[c] : 0;
    });
  if (with_label)
    write_png(variant / "label" / (stem + ".png"), 1, [](int x, int y, int) -> uint8_t { return inside_object(x, y) ? 7 : 0; });
}

// chair_01/var000: 000, 001; chair_01/var001: 000, 001; table/var000: 000; chair_01/_tmp_channels:
// ignored. Tests remove maps from it to make the incomplete cases.
fs::path make_dataset() {
  const fs::path root = fs::temp_directory_path() / "matpredict_dataset_test";
  fs::remove_all(root);
  write_frame(root / "chair_01" / "var000", "000", true);
  write_frame(root / "chair_01" / "var000", "001", true);
  write_frame(root / "chair_01" / "var001", "000", true);
  write_frame(root / "chair_01" / "var001", "001", true);
  write_frame(root / "table" / "var000", "000", true);
  write_frame(root / "chair_01" / "_tmp_channels", "000", true);
  std::ofstream(root / "split.yaml") << "name: tiny\nstrategy: object_disjoint\nseed: 42\n"
                                        "ratios: {train: 0.7, val: 0.15, test: 0.15}\n"
                                        "train:\n- chair_01/var000/000\n- chair_01/var001/000\n"
                                        "val:\n- table/var000/000\ntest: []\n";
  return root;
}

}  // namespace

TEST_CASE("The dataset index follows the repository loader's rules", "[learn]") {
  const fs::path root = make_dataset();
  std::vector<std::string> ids;
  for (const matdataset::SampleId& s : matdataset::index_dataset(root)) ids.push_back(s.str());
  CHECK(ids == std::vector<std::string>{"chair_01/var000/000", "chair_01/var000/001", "chair_01/var001/000",
                                        "chair_01/var001/001", "table/var000/000"});
  CHECK_THROWS_WITH(matdataset::index_dataset(root / "nowhere"), Catch::Contains("nowhere") && Catch::Contains("not a directory"));
}

TEST_CASE("A dataset missing a map, or a label some frames have, is refused naming the files", "[learn]") {
  // The repository's loader skips such a frame, and trains on fewer than it was given.
  const fs::path root = make_dataset();
  const fs::path orm = root / "chair_01" / "var001" / "ORM" / "001.png";
  fs::remove(orm);
  CHECK_THROWS_WITH(matdataset::index_dataset(root), Catch::Contains("1 map file is missing: " + orm.string()));
  make_dataset();
  const fs::path label = root / "chair_01" / "var000" / "label" / "001.png";
  fs::remove(label);
  CHECK_THROWS_WITH(matdataset::index_dataset(root),
                    Catch::Contains("1 of 5 frames have no label map") && Catch::Contains(label.string()));
}

TEST_CASE("Split files list samples in file order and every listed sample must exist", "[learn]") {
  const fs::path root = make_dataset();
  const matdataset::SplitFile split = matdataset::read_split_file(root / "split.yaml");
  CHECK(split.name == "tiny");
  CHECK(split.seed == 42);
  const std::vector<matdataset::SampleId> train = matdataset::split_samples(split, "train", root);
  REQUIRE(train.size() == 2);
  CHECK(train[1].str() == "chair_01/var001/000");
  CHECK(matdataset::split_samples(split, "test", root).empty());

  matdataset::SplitFile broken = split;
  broken.val.push_back("chair_01/var001/001");
  fs::remove(root / "chair_01" / "var001" / "ORM" / "001.png");
  CHECK_THROWS_WITH(matdataset::split_samples(broken, "val", root), Catch::Contains("chair_01/var001/ORM/001.png"));
  // A frame listed twice, in one list or in two, is counted twice or scored after training.
  std::ofstream(root / "twice.yaml") << "train:\n- chair_01/var000/000\nval:\n- chair_01/var000/000\ntest: []\n";
  CHECK_THROWS_WITH(matdataset::read_split_file(root / "twice.yaml"),
                    Catch::Contains("twice.yaml: lists chair_01/var000/000 twice (in train and in val)"));
  CHECK_THROWS_WITH(matdataset::split_samples(split, "holdout", root), Catch::Contains("holdout"));
  std::ofstream(root / "bad.yaml") << "name: bad\ntrain: chair_01/var000/000\n";
  CHECK_THROWS_WITH(matdataset::read_split_file(root / "bad.yaml"), Catch::Contains("bad.yaml") && Catch::Contains("'train'"));
  std::ofstream(root / "not_yaml.yaml") << "train: [unclosed\n";
  CHECK_THROWS_WITH(matdataset::read_split_file(root / "not_yaml.yaml"), Catch::Contains("not_yaml.yaml"));
  CHECK_THROWS_AS(matdataset::SampleId::parse("chair_01/000"), std::invalid_argument);
}

TEST_CASE("A sample decodes the maps the loader reads, at the model size", "[learn]") {
  const fs::path root = make_dataset();
  matdataset::SampleSettings settings;
  settings.size = kSize;
  const matdataset::MaterialSample s = matdataset::read_sample(root, matdataset::SampleId::parse("chair_01/var000/000"), settings);
  REQUIRE(s.has_label);
  REQUIRE(s.input.width == kSize);
  const size_t centre = 8 * kSize + 8, corner = 0;
  CHECK(s.material_id[centre] == 7);
  CHECK(s.material_id[corner] == 0);
  CHECK(s.mask[centre] == 1);
  CHECK(s.mask[corner] == 0);
  // RGB as stored, whatever the alpha (the centre pixel is a quarter covered); roughness from
  // ORM's green, metallic from its blue.
  CHECK(s.input.at(8, 8, 2) == Approx(140.0 / 255.0));
  CHECK(s.roughness.at(8, 8, 0) == Approx(51.0 / 255.0));
  CHECK(s.metallic.at(8, 8, 0) == Approx(204.0 / 255.0));
  CHECK(s.albedo.at(8, 8, 0) == Approx(200.0 / 255.0));

  // Without a label file every pixel counts, as in the repository.
  fs::remove(root / "chair_01" / "var000" / "label" / "001.png");
  const matdataset::MaterialSample unlabelled = matdataset::read_sample(root, matdataset::SampleId::parse("chair_01/var000/001"), settings);
  CHECK_FALSE(unlabelled.has_label);
  CHECK(std::all_of(unlabelled.mask.begin(), unlabelled.mask.end(), [](uint8_t m) { return m == 1; }));

  // Linear albedo: the sRGB decode of 200/255.
  settings.linear_albedo = true;
  const matdataset::MaterialSample linear = matdataset::read_sample(root, matdataset::SampleId::parse("chair_01/var000/000"), settings);
  CHECK(linear.albedo.at(8, 8, 0) == Approx(std::pow((200.0 / 255.0 + 0.055) / 1.055, 2.4)).epsilon(1e-5));
  fs::remove(root / "chair_01" / "var001" / "ORM" / "001.png");
  CHECK_THROWS_WITH(matdataset::read_sample(root, matdataset::SampleId::parse("chair_01/var001/001"), settings), Catch::Contains("ORM"));
  CHECK(linear.normal.values.empty());  // not asked for
}

// A one-channel 16-bit label PNG of id 7 on the object, as render_object writes label maps.
void write_label16(const fs::path& path) {
  std::vector<uint16_t> ids(static_cast<size_t>(kSize * kSize));
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) ids[static_cast<size_t>(y * kSize + x)] = inside_object(x, y) ? 7 : 0;
  OIIO::ImageSpec spec(kSize, kSize, 1, OIIO::TypeDesc::UINT16);
  auto out = OIIO::ImageOutput::create(path.string());
  REQUIRE(out);
  REQUIRE(out->open(path.string(), spec));
  REQUIRE(out->write_image(OIIO::TypeDesc::UINT16, ids.data()));
  REQUIRE(out->close());
}

TEST_CASE("Label maps are read as the integers written, 8 or 16 bits, and checked against the classes", "[learn]") {
  const fs::path root = make_dataset();
  const fs::path label = root / "chair_01" / "var000" / "label" / "000.png";
  write_label16(label);
  const matdataset::DecodedIds ids = matdataset::decode_ids(label);
  CHECK(ids.ids[8 * kSize + 8] == 7);  // scaled to 8 bits, 7 / 65535 would be 0
  matdataset::SampleSettings settings;
  settings.size = kSize;
  const matdataset::MaterialSample s = matdataset::read_sample(root, matdataset::SampleId::parse("chair_01/var000/000"), settings);
  CHECK(s.material_id[8 * kSize + 8] == 7);
  CHECK(s.mask[8 * kSize + 8] == 1);
  // A network of 5 classes (ids 0 to 4) cannot be trained on label 7.
  settings.material_classes = 5;
  CHECK_THROWS_WITH(matdataset::read_sample(root, matdataset::SampleId::parse("chair_01/var000/000"), settings),
                    Catch::Contains(label.string()) && Catch::Contains("label id 7, beyond the network's 5"));
  // Labels of more than one channel are no label map.
  write_png(label, 3, [](int, int, int) -> uint8_t { return 7; });
  CHECK_THROWS_WITH(matdataset::decode_ids(label), Catch::Contains(label.string()));
}

TEST_CASE("A normal map is read on request and resized as unit vectors", "[learn]") {
  const fs::path root = make_dataset();
  matdataset::SampleSettings settings;
  settings.size = kSize;
  settings.read_normal = true;
  const matdataset::MaterialSample same = matdataset::read_sample(root, matdataset::SampleId::parse("chair_01/var000/000"), settings);
  REQUIRE(same.normal.channels == 3);
  // At the stored size the map is the stored one (to the renormalisation of 8-bit values).
  for (int c = 0; c < 3; ++c) CHECK(same.normal.at(6, 8, c) == Approx(encoded_normal(6)[static_cast<size_t>(c)] / 255.0).margin(4e-3));

  // Halved, each output pixel averages normals of several columns. A plain average of encoded
  // values is shorter than a unit normal; the reader's is unit length.
  settings.size = 8;
  const matdataset::MaterialSample half = matdataset::read_sample(root, matdataset::SampleId::parse("chair_01/var000/000"), settings);
  int object_pixels = 0;
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      if (!half.mask[static_cast<size_t>(y * 8 + x)]) continue;
      ++object_pixels;
      double length2 = 0.0;
      for (int c = 0; c < 3; ++c) length2 += std::pow(2.0 * half.normal.at(x, y, c) - 1.0, 2.0);
      CHECK(std::sqrt(length2) == Approx(1.0).margin(1e-5));
      // Its tilt lies within the tilts of the columns it covers (2x to 2x + 1, widened by the filter).
      const double tilt = std::atan2(2.0 * half.normal.at(x, y, 0) - 1.0, 2.0 * half.normal.at(x, y, 2) - 1.0);
      CHECK(tilt > 0.1 * (2 * x - 1) - 0.01);
      CHECK(tilt < 0.1 * (2 * x + 2) + 0.01);
    }
  CHECK(object_pixels > 0);

  // Asked for and missing: an error naming the file.
  fs::remove(root / "table" / "var000" / "normal_obj" / "000.png");
  CHECK_THROWS_WITH(matdataset::read_sample(root, matdataset::SampleId::parse("table/var000/000"), settings),
                    Catch::Contains("normal_obj") && Catch::Contains("000.png"));
}

TEST_CASE("Shrunk targets keep their value along the silhouette (W16)", "[learn]") {
  // Halving the 16 px frame averages 2 x 2 blocks and more: along the disc's edge a plain
  // bilinear resize mixes in the black background; the mask-weighted one does not.
  const fs::path root = make_dataset();
  matdataset::SampleSettings settings;
  settings.size = 8;
  const matdataset::MaterialSample s = matdataset::read_sample(root, matdataset::SampleId::parse("table/var000/000"), settings);
  int edge_pixels = 0;
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      if (!s.mask[static_cast<size_t>(y * 8 + x)]) continue;
      CHECK(s.roughness.at(x, y, 0) == Approx(51.0 / 255.0).epsilon(1e-5));
      CHECK(s.albedo.at(x, y, 1) == Approx(200.0 / 255.0).epsilon(1e-5));
      if (s.input.at(x, y, 0) < 0.9f * 60.0f / 255.0f) ++edge_pixels;  // the input is not reweighted
    }
  CHECK(edge_pixels > 0);  // so the test does look at pixels where the background mixes in
}

TEST_CASE("The paper's texture-target layout: screenshots beside one reference map per material", "[learn]") {
  const fs::path root = fs::temp_directory_path() / "matpredict_paper_layout_test";
  fs::remove_all(root);
  // Two objects in wood, one in metal; metal has no roughness reference yet.
  for (const char* stem : {"000", "001"})
    write_png(root / "rendered_cropped" / "chair" / "wood" / (std::string(stem) + ".png"), 3,
              [](int x, int, int c) -> uint8_t { return static_cast<uint8_t>(10 * x + c); });
  write_png(root / "rendered_cropped" / "table" / "wood" / "000.png", 3, [](int, int, int) -> uint8_t { return 90; });
  write_png(root / "rendered_cropped" / "table" / "metal" / "000.png", 3, [](int, int, int) -> uint8_t { return 90; });
  // The wood references are 16 x 16, the screenshots' size, so the targets are exactly them.
  write_png(root / "ground_truth_basecolour" / "wood.png", 3, [](int x, int y, int c) -> uint8_t {
    return static_cast<uint8_t>(c == 0 ? 12 * x : c == 1 ? 12 * y : 200);
  });
  write_png(root / "ground_truth_roughness" / "wood.png", 1, [](int, int, int) -> uint8_t { return 153; });
  write_png(root / "ground_truth_basecolour" / "metal.png", 3, [](int, int, int) -> uint8_t { return 128; });

  CHECK(matdataset::dataset_layout(root) == matdataset::DatasetLayout::paper_textures);
  CHECK(matdataset::dataset_layout(make_dataset()) == matdataset::DatasetLayout::repository);
  // A material without its roughness reference is refused, as is a split naming it.
  CHECK_THROWS_WITH(matdataset::index_dataset(root), Catch::Contains("ground_truth_roughness/metal.png"));
  matdataset::SplitFile split;
  split.train = {"table/metal/000"};
  CHECK_THROWS_WITH(matdataset::split_samples(split, "train", root), Catch::Contains("ground_truth_roughness/metal.png"));
  write_png(root / "ground_truth_roughness" / "metal.png", 1, [](int, int, int) -> uint8_t { return 51; });
  std::vector<std::string> ids;
  for (const matdataset::SampleId& s : matdataset::index_dataset(root)) ids.push_back(s.str());
  CHECK(ids == std::vector<std::string>{"chair/wood/000", "chair/wood/001", "table/metal/000", "table/wood/000"});

  matdataset::SampleSettings settings;
  settings.size = kSize;
  const matdataset::MaterialSample s = matdataset::read_sample(root, matdataset::SampleId::parse("chair/wood/001"), settings);
  CHECK_FALSE(s.has_label);
  CHECK(std::all_of(s.mask.begin(), s.mask.end(), [](uint8_t m) { return m == 1; }));
  CHECK(s.input.at(3, 5, 1) == Approx(31.0 / 255.0));
  CHECK(s.albedo.at(3, 5, 0) == Approx(36.0 / 255.0));
  CHECK(s.albedo.at(3, 5, 1) == Approx(60.0 / 255.0));
  CHECK(s.roughness.at(9, 2, 0) == Approx(0.6));
  CHECK(s.metallic.values.empty());  // the material has no metallic reference
  // Shrunk to 8 px the whole reference is resized: a plain average of the uniform roughness.
  settings.size = 8;
  CHECK(matdataset::read_sample(root, matdataset::SampleId::parse("table/wood/000"), settings).roughness.at(4, 4, 0) == Approx(0.6));
  // A normal map asked for and missing: an error naming the file.
  settings.read_normal = true;
  CHECK_THROWS_WITH(matdataset::read_sample(root, matdataset::SampleId::parse("chair/wood/000"), settings), Catch::Contains("ground_truth_normal"));
}

TEST_CASE("The bilinear resize is Pillow's, to its 8-bit rounding", "[learn]") {
  // Pillow (Debian's python3-pil) resizes 8-bit images in fixed point and rounds to 8 bits, so
  // the two agree within one level.
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> byte(0, 255);
  const fs::path dir = fs::temp_directory_path() / "matpredict_resize_test";
  fs::create_directories(dir);
  for (const auto& [w, h, ow, oh] : {std::array<int, 4>{37, 29, 16, 12}, std::array<int, 4>{10, 7, 23, 17},
                                     std::array<int, 4>{64, 64, 64, 64}}) {
    matbase::FloatImage image(w, h, 3);
    std::vector<uint8_t> bytes(image.values.size());
    for (size_t i = 0; i < bytes.size(); ++i) {
      bytes[i] = static_cast<uint8_t>(byte(rng));
      image.values[i] = bytes[i] / 255.0f;
    }
    std::ofstream(dir / "in.u8", std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    std::ostringstream command;
    command << MATPREDICT_DEBIAN_PYTHON << " " << MATPREDICT_PIL_RESIZE_SCRIPT << " " << w << " " << h << " "
            << dir / "in.u8" << " " << ow << " " << oh << " " << dir / "out.u8";
    INFO(command.str() << " (needs Debian's python3-pil)");
    REQUIRE(std::system(command.str().c_str()) == 0);
    std::vector<char> pillow(static_cast<size_t>(ow * oh * 3));
    std::ifstream(dir / "out.u8", std::ios::binary).read(pillow.data(), static_cast<std::streamsize>(pillow.size()));
    const matbase::FloatImage ours = resize_bilinear(image, ow, oh);
    double worst = 0.0;
    for (size_t i = 0; i < pillow.size(); ++i)
      worst = std::max(worst, std::abs(ours.values[i] * 255.0 - static_cast<uint8_t>(pillow[i])));
    INFO(w << "x" << h << " -> " << ow << "x" << oh << ": worst difference " << worst << " levels");
    CHECK(worst <= 1.0);
  }
}

TEST_CASE("Loader batches decode the same data on 1 and 2 threads", "[learn]") {
  const fs::path root = make_dataset();
  matdataset::LoaderSettings settings;
  settings.batch_size = 3;
  settings.sample.size = 8;
  settings.threads = 1;
  const matdataset::SampleLoader one(root, matdataset::index_dataset(root), settings);
  settings.threads = 2;
  const matdataset::SampleLoader two(root, matdataset::index_dataset(root), settings);
  REQUIRE(one.batch_count() == 2);
  for (size_t b = 0; b < one.batch_count(); ++b) {
    const std::vector<matdataset::MaterialSample> a = one.batch(1, b), c = two.batch(1, b);
    REQUIRE(a.size() == c.size());
    for (size_t i = 0; i < a.size(); ++i) {
      CHECK(a[i].albedo.values == c[i].albedo.values);
      CHECK(a[i].material_id == c[i].material_id);
    }
  }
  CHECK(one.batch(1, 1).size() == 2);  // 5 samples in batches of 3
}

TEST_CASE("One image to predict: its mask from a label map, from alpha, or everything (W17)", "[learn]") {
  const fs::path root = make_dataset();
  const fs::path variant = root / "chair_01" / "var000";
  // A label map of ids 7 is the object: the repository's "> 0.5 after / 255" made it background.
  const matdataset::InputImage labelled = matdataset::read_input_image(variant / "images" / "000.png", variant / "label" / "000.png", 8);
  CHECK(labelled.rgb.width == 8);
  CHECK(labelled.rgb.channels == 3);
  size_t inside = 0;
  for (uint8_t m : labelled.mask) inside += m;
  CHECK(inside > 0);
  CHECK(inside < labelled.mask.size());
  // The RGBA image's alpha gives the same disc.
  const matdataset::InputImage from_alpha = matdataset::read_input_image(variant / "images" / "000.png", {}, 8);
  CHECK(from_alpha.mask == labelled.mask);
  // An RGB-only image (the albedo's colour channels as a grey PNG here) covers everything.
  write_png(root / "grey.png", 1, [](int x, int, int) -> uint8_t { return static_cast<uint8_t>(x * 10); });
  const matdataset::InputImage grey = matdataset::read_input_image(root / "grey.png", {}, 8);
  CHECK(std::all_of(grey.mask.begin(), grey.mask.end(), [](uint8_t m) { return m == 1; }));
  CHECK(grey.rgb.at(3, 3, 0) == grey.rgb.at(3, 3, 2));
  CHECK_THROWS_WITH(matdataset::read_input_image(root / "missing.png", {}, 8), Catch::Contains("missing.png"));
}
