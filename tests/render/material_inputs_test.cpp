// Every parameter of the table is shaded from its texture when it has one: none is silently
// taken as its constant, and a material is constant only when no parameter is textured.
#include <catch2/catch.hpp>

#include <array>

#include "matbase/image/srgb.h"
#include "matrender/asset.h"
#include "matrender/scene.h"
#include "scene/scene_data.h"
#include "scene/surface_shading.h"
#include "test_scenes.h"

using namespace matrender;

namespace {

// A 1x1 texture: every lookup gives exactly this texel.
TexturePtr constant_texture(const glm::vec4& texel) {
  const std::array<float, 4> rgba = {texel.r, texel.g, texel.b, texel.a};
  return Texture::from_pixelsf(1, 1, 4, rgba.data(), ColorSpace::NonColor);
}

// What shade_surface gives a point of the first triangle of the scene's first mesh, seen along -wo.
SurfacePoint shaded_point(Scene& scene, const glm::vec3& wo) {
  scene.commit();
  RayHit hit;
  hit.t = 1.0f;
  hit.mesh = 0;
  hit.triangle = 0;
  hit.u = hit.v = 0.25f;
  return shade_surface(scene.data(), hit, wo);
}

// The same for a square (normal +Z) in `material`.
SurfacePoint shaded_point(const Material& material, const glm::vec3& wo = glm::vec3(0.0f, 0.0f, 1.0f)) {
  Scene scene;
  scene.add_mesh(test_scenes::horizontal_square(1.0), {scene.add_material(material)});
  return shaded_point(scene, wo);
}

PrincipledInputs shaded_inputs(const Material& material) { return shaded_point(material).inputs; }

}  // namespace

TEST_CASE("Each texturable parameter is read from its texture and makes the material textured", "[render]") {
  const glm::vec4 texel(0.25f, 0.5f, 0.75f, 0.125f);
  for (const matmaterial::MaterialParameterInfo& info : matmaterial::kMaterialParameters) {
    if (!info.texturable) continue;
    CAPTURE(info.name);
    Material material;
    CHECK(constant_inputs(material));
    const glm::vec3 factor = info.kind == matmaterial::ParameterKind::Color ? glm::vec3(0.5f, 1.0f, 0.8f) : glm::vec3(0.8f);
    material[info.id].value = factor;
    material[info.id].texture = constant_texture(texel);
    material[info.id].channel = 3;
    CHECK(material.textured());
    CHECK_FALSE(constant_inputs(material));

    const PrincipledInputs inputs = shaded_inputs(material);
    if (info.kind == matmaterial::ParameterKind::Color) {
      CHECK(inputs.color(info.id) == factor * glm::vec3(texel));
    } else {
      CHECK(inputs.scalar(info.id) == 0.8f * texel.a);
    }
    // Every other parameter keeps its constant.
    for (const matmaterial::MaterialParameterInfo& other : matmaterial::kMaterialParameters)
      if (other.id != info.id) CHECK(inputs.color(other.id) == Material().color(other.id));
  }
}

TEST_CASE("An asset's image on any texturable parameter reaches the shading, in the table's colour space", "[render]") {
  const std::array<uint8_t, 4> texel = {64, 128, 192, 32};
  for (const matmaterial::MaterialParameterInfo& info : matmaterial::kMaterialParameters) {
    if (!info.texturable) continue;
    CAPTURE(info.name);
    matgeom::ObjectAsset asset;
    asset.mesh = test_scenes::horizontal_square(1.0);
    asset.images.push_back({"texel", 1, 1, 4, {texel.begin(), texel.end()}});
    matmaterial::MaterialInputs desc;
    desc.set(info.id, 0.5).set_image(info.id, 0, 3);
    asset.materials = {desc};
    Scene scene;
    add_asset(scene, asset);
    const PrincipledInputs inputs = shaded_point(scene, glm::vec3(0.0f, 0.0f, 1.0f)).inputs;
    if (info.kind == matmaterial::ParameterKind::Color) {
      // An sRGB image with alpha comes premultiplied by it (Blender's Straight alpha mode, the
      // material's alpha taken from elsewhere); a data image as stored.
      const float alpha = texel[3] / 255.0f;
      for (int c = 0; c < 3; ++c) {
        const float encoded = texel[static_cast<size_t>(c)] / 255.0f;
        const float expected =
            info.texture_space == ColorSpace::SRGB ? matbase::srgb_to_linear(encoded * alpha) : encoded;
        CHECK(inputs.color(info.id)[c] == Approx(0.5f * expected).epsilon(1e-5));
      }
    } else {
      CHECK(inputs.scalar(info.id) == Approx(0.5f * texel[3] / 255.0f).epsilon(1e-5));
    }
    for (const matmaterial::MaterialParameterInfo& other : matmaterial::kMaterialParameters)
      if (other.id != info.id) CHECK(inputs.color(other.id) == Material().color(other.id));
  }
}

