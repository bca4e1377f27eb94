// The environment light: Cycles 3.4's equirectangular mapping (checked at the poles, the seam and
// the horizon against what Blender 3.4.1 rendered), chi-square of its sampled directions against
// its pdf, and renders that converge to textbook closed forms: the albedo under a constant map,
// and the irradiance of a linear map, a (c0 + 2/3 c.n), on planes facing several ways.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>

#include <glm/gtc/matrix_transform.hpp>
#include <functional>
#include <vector>

#include "chi_square.h"
#include "lights/environment_light.h"
#include "lights/light_sampler.h"
#include "matbase/image/image_writing.h"
#include "matbase/pi.h"
#include "matbase/input_error.h"
#include "matrender/builtin_environments.h"
#include "matrender/camera.h"
#include "matrender/render.h"
#include "matrender/scene.h"
#include "matrender/scene_file.h"
#include "matrender/sky.h"
#include "test_scenes.h"
#include "texture/negative_radiance.h"
#include "uniform_floats.h"

using namespace matrender;

namespace {

// The direction at (u, v) by the definition u = 0.5 - atan2(y, x) / 2pi, v = 1 - acos(z) / pi.
glm::dvec3 direction_at(double u, double v) {
  const double phi = matbase::kPi * (1.0 - 2.0 * u), theta = matbase::kPi * (1.0 - v);
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

// A width x height map whose texel at column x, row y (0 = top) is texel(x, y).
TexturePtr map_of(int width, int height, const std::function<glm::vec3(int, int)>& texel) {
  std::vector<float> pixels;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const glm::vec3 c = texel(x, y);
      pixels.insert(pixels.end(), {c.x, c.y, c.z});
    }
  return Texture::from_pixelsf(width, height, 3, pixels.data(), ColorSpace::NonColor);
}

// The map of radiance(d) at each texel's centre direction.
TexturePtr map_of_function(int width, int height, const std::function<glm::vec3(const glm::dvec3&)>& radiance) {
  return map_of(width, height, [&](int x, int y) {
    return radiance(direction_at((x + 0.5) / width, 1.0 - (y + 0.5) / height));
  });
}

glm::vec3 rotated_about_z(const glm::vec3& d, double angle) {
  const float c = static_cast<float>(std::cos(angle)), s = static_cast<float>(std::sin(angle));
  return {c * d.x - s * d.y, s * d.x + c * d.y, d.z};
}

// Blender's probe map (docs/conventions.md, Environment): the top row red, the bottom row blue,
// between them green with a yellow first column and a cyan last one.
TexturePtr probe_map() {
  constexpr int kWidth = 64, kHeight = 32;
  return map_of(kWidth, kHeight, [](int x, int y) {
    if (y == 0) return glm::vec3(1, 0, 0);
    if (y == kHeight - 1) return glm::vec3(0, 0, 1);
    if (x == 0) return glm::vec3(1, 1, 0);
    if (x == kWidth - 1) return glm::vec3(0, 1, 1);
    return glm::vec3(0, 1, 0);
  });
}

void check_color(const glm::vec3& got, const glm::vec3& expected, float margin) {
  INFO("got (" << got.x << ", " << got.y << ", " << got.z << "), expected (" << expected.x << ", " << expected.y
               << ", " << expected.z << ")");
  CHECK(glm::all(glm::lessThanEqual(glm::abs(got - expected), glm::vec3(margin))));
}

}  // namespace

