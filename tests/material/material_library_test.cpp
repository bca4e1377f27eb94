// The procedural material library (matmaterial/library/material_library.h): every style's maps are seamless,
// inside its class's stated ranges, unit normals, the same bytes on any thread count; a
// generated folder reads back as generated; specs parse or fail with their own message.
#include "matbase/pi.h"
#include "matmaterial/library/material_library.h"

#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "matbase/image/srgb.h"
#include "matbase/image/unorm.h"
#include "matmaterial/material_parameters.h"
#include "matmaterial/metal_reflectances.h"
#include "support/temp_dir.h"

using namespace matmaterial;
using P = matmaterial::MaterialParameter;
using Catch::Matchers::Contains;

namespace {

// Every image a generated material holds, with what it is for.
std::vector<const matbase::ImagePixels*> images_of(const matmaterial::FolderMaterial& m) {
  std::vector<const matbase::ImagePixels*> images;
  for (const matbase::ImagePixels& image : m.images) images.push_back(&image);
  return images;
}

// Mean absolute difference, over every channel, between column a and column b, or between rows
// a and b.
double line_difference(const matbase::ImagePixels& image, int a, int b, bool columns) {
  const int length = columns ? image.height : image.width;
  double sum = 0.0;
  for (int k = 0; k < length; ++k)
    for (int c = 0; c < image.channels; ++c) {
      const auto texel = [&](int line) {
        return static_cast<size_t>(columns ? k * image.width + line : line * image.width + k);
      };
      sum += std::abs(matbase::texel_channel(image, texel(a), c) - matbase::texel_channel(image, texel(b), c));
    }
  return sum / (length * image.channels);
}

// The criterion: the step across the wrap is no larger than the steps between
// neighbouring interior columns (rows). The wrap is one more draw from the same distribution
// when the map is seamless, so it beats the largest of N - 1 interior steps with chance 1/N;
// the margin (a quarter of the largest, plus half a code) keeps that from failing the test,
// while a seam's step is several times the largest interior one (the checker's own test).
bool wraps_seamlessly(const matbase::ImagePixels& image) {
  for (const bool columns : {true, false}) {
    const int lines = columns ? image.width : image.height;
    double interior = 0.0;
    for (int line = 0; line + 1 < lines; ++line) interior = std::max(interior, line_difference(image, line, line + 1, columns));
    if (line_difference(image, lines - 1, 0, columns) > 1.25 * interior + 0.5) return false;
  }
  return true;
}

// The value an 8-bit code (or a fraction of one) of parameter p's image stands for, decoded as
// the renderer decodes it.
double decoded(const matmaterial::MaterialParameterInfo& info, double code) {
  const double value = code / 255.0;
  return info.texture_space == matmaterial::ColorSpace::SRGB ? matbase::srgb_to_linear(value) : value;
}

std::vector<matmaterial::LibraryMaterialSpec> every_style(uint32_t seed) {
  std::vector<matmaterial::LibraryMaterialSpec> specs;
  for (const matmaterial::LibraryStyleInfo& style : matmaterial::library_styles()) specs.push_back({style.material_class, style.name, seed});
  return specs;
}

}  // namespace

TEST_CASE("The seam checker catches a map that does not wrap", "[material]") {
  // Sums of sines over the tile: whole frequencies wrap, others leave a seam.
  const auto waves = [](double fu, double fv) {
    matbase::ImagePixels image{"waves", 128, 128, 1, std::vector<uint8_t>(128 * 128)};
    for (int y = 0; y < 128; ++y)
      for (int x = 0; x < 128; ++x) {
        const double u = (x + 0.5) / 128.0, v = 1.0 - (y + 0.5) / 128.0;
        const double w = 0.5 + 0.25 * std::sin(2.0 * matbase::kPi * (fu * u + 0.3)) + 0.2 * std::sin(2.0 * matbase::kPi * (fv * v + 3.0 * u));
        image.data[static_cast<size_t>(y * 128 + x)] = matbase::unorm8(w);
      }
    return image;
  };
  CHECK(wraps_seamlessly(waves(3.0, 5.0)));
  CHECK_FALSE(wraps_seamlessly(waves(3.4, 5.0)));  // a seam between the last column and the first
  CHECK_FALSE(wraps_seamlessly(waves(3.0, 5.5)));  // ... between the last row and the first
}

