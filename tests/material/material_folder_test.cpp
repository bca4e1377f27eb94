// Material folders (matmaterial/folder/material_folder.h): maps found by the names MatSynth and PBR packs
// use, colour spaces and normal conventions, resampling, metadata, what the writer writes reads
// back the same, and one message per kind of broken folder.
#include "matmaterial/folder/material_folder.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "matbase/image/png_encoding.h"
#include "matmaterial/material_parameters.h"
#include "support/temp_dir.h"

using matmaterial::FolderMap;
using matmaterial::FolderMaterial;
using matbase::ImagePixels;
using matmaterial::MaterialClass;
using P = matmaterial::MaterialParameter;
using Catch::Matchers::Contains;

namespace {

// A width x height RGBA image whose texel (x, y) is texel(x, y).
template <class F>
ImagePixels rgba_image(const std::string& name, int width, int height, F texel) {
  ImagePixels image{name, width, height, 4, std::vector<uint8_t>(static_cast<size_t>(width * height) * 4u)};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::array<uint8_t, 4> t = texel(x, y);
      for (size_t c = 0; c < 4; ++c) image.data[static_cast<size_t>(y * width + x) * 4u + c] = t[c];
    }
  return image;
}

ImagePixels grey_image(const std::string& name, int size, uint8_t value) {
  return rgba_image(name, size, size, [&](int, int) { return std::array<uint8_t, 4>{value, value, value, 255}; });
}

void write_png(const std::filesystem::path& path, const ImagePixels& image) {
  std::ofstream(path, std::ios::binary) << matbase::encode_png(image, path.string());
}

void write_text(const std::filesystem::path& path, const std::string& text) { std::ofstream(path) << text; }

// A normal map tilted toward +v in OpenGL's convention (green above 128) or the same surface in
// DirectX's (green below 128).
ImagePixels tilted_normal_map(const std::string& name, int size, bool directx) {
  const uint8_t green = directx ? 90 : 165;
  return rgba_image(name, size, size, [&](int x, int) {
    return std::array<uint8_t, 4>{static_cast<uint8_t>(120 + x), green, 230, 255};
  });
}

std::string read_error(const std::string& folder) {
  try {
    matmaterial::read_material_folder(folder);
  } catch (const std::runtime_error& error) {
    return error.what();
  }
  return "";
}

}  // namespace