TEST_CASE("The equirectangular mapping puts +X at the centre column, +Y a quarter left of it, +Z on top", "[render]") {
  const auto uv = [](glm::vec3 d) { return equirectangular_uv(glm::normalize(d)); };
  CHECK(uv({1, 0, 0}).x == Approx(0.5));
  CHECK(uv({0, 1, 0}).x == Approx(0.25));
  CHECK(uv({0, -1, 0}).x == Approx(0.75));
  // -X is the seam: atan2 gives +-pi, u = 0 or 1.
  CHECK(std::abs(uv({-1, 0, 0}).x - 0.5f) == Approx(0.5));
  for (glm::vec3 horizon : {glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(-1, 0, 0), glm::vec3(0, -1, 0)})
    CHECK(uv(horizon).y == Approx(0.5));
  CHECK(uv({0, 0, 1}).y == Approx(1.0));
  CHECK(uv({0, 0, -1}).y == Approx(0.0).margin(1e-7));
  UniformFloats rng(7);
  for (int i = 0; i < 1000; ++i) {
    const glm::vec3 d = random_unit_vector(rng);
    const glm::vec3 back = equirectangular_direction(equirectangular_uv(d));
    CHECK(glm::length(back - d) < 1e-5f);
    const glm::dvec3 expected = direction_at(equirectangular_uv(d).x, equirectangular_uv(d).y);
    CHECK(glm::length(glm::dvec3(back) - expected) < 1e-5);
  }
}

TEST_CASE("The map is looked up as Blender 3.4 does at the poles, the seam and the horizon", "[render]") {
  // What a 1-pixel Cycles render of the probe map gave looking along each direction: straight up
  // and down blend the top and bottom rows (the lookup wraps in v), -X blends the first and last
  // columns (it wraps in u), and 0.5 degrees off straight down blends 0.4118 of the top row.
  const EnvironmentLight light(EnvironmentMap{probe_map(), 1.0, 0.0});
  check_color(light.radiance({0, 0, 1}), {0.5f, 0.0f, 0.5f}, 1e-4f);
  check_color(light.radiance({0, 0, -1}), {0.5f, 0.0f, 0.5f}, 1e-4f);
  check_color(light.radiance({1, 0, 0}), {0.0f, 1.0f, 0.0f}, 1e-4f);
  check_color(light.radiance({-1, 0, 0}), {0.5f, 1.0f, 0.5f}, 1e-3f);
  const float tilt = glm::radians(0.5f);
  check_color(light.radiance({0, std::sin(tilt), -std::cos(tilt)}), {0.4118f, 0.0f, 0.5882f}, 1e-3f);
}

TEST_CASE("A Z rotation looks the map up along R_z(angle) d, as a Mapping node's rotation", "[render]") {
  // Columns numbered by their value: world -Y turned by +90 degrees looks at the map's +X column.
  const TexturePtr columns = map_of(64, 32, [](int x, int) { return glm::vec3(static_cast<float>(x)); });
  const EnvironmentLight turned(EnvironmentMap{columns, 2.0, matbase::kPi / 2});
  const EnvironmentLight plain(EnvironmentMap{columns, 2.0, 0.0});
  CHECK(turned.radiance({0, -1, 0}).x == Approx(plain.radiance({1, 0, 0}).x));
  CHECK(plain.radiance({1, 0, 0}).x == Approx(2.0 * 31.5));  // strength times the centre columns' mean
  UniformFloats rng(3);
  for (int i = 0; i < 100; ++i) {
    const glm::vec3 d = random_unit_vector(rng);
    CHECK(turned.radiance(d).x == Approx(plain.radiance(rotated_about_z(d, matbase::kPi / 2)).x).margin(1e-3));
    CHECK(turned.pdf(d) == Approx(plain.pdf(rotated_about_z(d, matbase::kPi / 2))).epsilon(1e-4));
  }
}

TexturePtr hazy_sky_map() {
  matrender::NishitaSky sky;
  sky.sun_elevation = 5.0 * matbase::kPi / 180.0;
  sky.dust_density = 6.0;
  return matrender::sky_lighting(sky, 256).map.image;
}