TEST_CASE("Every class has styles, and every style's maps wrap seamlessly", "[material]") {
  for (const matmaterial::MaterialClassInfo& info : matmaterial::kMaterialClasses) {
    if (info.id == matmaterial::MaterialClass::Background) continue;
    const bool has_style = std::any_of(matmaterial::library_styles().begin(), matmaterial::library_styles().end(),
                                       [&](const matmaterial::LibraryStyleInfo& s) { return s.material_class == info.id; });
    CHECK(has_style);
  }
  for (const uint32_t seed : {0u, 7u})
    for (const matmaterial::LibraryMaterialSpec& spec : every_style(seed)) {
      const matmaterial::FolderMaterial m = matmaterial::generate_library_material(spec, {128, 0});
      for (const matbase::ImagePixels* image : images_of(m)) {
        INFO(matmaterial::library_material_name(spec) << " " << image->name);
        CHECK(wraps_seamlessly(*image));
      }
    }
}

TEST_CASE("Every map stays inside its class's stated range; normals are unit vectors", "[material]") {
  for (uint32_t seed = 0; seed < 10; ++seed)
    for (const matmaterial::LibraryMaterialSpec& spec : every_style(seed)) {
      const matmaterial::FolderMaterial m = matmaterial::generate_library_material(spec, {24, 0});
      const std::vector<matmaterial::ParameterRange>& ranges = matmaterial::material_class_ranges(spec.material_class);
      INFO(matmaterial::library_material_name(spec));
      CHECK(m.material.label_id == matmaterial::label_id(spec.material_class));
      CHECK(m.material_class == spec.material_class);
      for (const matmaterial::MaterialParameterInfo& info : matmaterial::kMaterialParameters) {
        INFO(info.name);
        const matmaterial::MaterialInput& input = m.material[info.id];
        const auto range = std::find_if(ranges.begin(), ranges.end(),
                                        [&](const matmaterial::ParameterRange& r) { return r.parameter == info.id; });
        if (range == ranges.end()) {
          CHECK(input.image < 0);
          CHECK(input.value == glm::dvec3(info.default_value));
          continue;
        }
        if (input.image < 0) {
          const int channels = info.kind == matmaterial::ParameterKind::Color ? 3 : 1;
          for (int c = 0; c < channels; ++c) {
            CHECK(input.value[c] >= range->min);
            CHECK(input.value[c] <= range->max);
          }
          continue;
        }
        // A map: its factor is 1 and each texel within the range, give or take the half code
        // its value was rounded by.
        CHECK(input.value == glm::dvec3(1.0));
        const matbase::ImagePixels& image = m.images[static_cast<size_t>(input.image)];
        const int channels = info.kind == matmaterial::ParameterKind::Color ? 3 : 1;
        double low = 1e9, high = -1e9;
        for (size_t t = 0; t < static_cast<size_t>(image.width * image.height); ++t)
          for (int c = 0; c < channels; ++c) {
            const uint8_t code = matbase::texel_channel(image, t, info.kind == matmaterial::ParameterKind::Color ? c : input.channel);
            low = std::min(low, decoded(info, code + 0.5));
            high = std::max(high, decoded(info, code - 0.5));
          }
        CHECK(low >= range->min);
        CHECK(high <= range->max);
      }
      if (m.material.normal_image >= 0) {
        const matbase::ImagePixels& normals = m.images[static_cast<size_t>(m.material.normal_image)];
        for (size_t t = 0; t < static_cast<size_t>(normals.width * normals.height); ++t) {
          glm::dvec3 n;
          for (int c = 0; c < 3; ++c) n[c] = 2.0 * matbase::texel_channel(normals, t, c) / 255.0 - 1.0;
          // Each component is within half a code (1/255) of the unit vector's.
          if (std::abs(glm::length(n) - 1.0) > std::sqrt(3.0) / 255.0 || n.z <= 0.0) {
            FAIL_CHECK("texel " << t << " of the normal map is (" << n.x << ", " << n.y << ", " << n.z << ")");
            break;
          }
        }
      }
    }
}