TEST_CASE("Parameters sharing one packed image read their own channels of it", "[render]") {
  Material material;
  const TexturePtr packed = constant_texture({0.1f, 0.6f, 0.9f, 1.0f});
  material[MaterialParameter::Roughness].texture = packed;
  material[MaterialParameter::Metallic].texture = packed;
  material.set(MaterialParameter::Roughness, 1.0f).set(MaterialParameter::Metallic, 0.5f);
  const PrincipledInputs inputs = shaded_inputs(material);
  // A new Material's channels are the glTF packing: roughness G, metallic B.
  CHECK(inputs.scalar(MaterialParameter::Roughness) == 0.6f);
  CHECK(inputs.scalar(MaterialParameter::Metallic) == 0.5f * 0.9f);
}

TEST_CASE("A new material has Blender's defaults from the table", "[render]") {
  const Material material;
  for (const matmaterial::MaterialParameterInfo& info : matmaterial::kMaterialParameters) {
    CAPTURE(info.name);
    CHECK(material.color(info.id) == glm::vec3(static_cast<float>(info.default_value)));
    CHECK_FALSE(material[info.id].texture);
  }
  CHECK_FALSE(material.textured());
}

TEST_CASE("A surface point knows which side of the triangle the ray met", "[render]") {
  // Glass is entered through the front face (the winding's, as Blender) and left through the back.
  const Material glass;
  const SurfacePoint front = shaded_point(glass, glm::vec3(0.0f, 0.0f, 1.0f));
  CHECK(front.front_face);
  CHECK(front.geometric_normal == glm::vec3(0.0f, 0.0f, 1.0f));
  const SurfacePoint back = shaded_point(glass, glm::vec3(0.0f, 0.0f, -1.0f));
  CHECK_FALSE(back.front_face);
  CHECK(back.geometric_normal == glm::vec3(0.0f, 0.0f, -1.0f));
}

TEST_CASE("An asset's texture transform moves its image on the UVs, per input, packed or not", "[render]") {
  // A 4 x 1 ramp of data values; roughness reads it placed by a transform, metallic reads the
  // same image as it lies.
  const std::array<uint8_t, 4> ramp = {0, 85, 170, 255};
  matgeom::ObjectAsset asset;
  asset.mesh = test_scenes::horizontal_square(1.0);
  asset.images.push_back({"ramp", 4, 1, 1, {ramp.begin(), ramp.end()}});
  matmaterial::MaterialInputs desc;
  const matmaterial::TextureTransform shifted{{0.25, 0.0}, 0.0, {1.0, 1.0}};
  desc.set(MaterialParameter::Roughness, 1.0).set_image(MaterialParameter::Roughness, 0, 0, shifted);
  desc.set(MaterialParameter::Metallic, 1.0).set_image(MaterialParameter::Metallic, 0, 0);
  asset.materials = {desc};
  Scene scene;
  add_asset(scene, asset);
  const PrincipledInputs inputs = shaded_point(scene, glm::vec3(0.0f, 0.0f, 1.0f)).inputs;
  // The shaded point has uv (0.5, 0.25): metallic reads between texels 1 and 2, roughness a
  // quarter further, between texels 2 and 3.
  CHECK(inputs.scalar(MaterialParameter::Metallic) == Approx((85.0f + 170.0f) / 2.0f / 255.0f).epsilon(1e-5));
  CHECK(inputs.scalar(MaterialParameter::Roughness) == Approx((170.0f + 255.0f) / 2.0f / 255.0f).epsilon(1e-5));
}
