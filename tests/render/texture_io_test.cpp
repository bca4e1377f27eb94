// Image textures read through OpenImageIO from real files, sampled as Cycles' "Linear"
// interpolation; frames written to EXR/PNG read back with the values rendered.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include "matbase/image/srgb.h"
#include "matrender/image_io.h"
#include "matrender/texture.h"

using namespace matrender;
namespace fs = std::filesystem;

namespace {

fs::path temp_dir() {
  const fs::path dir = fs::temp_directory_path() / ("matrender_texture_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

// Pixels written as given; a fourth channel is PNG's straight alpha, not divided out.
template <typename T>
void write_image(const fs::path& path, int w, int h, int channels, OIIO::TypeDesc type, const std::vector<T>& pixels) {
  auto out = OIIO::ImageOutput::create(path.string());
  REQUIRE(out);
  OIIO::ImageSpec spec(w, h, channels, type);
  spec.attribute("oiio:UnassociatedAlpha", 1);
  REQUIRE(out->open(path.string(), spec));
  REQUIRE(out->write_image(type, pixels.data()));
  out->close();
}

// sRGB decoding written out from IEC 61966-2-1 for the expectations.
double srgb_decode(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

}  // namespace

TEST_CASE("8-bit PNG textures are filtered on encoded values, then decoded", "[render]") {
  const fs::path dir = temp_dir();
  // 2 x 2 RGB, rows top to bottom: top row (0, 255), bottom row (64, 128) in every channel.
  const std::vector<uint8_t> pixels = {0, 0, 0, 255, 255, 255, 64, 64, 64, 128, 128, 128};
  write_image(dir / "t.png", 2, 2, 3, OIIO::TypeDesc::UINT8, pixels);
  const auto srgb = Texture::load((dir / "t.png").string(), ColorSpace::SRGB);
  const auto data = Texture::load((dir / "t.png").string(), ColorSpace::NonColor);
  // Texel centres at (i + 0.5) / 2; v = 0 is the bottom row.
  CHECK(data->sample({0.25f, 0.25f}).x == Approx(64 / 255.0));
  CHECK(data->sample({0.75f, 0.75f}).x == Approx(1.0));
  CHECK(srgb->sample({0.25f, 0.25f}).x == Approx(srgb_decode(64 / 255.0)).epsilon(1e-5));
  // Half-way between the bottom texels: mix of encoded values, then decoded.
  const double encoded_mid = 0.5 * (64 + 128) / 255.0;
  CHECK(srgb->sample({0.5f, 0.25f}).y == Approx(srgb_decode(encoded_mid)).epsilon(1e-5));
  // Bilinear in the centre of all four.
  CHECK(data->sample({0.5f, 0.5f}).z == Approx((0 + 255 + 64 + 128) / (4 * 255.0)).epsilon(1e-6));
  // Repeat wraps u = 1.25 to 0.25; alpha defaults to 1 for RGB images.
  CHECK(data->sample({1.25f, 0.25f}).x == Approx(64 / 255.0));
  CHECK(data->sample({0.25f, 0.25f}).w == 1.0f);
  fs::remove_all(dir);
}

TEST_CASE("RGBA textures give their stored colour whatever the alpha, as Cycles' straight alpha", "[render]") {
  const fs::path dir = temp_dir();
  const std::vector<uint8_t> pixels = {200, 100, 50, 64};  // one texel, a quarter opaque
  write_image(dir / "a.png", 1, 1, 4, OIIO::TypeDesc::UINT8, pixels);
  const glm::vec4 texel = Texture::load((dir / "a.png").string(), ColorSpace::NonColor)->sample({0.5f, 0.5f});
  CHECK(texel.x == Approx(200 / 255.0));
  CHECK(texel.z == Approx(50 / 255.0));
  CHECK(texel.w == Approx(64 / 255.0));
  fs::remove_all(dir);
}

TEST_CASE("Display PNGs store straight alpha: a partly covered pixel keeps the surface's colour", "[render]") {
  const fs::path dir = temp_dir();
  // A surface of linear 0.5 covering a quarter of the pixel, premultiplied as rendered.
  const std::vector<float> premultiplied = {0.125f, 0.125f, 0.0f}, coverage = {0.25f};
  matbase::write_display_png((dir / "d.png").string(), 1, 1, premultiplied.data(), coverage.data());
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open((dir / "d.png").string(), &config);
  REQUIRE(in);
  std::vector<uint8_t> stored(4);
  REQUIRE(in->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, stored.data()));
  // sRGB OETF of 0.5 (IEC 61966-2-1): 1.055 * 0.5^(1/2.4) - 0.055 = 0.7354, 187.5 -> 188.
  CHECK(int(stored[0]) == 188);
  CHECK(int(stored[2]) == 0);
  CHECK(int(stored[3]) == 64);
  fs::remove_all(dir);
}

TEST_CASE("Clamp holds the edge texel; repeat blends across the seam", "[render]") {
  const std::vector<float> ramp = {0.0f, 1.0f};  // 2 x 1, grey
  const auto clamped = Texture::from_pixelsf(2, 1, 1, ramp.data(), ColorSpace::NonColor, TextureWrap::Clamp);
  const auto repeated = Texture::from_pixelsf(2, 1, 1, ramp.data(), ColorSpace::NonColor, TextureWrap::Repeat);
  CHECK(clamped->sample({0.0f, 0.5f}).x == Approx(0.0f));
  CHECK(clamped->sample({-3.0f, 0.5f}).x == Approx(0.0f));
  CHECK(clamped->sample({5.0f, 0.5f}).x == Approx(1.0f));
  CHECK(repeated->sample({0.0f, 0.5f}).x == Approx(0.5f));  // halfway between texel 1 and texel 0
  CHECK(std::isfinite(repeated->sample({1e30f, -1e30f}).x));
}

TEST_CASE("EXR, TIFF and JPEG textures load; float sRGB images decode at load", "[render]") {
  const fs::path dir = temp_dir();
  const std::vector<float> linear = {0.25f, 0.5f, 2.0f, 1.0f};  // 1 x 1 RGBA, HDR value
  write_image(dir / "t.exr", 1, 1, 4, OIIO::TypeDesc::FLOAT, linear);
  const auto exr = Texture::load((dir / "t.exr").string(), ColorSpace::NonColor);
  CHECK(exr->sample({0.3f, 0.7f}) == glm::vec4(0.25f, 0.5f, 2.0f, 1.0f));
  const auto exr_srgb = Texture::load((dir / "t.exr").string(), ColorSpace::SRGB);
  CHECK(exr_srgb->sample({0.5f, 0.5f}).x == Approx(srgb_decode(0.25)).epsilon(1e-5));

  const std::vector<uint16_t> sixteen = {0, 65535, 32768, 1000};
  write_image(dir / "t.tif", 2, 2, 1, OIIO::TypeDesc::UINT16, sixteen);
  const auto tif = Texture::load((dir / "t.tif").string(), ColorSpace::NonColor);
  CHECK(tif->sample({0.75f, 0.75f}).x == Approx(1.0f));
  CHECK(tif->sample({0.25f, 0.25f}).y == Approx(32768 / 65535.0f));

  const std::vector<uint8_t> grey(8 * 8 * 3, 200);
  write_image(dir / "t.jpg", 8, 8, 3, OIIO::TypeDesc::UINT8, grey);
  const auto jpg = Texture::load((dir / "t.jpg").string(), ColorSpace::NonColor);
  CHECK(jpg->sample({0.5f, 0.5f}).x == Approx(200 / 255.0f).margin(2 / 255.0f));
  fs::remove_all(dir);
}

TEST_CASE("A missing or corrupt texture is an error naming the file", "[render]") {
  const fs::path dir = temp_dir();
  CHECK_THROWS_WITH(Texture::load((dir / "missing.png").string(), ColorSpace::SRGB),
                    Catch::Contains("missing.png"));
  std::FILE* f = std::fopen((dir / "broken.png").c_str(), "wb");
  const char junk[] = "\x89PNG\r\n\x1a\n this is not a png";
  std::fwrite(junk, 1, sizeof junk, f);
  std::fclose(f);
  CHECK_THROWS_WITH(Texture::load((dir / "broken.png").string(), ColorSpace::SRGB), Catch::Contains("broken.png"));
  fs::remove_all(dir);
}

TEST_CASE("write_frame writes EXR values exactly and leaves no temporary files", "[render]") {
  const fs::path dir = temp_dir();
  FrameBuffers frame;
  frame.resize(3, 2, all_aovs());
  frame.transparent_background = true;
  for (size_t i = 0; i < frame.alpha.size(); ++i) frame.alpha[i] = 0.25f * static_cast<float>(i % 4);
  for (size_t i = 0; i < frame.color.size(); ++i) frame.color[i] = 0.1f * static_cast<float>(i);
  for (size_t i = 0; i < frame.depth.size(); ++i) frame.depth[i] = 1.5f + static_cast<float>(i);
  frame.label[4] = 7;
  const auto written = write_frame(frame, (dir / "out").string(), "v");
  // Colour, then an EXR and a PNG per material parameter (named as in the table) and per
  // other AOV (three normals, ambient occlusion, colour variance, depth, label, part id, object
  // id, sample count), and the alpha PNG.
  CHECK(written.size() == 2 + 2 * matmaterial::kMaterialParameterCount + 2 * 10 + 1);
  for (const auto& path : written) CHECK(fs::exists(path));
  for (const matmaterial::MaterialParameterInfo& info : matmaterial::kMaterialParameters)
    for (const char* extension : {".exr", ".png"})
      CHECK(fs::exists(dir / "out" / (std::string("v_") + info.name + extension)));
  for (const auto& entry : fs::directory_iterator(dir / "out"))
    CHECK(entry.path().filename().string().rfind(".tmp", 0) != 0);

  auto in = OIIO::ImageInput::open((dir / "out" / "v_color.exr").string());
  REQUIRE(in);
  std::vector<float> rgba(3 * 2 * 4);
  REQUIRE(in->read_image(0, 0, 0, 4, OIIO::TypeDesc::FLOAT, rgba.data()));
  CHECK(rgba[4 * 5 + 2] == frame.color[3 * 5 + 2]);
  CHECK(rgba[4 * 3 + 3] == frame.alpha[3]);  // transparent render: A = coverage
  auto depth = OIIO::ImageInput::open((dir / "out" / "v_depth.exr").string());
  std::vector<float> z(6);
  REQUIRE(depth->read_image(0, 0, 0, 1, OIIO::TypeDesc::FLOAT, z.data()));
  CHECK(z[3] == 4.5f);
  auto label = OIIO::ImageInput::open((dir / "out" / "v_label.png").string());
  std::vector<uint16_t> ids(6);
  REQUIRE(label->read_image(0, 0, 0, 1, OIIO::TypeDesc::UINT16, ids.data()));
  CHECK(ids[4] == 7);
  fs::remove_all(dir);
}

TEST_CASE("sRGB images with alpha filter premultiplied, as Blender's Straight alpha mode", "[render]") {
  // The texels Blender 3.4 was probed with (docs/conventions.md, "Alpha"): red of alpha 0 beside
  // green of alpha 1. Cycles renders, along the row, the premultiplied colour when the alpha is not
  // used, and that colour divided by the filtered alpha when it is; the red never shows.
  const fs::path dir = temp_dir();
  const std::vector<uint8_t> pixels = {255, 0, 0, 0, 0, 255, 0, 255};
  write_image(dir / "edge.png", 2, 1, 4, OIIO::TypeDesc::UINT8, pixels);
  const TexturePtr image = Texture::load((dir / "edge.png").string(), ColorSpace::SRGB);
  CHECK(image->associated_alpha());
  // A quarter of the way from the red texel's centre to the green one's.
  const glm::vec2 uv(0.25f + 0.125f, 0.5f);
  const glm::vec4 premultiplied = image->sample(uv);
  CHECK(premultiplied.x == 0.0f);
  CHECK(premultiplied.y == Approx(matbase::srgb_to_linear(0.25f)).epsilon(1e-5));
  CHECK(premultiplied.w == Approx(0.25f));
  const glm::vec4 unassociated = image->sample(uv, true);
  CHECK(unassociated.x == 0.0f);
  CHECK(unassociated.y == Approx(1.0f).epsilon(1e-5));
  CHECK(unassociated.w == Approx(0.25f));
  // The same file as data keeps its channels as stored, red included.
  const TexturePtr data = Texture::load((dir / "edge.png").string(), ColorSpace::NonColor);
  CHECK_FALSE(data->associated_alpha());
  CHECK(data->sample(uv).x == Approx(0.75f).epsilon(1e-5));
  fs::remove_all(dir);
}

TEST_CASE("A UDIM set looks each UV up in its own tile, on both sides of a border, loading tiles when hit", "[render]") {
  // Tiles 1001 (u in [0, 1)) red, 1002 ([1, 2)) green, 1011 (v in [1, 2)) blue, each 4 x 4 and
  // one colour, so a lookup's colour says which tile it read.
  const fs::path dir = temp_dir();
  const auto write_tile = [&](int number, uint8_t r, uint8_t g, uint8_t b) {
    std::vector<uint8_t> pixels;
    for (int i = 0; i < 16; ++i) pixels.insert(pixels.end(), {r, g, b});
    write_image(dir / ("wood." + std::to_string(number) + ".png"), 4, 4, 3, OIIO::TypeDesc::UINT8, pixels);
  };
  write_tile(1001, 255, 0, 0);
  write_tile(1002, 0, 255, 0);
  write_tile(1011, 0, 0, 255);
  write_image(dir / "wood.png", 1, 1, 3, OIIO::TypeDesc::UINT8, std::vector<uint8_t>{9, 9, 9});  // not a tile
  const TexturePtr set = Texture::load((dir / "wood.<UDIM>.png").string(), ColorSpace::NonColor);
  CHECK(set->udim_tiles() == std::vector<int>{1001, 1002, 1011});
  CHECK(set->loaded_udim_tiles() == 0);
  CHECK(set->sample({0.999f, 0.5f}) == glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
  CHECK(set->loaded_udim_tiles() == 1);
  CHECK(set->sample({1.001f, 0.5f}) == glm::vec4(0.0f, 1.0f, 0.0f, 1.0f));
  CHECK(set->sample({0.5f, 1.001f}) == glm::vec4(0.0f, 0.0f, 1.0f, 1.0f));
  CHECK(set->loaded_udim_tiles() == 3);
  // As Cycles 3.4's svm_node_tex_image: u and v in (-1, 0) truncate to tile 1001 (wrapped); a
  // tile the set does not have, u left of -1 and u past 10 read the missing-texture magenta.
  CHECK(set->sample({-0.5f, 0.5f}) == glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
  CHECK(set->sample({0.5f, -0.5f}) == glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
  const glm::vec4 magenta(1.0f, 0.0f, 1.0f, 1.0f);
  CHECK(set->sample({2.5f, 0.5f}) == magenta);
  CHECK(set->sample({-1.5f, 0.5f}) == magenta);
  CHECK(set->sample({10.5f, 0.5f}) == magenta);
  // A pattern with no tiles, and a tile that is no image, are errors naming the files.
  CHECK_THROWS_WITH(Texture::load((dir / "oak.<UDIM>.png").string(), ColorSpace::SRGB),
                    Catch::Contains("oak.<UDIM>.png: no UDIM tile files (oak.1001.png, ...) found"));
  std::ofstream(dir / "bad.1001.png") << "not an image";
  CHECK_THROWS_WITH(Texture::load((dir / "bad.<UDIM>.png").string(), ColorSpace::SRGB),
                    Catch::Contains("bad.1001.png: cannot read image"));
  fs::remove_all(dir);
}