TEST_CASE("Dielectric classes keep albedo within 0.03-0.9; metals use measured reflectances", "[material]") {
  for (const matmaterial::MaterialClassInfo& info : matmaterial::kMaterialClasses) {
    if (info.id == matmaterial::MaterialClass::Background || info.id == matmaterial::MaterialClass::Metal || info.id == matmaterial::MaterialClass::Glass)
      continue;
    INFO(info.name);
    for (const matmaterial::ParameterRange& range : matmaterial::material_class_ranges(info.id))
      if (range.parameter == P::BaseColor) {
        CHECK(range.min >= 0.03);
        CHECK(range.max <= 0.9);
      }
  }
  // Metallic 1 with a base colour among the table's reflectances.
  for (uint32_t seed = 0; seed < 8; ++seed) {
    const matmaterial::FolderMaterial m = matmaterial::generate_library_material({matmaterial::MaterialClass::Metal, "polished", seed}, {16, 0});
    CHECK(m.material.scalar(P::Metallic) == 1.0);
    CHECK(m.material[P::BaseColor].image < 0);
    const glm::dvec3 f0 = m.material.color(P::BaseColor);
    CHECK(std::any_of(matmaterial::kMetalReflectances.begin(), matmaterial::kMetalReflectances.end(),
                      [&](const matmaterial::MetalReflectance& metal) { return metal.f0 == f0; }));
  }
  // Glass transmits with an IOR; fabric has a sheen; lacquered wood and glazed ceramic a clearcoat.
  const matmaterial::FolderMaterial glass = matmaterial::generate_library_material({matmaterial::MaterialClass::Glass, "clear", 3}, {16, 0});
  CHECK(glass.material.scalar(P::Transmission) == 1.0);
  CHECK(glass.material.scalar(P::Ior) > 1.4);
  CHECK(matmaterial::generate_library_material({matmaterial::MaterialClass::Fabric, "twill", 3}, {16, 0}).material.scalar(P::Sheen) >= 0.5);
  CHECK(matmaterial::generate_library_material({matmaterial::MaterialClass::Fabric, "velvet", 3}, {16, 0}).material.color(P::VelvetColor).r > 0.0);
  CHECK(matmaterial::generate_library_material({matmaterial::MaterialClass::Wood, "lacquered", 3}, {16, 0}).material.scalar(P::Clearcoat) >= 0.7);
  CHECK(matmaterial::generate_library_material({matmaterial::MaterialClass::Ceramic, "glazed", 3}, {16, 0}).material.scalar(P::Clearcoat) == 1.0);
  const matmaterial::FolderMaterial perforated = matmaterial::generate_library_material({matmaterial::MaterialClass::Metal, "perforated", 3}, {64, 0});
  REQUIRE(perforated.material[P::Alpha].image >= 0);
  const matbase::ImagePixels& opacity = perforated.images[static_cast<size_t>(perforated.material[P::Alpha].image)];
  CHECK(std::count(opacity.data.begin(), opacity.data.end(), uint8_t{0}) > 0);    // holes
  CHECK(std::count(opacity.data.begin(), opacity.data.end(), uint8_t{255}) > 0);  // sheet
}

TEST_CASE("A seed gives the same bytes on any thread count, and another seed other bytes", "[material]") {
  for (const matmaterial::LibraryMaterialSpec& spec : every_style(11)) {
    INFO(matmaterial::library_material_name(spec));
    const matmaterial::FolderMaterial one = matmaterial::generate_library_material(spec, {48, 1});
    const matmaterial::FolderMaterial two = matmaterial::generate_library_material(spec, {48, 2});
    const matmaterial::FolderMaterial many = matmaterial::generate_library_material(spec, {48, 0});
    REQUIRE(one.images.size() == two.images.size());
    REQUIRE(one.images.size() == many.images.size());
    for (size_t i = 0; i < one.images.size(); ++i) {
      CHECK(one.images[i].data == two.images[i].data);
      CHECK(one.images[i].data == many.images[i].data);
    }
    for (size_t p = 0; p < matmaterial::kMaterialParameterCount; ++p) CHECK(one.material.inputs[p].value == two.material.inputs[p].value);
  }
  const matmaterial::FolderMaterial a = matmaterial::generate_library_material({matmaterial::MaterialClass::Wood, "raw", 1}, {32, 0});
  const matmaterial::FolderMaterial b = matmaterial::generate_library_material({matmaterial::MaterialClass::Wood, "raw", 2}, {32, 0});
  CHECK(a.images[0].data != b.images[0].data);
}

TEST_CASE("A seed without a style picks one of its class's, the same every time", "[material]") {
  int styles_seen = 0;
  std::vector<std::string> seen;
  for (uint32_t seed = 0; seed < 40; ++seed) {
    const matmaterial::LibraryMaterialSpec spec{matmaterial::MaterialClass::Wood, "", seed};
    const matmaterial::LibraryStyleInfo& style = matmaterial::resolved_style(spec);
    CHECK(style.material_class == matmaterial::MaterialClass::Wood);
    CHECK(&matmaterial::resolved_style(spec) == &style);
    // The same material as naming the picked style.
    const matmaterial::FolderMaterial picked = matmaterial::generate_library_material(spec, {16, 1});
    const matmaterial::FolderMaterial named = matmaterial::generate_library_material({matmaterial::MaterialClass::Wood, style.name, seed}, {16, 1});
    REQUIRE(picked.images.size() == named.images.size());
    for (size_t i = 0; i < picked.images.size(); ++i) CHECK(picked.images[i].data == named.images[i].data);
    if (std::find(seen.begin(), seen.end(), style.name) == seen.end()) {
      seen.push_back(style.name);
      ++styles_seen;
    }
  }
  CHECK(styles_seen == 4);  // 40 seeds reach every one of wood's four styles
}