TEST_CASE("A written material folder reads back the same", "[geom]") {
  TempDir dir;
  FolderMaterial written;
  written.material = matmaterial::MaterialInputs("lacquered_oak");
  written.images = {
      rgba_image("base", 8, 8,
                 [](int x, int y) {
                   return std::array<uint8_t, 4>{static_cast<uint8_t>(20 * x), static_cast<uint8_t>(30 * y), 77, 255};
                 }),
      grey_image("roughness", 8, 140),
      grey_image("metallic", 8, 0),
      tilted_normal_map("normal", 8, false),
      grey_image("opacity", 8, 255),
      grey_image("height", 8, 60)};
  written.material.set(P::BaseColor, 1.0).set_image(P::BaseColor, 0);
  written.material.set(P::Roughness, 1.0).set_image(P::Roughness, 1);
  written.material.set(P::Metallic, 1.0).set_image(P::Metallic, 2);
  written.material.normal_image = 3;
  written.material.set(P::Alpha, 1.0).set_image(P::Alpha, 4);
  written.height_image = 5;
  // Constants the maps cannot carry: a lacquer, an index, a factor on the roughness map.
  written.material.set(P::Clearcoat, 0.5).set(P::Ior, 1.33).set(P::Roughness, 0.8);
  written.material.set(P::VelvetColor, glm::dvec3(0.1, 0.2, 0.3));
  written.material_class = MaterialClass::Wood;
  written.material.label_id = matmaterial::label_id(MaterialClass::Wood);
  written.tile_size_m = 0.75;
  const std::string folder = (dir.path() / "lacquered_oak").string();
  matmaterial::write_material_folder(written, folder);

  const FolderMaterial read = matmaterial::read_material_folder(folder);
  CHECK(read.material.name == "lacquered_oak");
  CHECK(read.material_class == MaterialClass::Wood);
  CHECK(read.material.label_id == 7);
  REQUIRE(read.tile_size_m);
  CHECK(*read.tile_size_m == Approx(0.75));
  for (const matmaterial::MaterialParameterInfo& info : matmaterial::kMaterialParameters) {
    CAPTURE(info.name);
    CHECK(read.material.color(info.id) == written.material.color(info.id));
    CHECK((read.material[info.id].image >= 0) == (written.material[info.id].image >= 0));
  }
  const auto same_image = [&](int a, int b) {
    REQUIRE(a >= 0);
    REQUIRE(b >= 0);
    const ImagePixels& x = written.images[static_cast<size_t>(a)];
    const ImagePixels& y = read.images[static_cast<size_t>(b)];
    CHECK(y.width == x.width);
    CHECK(y.height == x.height);
    CHECK(y.data == x.data);  // PNG is lossless, the maps are grey or RGB as written
  };
  for (const P p : {P::BaseColor, P::Roughness, P::Metallic, P::Alpha})
    same_image(written.material[p].image, read.material[p].image);
  same_image(written.material.normal_image, read.material.normal_image);
  same_image(written.height_image, read.height_image);
  CHECK(read.specular_image == -1);
  CHECK(read.files[static_cast<size_t>(FolderMap::BaseColor)] ==
        (dir.path() / "lacquered_oak" / "basecolor.png").string());
  CHECK(read.files[static_cast<size_t>(FolderMap::Specular)].empty());
}

TEST_CASE("Maps are found by the names MatSynth and PBR packs give them", "[geom]") {
  TempDir dir;
  const std::filesystem::path folder = dir.path() / "Fabric_Denim_02";
  std::filesystem::create_directories(folder);
  // ambientCG-style names: a colour map, a DirectX normal map, a displacement map, and files
  // that are no map (a preview, a specular colour that is not the base colour).
  write_png(folder / "Denim02_2K_Color.png", grey_image("c", 4, 100));
  write_png(folder / "Denim02_2K_Roughness.png", grey_image("r", 4, 200));
  write_png(folder / "Denim02_2K_NormalDX.png", tilted_normal_map("n", 4, true));
  write_png(folder / "Denim02_2K_Displacement.png", grey_image("d", 4, 10));
  write_png(folder / "specular_color.png", grey_image("s", 4, 30));
  write_png(folder / "preview.png", grey_image("p", 4, 1));
  write_text(folder / "readme.txt", "not an image");
  const FolderMaterial m = matmaterial::read_material_folder(folder.string());
  CHECK(m.files[static_cast<size_t>(FolderMap::BaseColor)] == (folder / "Denim02_2K_Color.png").string());
  CHECK(m.files[static_cast<size_t>(FolderMap::Roughness)] == (folder / "Denim02_2K_Roughness.png").string());
  CHECK(m.files[static_cast<size_t>(FolderMap::Normal)] == (folder / "Denim02_2K_NormalDX.png").string());
  CHECK(m.files[static_cast<size_t>(FolderMap::Height)] == (folder / "Denim02_2K_Displacement.png").string());
  CHECK(m.files[static_cast<size_t>(FolderMap::Specular)] == (folder / "specular_color.png").string());
  CHECK(m.files[static_cast<size_t>(FolderMap::Metallic)].empty());
  // The class from the folder's name, as the repository finds it; no metadata, no tile size.
  CHECK(m.material_class == MaterialClass::Fabric);
  CHECK(m.material.label_id == 2);
  CHECK_FALSE(m.tile_size_m);
  // A missing map leaves Blender's default; a found one is a factor of 1 times the image.
  CHECK(m.material.scalar(P::Metallic) == 0.0);
  CHECK(m.material[P::Metallic].image == -1);
  CHECK(m.material.scalar(P::Roughness) == 1.0);
  // DirectX's green (90, pointing to -v) is flipped to OpenGL's (165, pointing to +v).
  const ImagePixels& normal = m.images[static_cast<size_t>(m.material.normal_image)];
  CHECK(normal.data[1] == 255 - 90);
  CHECK(normal.data[0] == 120);

  SECTION("an option overrides what the name says") {
    matmaterial::MaterialFolderOptions options;
    options.normal_convention = matmaterial::NormalConvention::OpenGL;
    const FolderMaterial kept = matmaterial::read_material_folder(folder.string(), options);
    CHECK(kept.images[static_cast<size_t>(kept.material.normal_image)].data[1] == 90);
  }
  SECTION("metadata.json says what MatSynth's metadata says") {
    write_text(folder / "metadata.json",
               R"({"name": "Denim", "category": "Leather", "physical_size": 150, "normal_convention": "opengl"})");
    const FolderMaterial described = matmaterial::read_material_folder(folder.string());
    CHECK(described.material_class == MaterialClass::Leather);  // the category before the folder's name
    REQUIRE(described.tile_size_m);
    CHECK(*described.tile_size_m == Approx(1.5));  // centimetres
    CHECK(described.images[static_cast<size_t>(described.material.normal_image)].data[1] == 90);
    // MatSynth's categories without a class of ours leave it to the folder's name.
    write_text(folder / "metadata.json", R"({"category": "ground"})");
    CHECK(matmaterial::read_material_folder(folder.string()).material_class == MaterialClass::Fabric);
  }
}