TEST_CASE("Environment sampling fits its pdf (chi-square), and the pdf covers every lit direction", "[render]") {
  struct Case {
    const char* name;
    TexturePtr image;
    double rotation;
  };
  // A sky gradient; a small sun over a black band (the density must follow the bilinear lookup's
  // spread into the band); the probe map turned by 30 degrees.
  const std::vector<Case> cases = {
      {"gradient", map_of_function(32, 16, [](const glm::dvec3& d) { return glm::vec3(1.0 + d.z + 0.3 * d.x); }), 0.0},
      {"sun over a black band",
       map_of(32, 16, [](int x, int y) { return y == 3 && x == 20 ? glm::vec3(5000.0f) : glm::vec3(y > 6 ? 0.2f : 0.0f); }),
       0.0},
      {"probe, turned", probe_map(), matbase::kPi / 6},
      // A real map with its sun in it: blender-data's sunrise, 1024 x 512, peaking at 33,664
      // against a mean of 0.47.
      {"sunrise", Texture::load_radiance(builtin_environment_path("sunrise"), ColorSpace::NonColor), 0.0},
      // A Nishita sky baked for a low sun in haze: its bright aureole on a black ground.
      {"hazy sky", hazy_sky_map(), 0.0},
  };
  constexpr int kBinsU = 64, kBinsV = 32, kSamples = 1000000;
  const double significance = 0.01 / static_cast<double>(cases.size());
  for (const Case& c : cases) {
    INFO(c.name);
    const EnvironmentLight light(EnvironmentMap{c.image, 1.0, c.rotation});
    std::vector<double> observed(kBinsU * kBinsV, 0.0), expected(kBinsU * kBinsV, 0.0);
    UniformFloats rng(0xe4f1);
    int failures = 0;
    for (int n = 0; n < kSamples; ++n) {
      const auto s = light.sample(glm::vec3(0.0f), {}, {rng.next(), rng.next()});
      if (!s) {
        ++failures;
        continue;
      }
      // The sample's own pdf is the density pdf() gives its direction.
      if (n % 1000 == 0) CHECK(s->pdf == Approx(light.pdf(s->wi)).epsilon(1e-3));
      const glm::vec2 uv = equirectangular_uv(rotated_about_z(s->wi, c.rotation));
      const int bu = std::min(kBinsU - 1, static_cast<int>(uv.x * kBinsU));
      const int bv = std::min(kBinsV - 1, static_cast<int>(uv.y * kBinsV));
      observed[static_cast<size_t>(bv) * kBinsU + bu] += 1.0;
    }
    CHECK(failures == 0);
    // Expected counts: N times the integral of pdf(w) dw = pdf(w(u, v)) 2 pi^2 sin(theta) du dv
    // over each bin, by a midpoint rule of at least 4 x 4 points and one per texel (the density is
    // constant on the map's texels, which the bins nest in).
    const int points = std::max(4, c.image->width() / kBinsU);
    double total = 0.0;
    for (int bv = 0; bv < kBinsV; ++bv)
      for (int bu = 0; bu < kBinsU; ++bu) {
        double integral = 0.0;
        for (int i = 0; i < points; ++i)
          for (int j = 0; j < points; ++j) {
            const double u = (bu + (i + 0.5) / points) / kBinsU, v = (bv + (j + 0.5) / points) / kBinsV;
            const glm::vec3 d = rotated_about_z(glm::vec3(direction_at(u, v)), -c.rotation);
            integral += light.pdf(d) * 2.0 * matbase::kPi * matbase::kPi * std::sin(matbase::kPi * (1.0 - v));
          }
        const double probability = integral / (points * points) / (kBinsU * kBinsV);
        expected[static_cast<size_t>(bv) * kBinsU + bu] = kSamples * probability;
        total += probability;
      }
    CHECK(total == Approx(1.0).epsilon(1e-4));
    const PearsonTest test = pearson_chi_square(observed, expected);
    INFO("chi^2 = " << test.statistic << ", dof = " << test.degrees_of_freedom << ", p = " << test.p_value);
    CHECK(test.p_value >= significance);
    // Wherever the lookup gives light, the density is positive, so MIS never misses it.
    for (int i = 0; i < 20000; ++i) {
      const glm::vec3 d = random_unit_vector(rng);
      if (glm::dot(light.radiance(d), glm::vec3(1.0f)) > 0.0f) CHECK(light.pdf(d) > 0.0f);
    }
  }
}