TEST_CASE("A generated material written as a folder reads back as generated", "[material]") {
  TempDir dir;
  for (const matmaterial::LibraryMaterialSpec& spec : every_style(5)) {
    const matmaterial::FolderMaterial generated = matmaterial::generate_library_material(spec, {32, 0});
    const std::string folder = dir.file(generated.material.name);
    matmaterial::write_material_folder(generated, folder);
    const matmaterial::FolderMaterial read = matmaterial::read_material_folder(folder);
    INFO(matmaterial::library_material_name(spec));
    CHECK(read.material.name == generated.material.name);
    CHECK(read.material_class == spec.material_class);
    CHECK(read.material.label_id == generated.material.label_id);
    REQUIRE(read.tile_size_m);
    CHECK(*read.tile_size_m == Approx(matmaterial::resolved_style(spec).tile_size_m));
    for (size_t p = 0; p < matmaterial::kMaterialParameterCount; ++p) {
      const matmaterial::MaterialInput& g = generated.material.inputs[p];
      const matmaterial::MaterialInput& r = read.material.inputs[p];
      INFO(matmaterial::kMaterialParameters[p].name);
      CHECK((g.image >= 0) == (r.image >= 0));
      CHECK(r.value.x == Approx(g.value.x));
      CHECK(r.value.z == Approx(g.value.z));
      if (g.image < 0 || r.image < 0) continue;
      const matbase::ImagePixels& gi = generated.images[static_cast<size_t>(g.image)];
      const matbase::ImagePixels& ri = read.images[static_cast<size_t>(r.image)];
      REQUIRE(gi.width == ri.width);
      bool same = true;
      for (size_t t = 0; t < static_cast<size_t>(gi.width * gi.height); ++t)
        for (int c = 0; c < 3; ++c) same = same && matbase::texel_channel(gi, t, c) == matbase::texel_channel(ri, t, c);
      CHECK(same);
    }
    CHECK((generated.material.normal_image >= 0) == (read.material.normal_image >= 0));
    CHECK((generated.height_image >= 0) == (read.height_image >= 0));
  }
}

TEST_CASE("Material specs parse, and each mistake gets its own message", "[material]") {
  const matmaterial::LibraryMaterialSpec plain = matmaterial::parse_library_material("wood");
  CHECK(plain.material_class == matmaterial::MaterialClass::Wood);
  CHECK(plain.style.empty());
  CHECK(plain.seed == 0);
  const matmaterial::LibraryMaterialSpec full = matmaterial::parse_library_material("Wood/wicker:3");
  CHECK(full.material_class == matmaterial::MaterialClass::Wood);
  CHECK(full.style == "wicker");
  CHECK(full.seed == 3);
  CHECK(matmaterial::library_material_name(full) == "wood/wicker:3");
  CHECK(matmaterial::parse_library_material("glass:4294967295").seed == 4294967295u);
  CHECK(matmaterial::parse_library_material(matmaterial::library_material_name(matmaterial::parse_library_material("metal:9"))).style ==
        matmaterial::resolved_style(matmaterial::parse_library_material("metal:9")).name);
  const auto error = [](const std::string& text) {
    try {
      matmaterial::parse_library_material(text);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK_THAT(error("banana"), Contains("no material class \"banana\""));
  CHECK_THAT(error("background"), Contains("no material class \"background\""));
  CHECK_THAT(error("wood/velvet"), Contains("no style \"velvet\" of wood (styles: raw, lacquered, painted, wicker)"));
  CHECK_THAT(error("wood:"), Contains("the seed after ':' must be a whole number"));
  CHECK_THAT(error("wood:-1"), Contains("the seed after ':' must be a whole number"));
  CHECK_THAT(error("wood:3x"), Contains("the seed after ':' must be a whole number"));
  CHECK_THAT(error("wood:4294967296"), Contains("the seed after ':' must be a whole number"));
  CHECK_THROWS_WITH(matmaterial::generate_library_material({matmaterial::MaterialClass::Wood, "", 0}, {4, 0}), Contains("resolution 4"));
  CHECK_THROWS_WITH(matmaterial::generate_library_material({matmaterial::MaterialClass::Background, "", 0}, {16, 0}),
                    Contains("no background materials"));
}

TEST_CASE("docs/material_library.md lists the styles and ranges exactly as the tables have them", "[material]") {
  std::ifstream in(MATPREDICT_MATERIAL_LIBRARY_DOC);
  REQUIRE(in);
  std::stringstream text;
  text << in.rdbuf();
  INFO("regenerate the tables with: render_object --list-materials");
  CHECK(text.str().find(matmaterial::library_styles_markdown()) != std::string::npos);
  CHECK(text.str().find(matmaterial::library_ranges_markdown()) != std::string::npos);
}