TEST_CASE("A folder's own base colour wins over its diffuse map, and maps of other sizes are resampled", "[geom]") {
  TempDir dir;
  const std::filesystem::path folder = dir.path() / "plaster_3";
  std::filesystem::create_directories(folder);
  write_png(folder / "basecolor.png", grey_image("b", 8, 180));
  write_png(folder / "diffuse.png", grey_image("d", 8, 20));
  write_png(folder / "roughness.png", grey_image("r", 2, 100));
  // An RGB roughness map reads as its luminance, as Blender feeds a colour to a float input.
  write_png(folder / "metallic.png", rgba_image("m", 16, 16, [](int, int) {
              return std::array<uint8_t, 4>{200, 100, 0, 255};
            }));
  const FolderMaterial m = matmaterial::read_material_folder(folder.string());
  CHECK(m.files[static_cast<size_t>(FolderMap::BaseColor)] == (folder / "basecolor.png").string());
  CHECK(m.material_class == MaterialClass::Plaster);
  for (const P p : {P::BaseColor, P::Roughness, P::Metallic}) {
    const ImagePixels& image = m.images[static_cast<size_t>(m.material[p].image)];
    CHECK(image.width == 8);
    CHECK(image.height == 8);
  }
  // A constant image stays the same constant through the resampling filter.
  const ImagePixels& roughness = m.images[static_cast<size_t>(m.material[P::Roughness].image)];
  for (size_t i = 0; i < roughness.data.size(); i += 4) CHECK(roughness.data[i] == 100);
  const ImagePixels& metallic = m.images[static_cast<size_t>(m.material[P::Metallic].image)];
  // 0.2126 200 + 0.7152 100 + 0.0722 0 = 114.04
  for (size_t i = 0; i < metallic.data.size(); i += 4) {
    CHECK(metallic.data[i] == 114);
    CHECK(metallic.data[i + 1] == 114);
  }
}