TEST_CASE("A black map is no light: nothing sampled, and the light set leaves it out", "[render]") {
  const TexturePtr black = map_of(8, 4, [](int, int) { return glm::vec3(0.0f); });
  const EnvironmentLight light(EnvironmentMap{black, 3.0, 0.0});
  CHECK(light.black());
  CHECK_FALSE(light.sample(glm::vec3(0.0f), {}, {0.3f, 0.7f}));
  CHECK(light.pdf({0, 0, 1}) == 0.0f);
  const LightSampler sampler({}, WorldLight(light));
  CHECK(sampler.empty());
  const PickSite site = sampler.site(glm::vec3(0.0f), {});
  CHECK(sampler.escaped_radiance({0, 0, 1}, ScatteredRay{1.0f, false, false, &site}) == glm::vec3(0.0f));
  // Strength 0 blackens any map.
  CHECK(EnvironmentLight(EnvironmentMap{probe_map(), 0.0, 0.0}).radiance({1, 0, 0}) == glm::vec3(0.0f));
}

TEST_CASE("An environment map that cannot be rendered is refused", "[render]") {
  CHECK_THROWS_AS(EnvironmentLight(EnvironmentMap{nullptr, 1.0, 0.0}), std::invalid_argument);
  CHECK_THROWS_AS(EnvironmentLight(EnvironmentMap{probe_map(), -1.0, 0.0}), std::invalid_argument);
  CHECK_THROWS_AS(EnvironmentLight(EnvironmentMap{probe_map(), 1e300, 0.0}), std::invalid_argument);
  CHECK_THROWS_AS(EnvironmentLight(EnvironmentMap{probe_map(), 1.0, NAN}), std::invalid_argument);
  const TexturePtr bright = map_of(4, 2, [](int, int) { return glm::vec3(1e30f); });
  CHECK_THROWS_WITH(EnvironmentLight(EnvironmentMap{bright, 1e10, 0.0}), Catch::Contains("lower the strength"));
  Scene scene;
  CHECK_THROWS_AS(scene.set_background(EnvironmentMap{probe_map(), -2.0, 0.0}), std::invalid_argument);
  CHECK_THROWS_AS(scene.set_background(glm::vec3(-1.0f)), std::invalid_argument);
}

namespace {

// Pixel statistics of a large Lambertian plane of albedo 0.5 through the point 0 with normal n,
// seen along n from close by through a narrow camera, under `background`.
test_scenes::PixelStatistics plane_under(const Background& background, const glm::dvec3& n, int channel) {
  matgeom::TriangleMesh plane = test_scenes::horizontal_square(100.0);
  const glm::dvec3 z(0, 0, 1);
  const glm::dvec3 axis = glm::cross(z, n);
  const double angle = std::acos(glm::clamp(glm::dot(z, n), -1.0, 1.0));
  const glm::dmat3 r = glm::length(axis) > 1e-9 ? glm::dmat3(glm::rotate(glm::dmat4(1.0), angle, glm::normalize(axis)))
                                                 : (angle > 1.0 ? glm::dmat3(1, 0, 0, 0, -1, 0, 0, 0, -1) : glm::dmat3(1.0));
  for (glm::vec3& p : plane.positions) p = glm::vec3(r * glm::dvec3(p));
  Scene scene;
  scene.add_mesh(plane, {scene.add_material(test_scenes::lambert(0.5f))});
  scene.set_background(background);
  const glm::dvec3 up = std::abs(n.z) > 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1);
  const Camera camera = Camera::look_at(n, glm::dvec3(0.0), up, 0.002, 16, 16);
  RenderSettings settings;
  settings.samples_per_pixel = 64;
  settings.seed = 5;
  FrameBuffers frame;
  REQUIRE(render(scene, camera, settings, frame).discarded_samples == 0);
  return test_scenes::channel_statistics(frame, channel);
}

}  // namespace

TEST_CASE("Furnace: a Lambertian plane under a constant map shows its albedo", "[render]") {
  const TexturePtr white = map_of(16, 8, [](int, int) { return glm::vec3(1.0f, 0.5f, 2.0f); });
  for (const glm::dvec3& n : {glm::dvec3(0, 0, 1), glm::dvec3(1, 0, 0), glm::dvec3(0, 0, -1)})
    for (int c = 0; c < 3; ++c) {
      const auto s = plane_under(EnvironmentMap{white, 1.0, 0.0}, n, c);
      const double expected = 0.5 * glm::vec3(1.0f, 0.5f, 2.0f)[c];
      INFO("normal " << n.x << "," << n.y << "," << n.z << " channel " << c << ": " << s.mean << " +- "
                     << s.standard_error);
      CHECK(std::abs(s.mean - expected) < 4.0 * s.standard_error + 1e-5);
    }
}

TEST_CASE("A Lambertian plane under a linear map converges to a (c0 + 2/3 c.n), turned maps too", "[render]") {
  // The cosine-weighted integral over the hemisphere of n of c0 + c.w is pi c0 + 2 pi / 3 c.n.
  const double c0 = 1.0;
  const glm::dvec3 c(0.3, -0.2, 0.5);
  const TexturePtr linear = map_of_function(512, 256, [&](const glm::dvec3& d) { return glm::vec3(c0 + glm::dot(c, d)); });
  for (double rotation : {0.0, matbase::kPi / 2}) {
    // Looked up along R d, the world sees c0 + (R^T c).d.
    const glm::dvec3 world_c = glm::transpose(glm::dmat3(glm::rotate(glm::dmat4(1.0), rotation, glm::dvec3(0, 0, 1)))) * c;
    for (const glm::dvec3& n : {glm::dvec3(0, 0, 1), glm::dvec3(0, 0, -1), glm::dvec3(1, 0, 0),
                                glm::normalize(glm::dvec3(-1, 2, 0.5))}) {
      const auto s = plane_under(EnvironmentMap{linear, 1.0, rotation}, n, 0);
      const double expected = 0.5 * (c0 + 2.0 / 3.0 * glm::dot(world_c, n));
      INFO("rotation " << rotation << " normal " << n.x << "," << n.y << "," << n.z << ": " << s.mean << " +- "
                       << s.standard_error << ", closed form " << expected);
      // The bilinear lookup of a smooth map at 512 x 256 is within 1e-4 of it.
      CHECK(std::abs(s.mean - expected) < 4.0 * s.standard_error + 2e-4);
    }
  }
}

TEST_CASE("A map black but for one very bright texel, at the pole or the horizon, gives finite pixels", "[render]") {
  // The texel at row 0 sits where sin(theta) nearly vanishes, so its sampling density is tiny
  // and its weight huge; the one on the horizon is the common sun. Glossy, mirror and glass
  // surfaces see it through every kind of bounce.
  for (const int row : {0, 16}) {
    const TexturePtr map = map_of(64, 32, [row](int x, int y) {
      return x == 20 && y == row ? glm::vec3(1e6f, 5e5f, 2e5f) : glm::vec3(0.0f);
    });
    Scene scene;
    Material glossy, glass, mirror;
    glossy.set(MaterialParameter::Roughness, 0.2f);
    glass.set(MaterialParameter::Transmission, 1.0f).set(MaterialParameter::Roughness, 0.0f);
    mirror.set(MaterialParameter::Metallic, 1.0f).set(MaterialParameter::Roughness, 0.0f);
    scene.add_mesh(test_scenes::uv_sphere(0.4, 16, {-0.5, 0.0, 0.5}), {scene.add_material(glossy)});
    scene.add_mesh(test_scenes::uv_sphere(0.4, 16, {0.5, 0.0, 0.5}), {scene.add_material(glass)});
    scene.add_mesh(test_scenes::horizontal_square(4.0), {scene.add_material(mirror)});
    scene.set_background(EnvironmentMap{map, 1.0, 0.3});
    RenderSettings settings;
    settings.samples_per_pixel = 8;
    CAPTURE(row);
    CHECK(test_scenes::renders_finite(
        scene, Camera::look_at({0.0, -3.0, 1.0}, {0.0, 0.0, 0.4}, {0, 0, 1}, 0.8, 24, 24), settings));
  }
}