TEST_CASE("Each kind of broken material folder gets its own message", "[geom]") {
  TempDir dir;
  const std::filesystem::path folder = dir.path() / "wood_1";
  CHECK_THAT(read_error(folder.string()), Contains(folder.string() + ": no such folder"));
  write_text(dir.path() / "a_file", "x");
  CHECK_THAT(read_error((dir.path() / "a_file").string()), Contains("a_file: not a folder"));
  std::filesystem::create_directories(folder);
  CHECK_THAT(read_error(folder.string()), Contains(folder.string() + ": no material map in the folder"));
  write_text(folder / "basecolor.png", "not a PNG");
  CHECK_THAT(read_error(folder.string()), Contains((folder / "basecolor.png").string() + ": cannot decode the image"));
  write_png(folder / "basecolor.png", grey_image("b", 4, 128));
  write_png(folder / "normal.png", grey_image("n", 4, 128));
  CHECK_THAT(read_error(folder.string()), Contains((folder / "normal.png").string() + ": the normal map is grey"));
  std::filesystem::remove(folder / "normal.png");
  const std::string metadata = (folder / "metadata.json").string();
  for (const auto& [text, problem] :
       {std::pair{"{\"category\": ", "not valid JSON"}, std::pair{"[1, 2]", "expected a JSON object"},
        std::pair{R"({"physical_size": -3})", "/physical_size: expected a number greater than 0, got -3"},
        std::pair{R"({"normal_convention": "metal"})", "/normal_convention: expected one of \"opengl\", \"directx\", got \"metal\""},
        std::pair{R"({"parameters": {"shininess": 3}})", "/parameters/shininess: unknown material parameter"},
        std::pair{R"({"parameters": {"ior": 0.5}})", "/parameters/ior: expected a number from 1 to 1000, got 0.5"},
        std::pair{R"({"parameters": {"base_color": 0.5}})", "/parameters/base_color: expected [r, g, b], got 0.5"},
        // A misspelt class used to give the folder label 0 without a word.
        std::pair{R"({"category": "Wod"})",
                  "/category: unknown category \"Wod\" (known: concrete, fabric, leather, metal, plastic, stone, wood, "
                  "marble, ceramic, terracotta, plaster, rubber, paper, glass, ground, misc, blends)"},
        std::pair{R"({"category": "background"})", "/category: unknown category \"background\""},
        std::pair{R"({"category": "wood", "category": "metal"})", "/category: given twice; say it once"}}) {
    CAPTURE(text);
    write_text(metadata, text);
    CHECK_THAT(read_error(folder.string()), Contains(metadata + ": " + problem));
  }
  // metadata.json saved by Windows Notepad as "Unicode" (UTF-16, little-endian) reads as the same
  // text; a roughness map only as EXR is refused by name rather than left out.
  std::string utf16 = "\xFF\xFE";
  for (const char c : std::string(R"({"category": "wood"})")) utf16 += std::string{c, '\0'};
  std::ofstream(metadata, std::ios::binary) << utf16;
  CHECK(read_error(folder.string()).empty());
  write_text(folder / "wood_roughness.exr", "an EXR file");
  CHECK_THAT(read_error(folder.string()),
             Contains(folder.string() + ": the roughness map wood_roughness.exr is in EXR format, which material folders do "
                                        "not read (PNG, JPEG, BMP or TGA)"));
  write_png(folder / "wood_roughness.png", grey_image("r", 4, 100));
  CHECK(read_error(folder.string()).empty());
}

TEST_CASE("write_material_folder refuses what a folder cannot hold and leaves nothing behind", "[geom]") {
  TempDir dir;
  FolderMaterial m;
  m.material = matmaterial::MaterialInputs("coat");
  m.images = {grey_image("g", 4, 10)};
  m.material.set_image(P::Clearcoat, 0);
  const std::string folder = (dir.path() / "coat").string();
  CHECK_THROWS_WITH(matmaterial::write_material_folder(m, folder),
                    Contains("clearcoat comes from an image, and a material folder has no map for it"));
  m.material = matmaterial::MaterialInputs("packed");
  m.material.set_image(P::Roughness, 0, 1);
  CHECK_THROWS_WITH(matmaterial::write_material_folder(m, folder), Contains("roughness reads image channel 1"));
  CHECK_FALSE(std::filesystem::exists(folder));
}