TEST_CASE("Negative texels are clamped where compression rings and refused where nothing explains them", "[render]") {
  // A 4 x 2 map of 0.5 everywhere (bottom row first, as stored), one component changed.
  const auto level_with = [](int x, int y, int c, float value) {
    TexelLevel level;
    level.width = 4;
    level.height = 2;
    level.floats.assign(8, glm::vec4(0.5f, 0.5f, 0.5f, 1.0f));
    level.floats[static_cast<size_t>(y) * 4 + x][c] = value;
    return level;
  };
  SECTION("ringing: no deeper than an eighth of the brightest neighbour") {
    TexelLevel level = level_with(1, 0, 2, -0.0625f);
    clamp_compression_negatives(level, "map.exr");
    CHECK(level.floats[1] == glm::vec4(0.5f, 0.5f, 0.0f, 1.0f));
  }
  SECTION("deeper is a damaged file, named at its texel (rows counted from the top)") {
    TexelLevel level = level_with(3, 0, 0, -5.0f);
    CHECK_THROWS_WITH(clamp_compression_negatives(level, "map.exr"),
                      Catch::StartsWith("map.exr: texel (3, 1) has R -5, a negative radiance no compression explains"));
    TexelLevel just_deeper = level_with(0, 1, 1, -0.07f);
    CHECK_THROWS_WITH(clamp_compression_negatives(just_deeper, "map.exr"), Catch::Contains("texel (0, 0) has G -0.07"));
  }
  SECTION("a file goes through the rule, and a map that passes renders its clamped texel") {
    const std::string path = (std::filesystem::temp_directory_path() / "matrender_negative_radiance.exr").string();
    std::vector<float> pixels(4 * 2 * 3, 0.5f);
    pixels[3 * 5 + 1] = -0.001f;  // column 1 of the bottom row (rows top first in the file)
    matbase::write_exr(path, 4, 2, {"R", "G", "B"}, pixels.data());
    const TexturePtr map = Texture::load_radiance(path, ColorSpace::NonColor);
    CHECK(map->sample({(1 + 0.5f) / 4, 0.25f}).y == 0.0f);
    pixels[3 * 5 + 1] = -5.0f;
    matbase::write_exr(path, 4, 2, {"R", "G", "B"}, pixels.data());
    CHECK_THROWS_WITH(Texture::load_radiance(path, ColorSpace::NonColor), Catch::Contains("texel (1, 1) has G -5"));
    std::filesystem::remove(path);
  }
}

TEST_CASE("The eight built-in environments are Debian blender-data's HDR images, by name", "[render]") {
  const std::vector<std::string>& names = builtin_environment_names();
  REQUIRE(names.size() == 8);
  CHECK(is_builtin_environment("forest"));
  CHECK_FALSE(is_builtin_environment("forest.exr"));
  CHECK_FALSE(is_builtin_environment("Forest"));
  // scripts/install_deps.sh installs blender-data: every image is there and reads as a map.
  for (const std::string& name : names) {
    INFO(name);
    const std::string path = builtin_environment_path(name);
    const TexturePtr map = Texture::load_radiance(path, ColorSpace::NonColor);
    REQUIRE(map);
    CHECK(map->width() == 1024);
    CHECK(map->height() == 512);
  }
  // Absent, the refusal names the folder searched and the package that fills it.
  const std::filesystem::path empty = std::filesystem::temp_directory_path() / "matpredict_no_environments";
  std::filesystem::create_directories(empty);
  try {
    builtin_environment_path("sunset", empty.string());
    FAIL("no refusal");
  } catch (const matbase::InputError& e) {
    CHECK(std::string(e.what()) == "the built-in environment \"sunset\" is not in " + empty.string() +
                                       " (Debian's blender-data package puts it there: apt-get install blender-data, "
                                       "or bash scripts/install_deps.sh)");
  }
}

TEST_CASE("A scene file's environment may be a built-in one's name", "[render]") {
  auto background = [](const std::string& environment) {
    return read_scene_text(R"({"camera": {"position": [1, -1, 0.5], "look_at": [0, 0, 0]}, "lights": [],
                              "objects": [{"builtin": "vase"}], "background": {"environment": )" +
                               environment + "}}",
                           "s.json", ".")
        .background;
  };
  const BackgroundDescription read = background("\"sunrise\"");
  const auto* sunrise = std::get_if<EnvironmentDescription>(&read);
  REQUIRE(sunrise);
  CHECK(sunrise->path == builtin_environment_path("sunrise"));
  CHECK_THROWS_WITH(background("\"sunrise.hdr\""), Catch::Contains("/background/environment: file not found"));
}
