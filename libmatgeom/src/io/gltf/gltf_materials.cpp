#include "io/gltf/gltf_materials.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <set>
#include <utility>

#include <glm/glm.hpp>

#include "io/gltf/extensions.h"
#include "matbase/file/file_error.h"
#include "matbase/image/unorm.h"
#include "matgeom/object_asset.h"
#include "matmaterial/material_parameters.h"

// Each material is converted once, when a primitive first uses it; the images it references are
// converted once each, and a specular-glossiness material's roughness map is baked from its
// glossiness. The functions below take the conversion's state (GltfMaterials::Conversion).

namespace matgeom::gltf {
namespace {

using Conversion = GltfMaterials::Conversion;


matbase::ImagePixels convert_image(const GltfFile& file, size_t index) {
  const tinygltf::Image& image = file.model.images[index];
  const std::string name = matbase::concat("image ", index);
  if (image.image.empty() || image.width <= 0 || image.height <= 0) {
    matbase::fail(file.path, name + ": no decoded pixels");
  }
  if (image.component < 1 || image.component > 4 || (image.bits != 8 && image.bits != 16)) {
    matbase::fail(file.path, matbase::concat(name, ": unsupported format (", image.component, " channels of ",
                           image.bits, " bits)"));
  }
  const size_t expected = static_cast<size_t>(image.width) * static_cast<size_t>(image.height) *
                          static_cast<size_t>(image.component) *
                          static_cast<size_t>(image.bits / 8);
  if (image.image.size() != expected) matbase::fail(file.path, name + ": pixel data has the wrong size");

  matbase::ImagePixels pixels;
  const bool embedded = image.uri.empty() || image.uri.rfind("data:", 0) == 0;
  pixels.name = embedded
                    ? matbase::concat(std::filesystem::path(file.path).filename().string(), "#image", index)
                    : image.uri;
  pixels.width = image.width;
  pixels.height = image.height;
  pixels.channels = image.component;
  pixels.data = matbase::unorm_channels_to_8_bit(image.image, image.bits);
  return pixels;
}

// glTF images referenced by materials, converted once each, in order of first reference.
class ImageTable {
 public:
  explicit ImageTable(const GltfFile& file) : file_(file) {}

  int asset_index(size_t gltf_image) {
    const auto it = asset_indices_.find(gltf_image);
    if (it != asset_indices_.end()) return it->second;
    const int index = static_cast<int>(images_.size());
    images_.push_back(convert_image(file_, gltf_image));
    asset_indices_.emplace(gltf_image, index);
    return index;
  }

  // An image made here (a baked map), appended; its asset index.
  int add_image(matbase::ImagePixels pixels) {
    images_.push_back(std::move(pixels));
    return static_cast<int>(images_.size()) - 1;
  }

  const matbase::ImagePixels& pixels(int asset_index) const { return images_[static_cast<size_t>(asset_index)]; }

  std::vector<matbase::ImagePixels> take_images() { return std::move(images_); }

 private:
  const GltfFile& file_;
  std::map<size_t, int> asset_indices_;
  std::vector<matbase::ImagePixels> images_;
};

}  // namespace

// The state of one file's conversion: its images, its notes, and the UV set of the material
// being converted.
struct GltfMaterials::Conversion {
  explicit Conversion(const GltfFile& file) : images(file) {}

  ImageTable images;
  std::vector<std::string> notes;
  std::optional<int> uv_set;
  std::string uv_set_texture;  // the first texture that named it, for messages

  void note(const std::string& sentence) {
    add_note(notes, sentence);
  }

  void use_uv_set(const GltfFile& file, int set, const std::string& texture) {
    if (!uv_set) {
      uv_set = set;
      uv_set_texture = texture;
    } else if (*uv_set != set) {
      matbase::fail(file.path, matbase::concat(texture, " samples TEXCOORD_", set, ", but ", uv_set_texture, " samples TEXCOORD_",
                                               *uv_set, ": a material's textures are read on one UV set"));
    }
  }
};

namespace {

struct TextureRef {
  int image = -1;  // index into the asset's images
  matmaterial::TextureWrap wrap = matmaterial::TextureWrap::Repeat;
  matmaterial::TextureTransform transform;  // KHR_texture_transform's
};

// MaterialInputs has one wrap mode. Blender 3.4's Image Texture offers REPEAT and EXTEND per image
// (its importer emulates mirrored and mixed modes with extra nodes); here a texture clamps only
// when both axes say CLAMP_TO_EDGE, and MIRRORED_REPEAT is approximated by REPEAT.
matmaterial::TextureWrap sampler_wrap(const GltfFile& file, Conversion& conversion, int sampler_index, const std::string& what) {
  if (sampler_index < 0) return matmaterial::TextureWrap::Repeat;
  if (static_cast<size_t>(sampler_index) >= file.model.samplers.size()) {
    matbase::fail(file.path, matbase::concat(what, ": sampler ", sampler_index, " does not exist"));
  }
  const tinygltf::Sampler& sampler = file.model.samplers[static_cast<size_t>(sampler_index)];
  const bool clamp = sampler.wrapS == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE &&
                     sampler.wrapT == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
  const bool mirrored = sampler.wrapS == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT || sampler.wrapT == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT;
  if (mirrored) conversion.note("MIRRORED_REPEAT wrapping is read as REPEAT (textures repeat without mirroring)");
  else if (!clamp && sampler.wrapS != sampler.wrapT)
    conversion.note("a sampler that clamps one axis and repeats the other is read as REPEAT on both");
  return clamp ? matmaterial::TextureWrap::Clamp : matmaterial::TextureWrap::Repeat;
}

// Two numbers of a KHR_texture_transform member, `fallback` when absent.
glm::dvec2 transform_pair(const GltfFile& file, const tinygltf::Value& transform, const char* member,
                          glm::dvec2 fallback, const std::string& what) {
  if (!transform.Has(member)) return fallback;
  const tinygltf::Value& value = transform.Get(member);
  if (!value.IsArray() || value.ArrayLen() != 2 || !value.Get(0).IsNumber() || !value.Get(1).IsNumber())
    matbase::fail(file.path, matbase::concat(what, ": ", kTextureTransform, " ", member, " needs 2 numbers"));
  const glm::dvec2 pair(value.Get(0).GetNumberAsDouble(), value.Get(1).GetNumberAsDouble());
  if (!std::isfinite(pair.x) || !std::isfinite(pair.y))
    matbase::fail(file.path, matbase::concat(what, ": ", kTextureTransform, " ", member, " is not finite"));
  return pair;
}

// A textureInfo's KHR_texture_transform, whose texCoord (when given) replaces the textureInfo's.
matmaterial::TextureTransform read_texture_transform(const GltfFile& file, const tinygltf::Value& transform, int& tex_coord,
                                        const std::string& what) {
  if (!transform.IsObject()) matbase::fail(file.path, matbase::concat(what, ": ", kTextureTransform, " is not an object"));
  matmaterial::TextureTransform t;
  t.offset = transform_pair(file, transform, "offset", t.offset, what);
  t.scale = transform_pair(file, transform, "scale", t.scale, what);
  if (transform.Has("rotation")) {
    const tinygltf::Value& rotation = transform.Get("rotation");
    if (!rotation.IsNumber() || !std::isfinite(rotation.GetNumberAsDouble()))
      matbase::fail(file.path, matbase::concat(what, ": ", kTextureTransform, " rotation is not a finite number"));
    t.rotation = rotation.GetNumberAsDouble();
  }
  if (transform.Has("texCoord")) {
    if (!transform.Get("texCoord").IsInt())
      matbase::fail(file.path, matbase::concat(what, ": ", kTextureTransform, " texCoord is not an integer"));
    tex_coord = transform.Get("texCoord").GetNumberAsInt();
  }
  return t;
}

// `extensions`: the textureInfo's, where a KHR_texture_transform may be.
TextureRef resolve_texture(const GltfFile& file, Conversion& conversion, int texture_index, int tex_coord,
                           const tinygltf::ExtensionMap& extensions, const std::string& what) {
  TextureRef ref;
  if (texture_index < 0) return ref;
  const auto transform = extensions.find(kTextureTransform);
  if (transform != extensions.end()) ref.transform = read_texture_transform(file, transform->second, tex_coord, what);
  if (static_cast<size_t>(texture_index) >= file.model.textures.size()) {
    matbase::fail(file.path, matbase::concat(what, ": texture ", texture_index, " does not exist"));
  }
  if (tex_coord < 0) matbase::fail(file.path, matbase::concat(what, ": texCoord ", tex_coord, " is negative"));
  conversion.use_uv_set(file, tex_coord, what);
  const tinygltf::Texture& texture = file.model.textures[static_cast<size_t>(texture_index)];
  if (texture.source < 0 || static_cast<size_t>(texture.source) >= file.model.images.size()) {
    matbase::fail(file.path,
         matbase::concat(what, ": texture ", texture_index, " has no image in a core format (PNG or JPEG)"));
  }
  ref.image = conversion.images.asset_index(static_cast<size_t>(texture.source));
  ref.wrap = sampler_wrap(file, conversion, texture.sampler, what);
  return ref;
}

// A factor must lie in its parameter's range (the parameter table's).
double checked_factor(const GltfFile& file, matmaterial::MaterialParameter p, double value, const std::string& what) {
  const matmaterial::MaterialParameterInfo& info = matmaterial::material_parameter(p);
  if (!(value >= info.min && value <= info.max))
    matbase::fail(file.path, matbase::concat(what, " ", value, " is outside [", info.min, ", ", info.max, "]"));
  return value;
}

// A number member of an extension object, if present.
std::optional<double> extension_number(const GltfFile& file, const tinygltf::Value& extension, const char* member,
                                       const std::string& what) {
  if (!extension.Has(member)) return std::nullopt;
  const tinygltf::Value& value = extension.Get(member);
  if (!value.IsNumber()) matbase::fail(file.path, matbase::concat(what, ": ", member, " is not a number"));
  return value.GetNumberAsDouble();
}

// A textureInfo member of an extension object: the texture, without an image when absent.
TextureRef extension_texture(const GltfFile& file, Conversion& conversion, const tinygltf::Value& extension,
                             const char* member, const std::string& what) {
  if (!extension.Has(member)) return {};
  const tinygltf::Value& info = extension.Get(member);
  const std::string where = matbase::concat(what, " ", member);
  if (!info.IsObject() || !info.Has("index") || !info.Get("index").IsInt())
    matbase::fail(file.path, where + ": expected a texture info with an integer index");
  int tex_coord = 0;
  if (info.Has("texCoord")) {
    if (!info.Get("texCoord").IsInt()) matbase::fail(file.path, where + ": texCoord is not an integer");
    tex_coord = info.Get("texCoord").GetNumberAsInt();
  }
  tinygltf::ExtensionMap extensions;
  if (info.Has("extensions")) {
    const tinygltf::Value& all = info.Get("extensions");
    if (!all.IsObject()) matbase::fail(file.path, where + ": extensions is not an object");
    for (const std::string& name : all.Keys()) extensions.emplace(name, all.Get(name));
  }
  return resolve_texture(file, conversion, info.Get("index").GetNumberAsInt(), tex_coord, extensions, where);
}

// One input an extension gives as factor x one channel of a texture (glTF's pattern), set on
// `p`; the factor is glTF's default 0 when absent.
void read_extension_input(const GltfFile& file, Conversion& conversion, const tinygltf::Value& extension,
                          const char* factor_member, const char* texture_member, int channel, matmaterial::MaterialParameter p,
                          matmaterial::MaterialInputs& desc, const std::string& where) {
  const double factor = extension_number(file, extension, factor_member, where).value_or(0.0);
  desc.set(p, checked_factor(file, p, factor, matbase::concat(where, " ", factor_member)));
  const TextureRef texture = extension_texture(file, conversion, extension, texture_member, where);
  if (texture.image >= 0) desc.set_image(p, texture.image, channel, texture.transform);
}

// KHR_materials_clearcoat as Blender 3.4's importer wires it: Clearcoat = clearcoatFactor x
// clearcoatTexture.R, Clearcoat Roughness = clearcoatRoughnessFactor x clearcoatRoughnessTexture.G,
// both factors 0 when absent (so a coat without a roughness is a mirror, not Blender's default
// 0.03). clearcoatNormalTexture has no MaterialInputs input: the coat keeps the surface's normal,
// and the file is told so.
void read_clearcoat(const GltfFile& file, Conversion& conversion, const tinygltf::Value& extension, matmaterial::MaterialInputs& desc,
                    const std::string& what) {
  const std::string where = matbase::concat(what, " ", kClearcoat);
  read_extension_input(file, conversion, extension, "clearcoatFactor", "clearcoatTexture", kClearcoatChannel,
                       matmaterial::MaterialParameter::Clearcoat, desc, where);
  read_extension_input(file, conversion, extension, "clearcoatRoughnessFactor", "clearcoatRoughnessTexture",
                       kClearcoatRoughnessChannel, matmaterial::MaterialParameter::ClearcoatRoughness, desc, where);
  if (extension.Has("clearcoatNormalTexture"))
    conversion.note(where + " clearcoatNormalTexture is not applied (the coat keeps the surface's normal)");
}

// KHR_materials_sheen as Blender 3.4's importer wires it (gltf2_blender_KHR_materials_sheen.py):
// a Velvet BSDF added to the Principled BSDF, Color = sheenColorFactor x sheenColorTexture.RGB,
// Sigma = sheenRoughnessFactor x sheenRoughnessTexture.A, both factors 0 when absent. Present
// with a black colour, the extension adds a velvet that reflects nothing.
void read_sheen(const GltfFile& file, Conversion& conversion, const tinygltf::Value& extension, matmaterial::MaterialInputs& desc,
                const std::string& what) {
  const std::string where = matbase::concat(what, " ", kSheen);
  glm::dvec3 colour(0.0);
  if (extension.Has("sheenColorFactor")) {
    const tinygltf::Value& factor = extension.Get("sheenColorFactor");
    if (!factor.IsArray() || factor.ArrayLen() != 3) matbase::fail(file.path, where + ": sheenColorFactor needs 3 numbers");
    for (int c = 0; c < 3; ++c) {
      const tinygltf::Value& component = factor.Get(c);
      if (!component.IsNumber()) matbase::fail(file.path, where + ": sheenColorFactor needs 3 numbers");
      colour[c] = checked_factor(file, matmaterial::MaterialParameter::VelvetColor, component.GetNumberAsDouble(),
                                 where + " sheenColorFactor");
    }
  }
  desc.set(matmaterial::MaterialParameter::VelvetColor, colour);
  const TextureRef colour_texture = extension_texture(file, conversion, extension, "sheenColorTexture", where);
  if (colour_texture.image >= 0)
    desc.set_image(matmaterial::MaterialParameter::VelvetColor, colour_texture.image, 0, colour_texture.transform);
  read_extension_input(file, conversion, extension, "sheenRoughnessFactor", "sheenRoughnessTexture",
                       kSheenRoughnessChannel, matmaterial::MaterialParameter::VelvetSigma, desc, where);
}

// KHR_materials_transmission as Blender 3.4's importer wires it: Transmission =
// transmissionFactor x transmissionTexture.R; a factor of 0 (the default) leaves the texture out.
void read_transmission(const GltfFile& file, Conversion& conversion, const tinygltf::Value& extension, matmaterial::MaterialInputs& desc,
                       const std::string& what) {
  const std::string where = matbase::concat(what, " ", kTransmission);
  read_extension_input(file, conversion, extension, "transmissionFactor", "transmissionTexture",
                       kTransmissionChannel, matmaterial::MaterialParameter::Transmission, desc, where);
  if (desc.scalar(matmaterial::MaterialParameter::Transmission) == 0.0) desc[matmaterial::MaterialParameter::Transmission].image = -1;
}

// KHR_materials_pbrSpecularGlossiness. Blender 3.4's importer builds it as the sum of a Diffuse
// BSDF (the diffuse colour) and a Glossy BSDF (the specular colour, without Fresnel), both at
// roughness 1 - glossiness; the Principled BSDF cannot express that sum, so the material becomes the
// metallic-roughness one nearest it, the conversion said in the file's notes: Base Color =
// diffuseFactor x diffuseTexture (its alpha the Alpha, for BLEND and MASK), Metallic 0, Roughness =
// 1 - glossinessFactor x specularGlossinessTexture.A (a map baked here), Specular = the mean of
// specularFactor / 0.08 up to 1 (Principled's dielectric F0 is 0.08 Specular). The specular
// colour's texture is not applied. Returns the diffuse texture, which stands for the base colour.
TextureRef read_specular_glossiness(const GltfFile& file, Conversion& conversion, const tinygltf::Value& extension,
                                    bool uses_alpha, matmaterial::MaterialInputs& desc, const std::string& what) {
  using P = matmaterial::MaterialParameter;
  const std::string where = matbase::concat(what, " ", kSpecularGlossiness);
  if (!extension.IsObject()) matbase::fail(file.path, where + " is not an object");
  const auto factors = [&](const char* member, size_t count, std::vector<double> fallback) {
    if (!extension.Has(member)) return fallback;
    const tinygltf::Value& value = extension.Get(member);
    if (!value.IsArray() || value.ArrayLen() != count)
      matbase::fail(file.path, matbase::concat(where, " ", member, " needs ", count, " numbers"));
    std::vector<double> numbers;
    for (size_t c = 0; c < count; ++c) {
      const tinygltf::Value& component = value.Get(static_cast<int>(c));
      if (!component.IsNumber()) matbase::fail(file.path, matbase::concat(where, " ", member, " needs ", count, " numbers"));
      numbers.push_back(checked_factor(file, P::BaseColor, component.GetNumberAsDouble(), where + " " + member));
    }
    return numbers;
  };
  const std::vector<double> diffuse = factors("diffuseFactor", 4, {1.0, 1.0, 1.0, 1.0});
  const std::vector<double> specular = factors("specularFactor", 3, {1.0, 1.0, 1.0});
  const double glossiness =
      checked_factor(file, P::Roughness, extension_number(file, extension, "glossinessFactor", where).value_or(1.0),
                     where + " glossinessFactor");
  desc.set(P::BaseColor, glm::dvec3(diffuse[0], diffuse[1], diffuse[2]));
  if (uses_alpha) desc.set(P::Alpha, diffuse[3]);
  desc.set(P::Metallic, 0.0);
  desc.set(P::Specular, std::min(1.0, (specular[0] + specular[1] + specular[2]) / 3.0 / 0.08));
  desc.set(P::Roughness, 1.0 - glossiness);
  const TextureRef gloss = extension_texture(file, conversion, extension, "specularGlossinessTexture", where);
  if (gloss.image >= 0) {
    // Roughness = 1 - glossinessFactor x A, one channel per texel.
    const matbase::ImagePixels& source = conversion.images.pixels(gloss.image);
    matbase::ImagePixels roughness = matbase::blank_image(source.name + "#roughness", source.width, source.height, 1);
    const size_t texels = static_cast<size_t>(source.width) * static_cast<size_t>(source.height);
    for (size_t i = 0; i < texels; ++i) {
      const int alpha = source.channels == 4 ? source.data[4 * i + 3] : source.channels == 2 ? source.data[2 * i + 1] : 255;
      roughness.data[i] = static_cast<uint8_t>(std::lround(255.0 - glossiness * alpha));
    }
    desc.set(P::Roughness, 1.0).set_image(P::Roughness, conversion.images.add_image(std::move(roughness)), 0, gloss.transform);
    conversion.note(where + ": specularGlossinessTexture's specular colour is not applied (its glossiness is)");
  }
  conversion.note(where + ": converted to the nearest metallic-roughness material (Blender 3.4 adds a Diffuse and a "
                          "Glossy BSDF, which the Principled BSDF cannot express): base colour = diffuse, roughness = "
                          "1 - glossiness, specular = the specular colour's mean / 0.08");
  const TextureRef diffuse_texture = extension_texture(file, conversion, extension, "diffuseTexture", where);
  return diffuse_texture;
}

// The Principled BSDF inputs Blender's importer sets (docs/conventions.md): base colour =
// factor x texture, roughness = factor x texture.G, metallic = factor x texture.B, normal map
// strength = normalTexture.scale, emission = emissiveFactor x emissiveTexture with
// KHR_materials_emissive_strength's strength, IOR = KHR_materials_ior's (1.5 without it),
// KHR_materials_clearcoat (read_clearcoat), KHR_materials_transmission (read_transmission),
// KHR_materials_sheen (read_sheen);
// alphaMode BLEND or MASK: Alpha = baseColorFactor[3] x baseColorTexture.A; specular and
// specular tint keep Blender's defaults. Occlusion has no MaterialInputs input.
matmaterial::MaterialInputs convert_material(const GltfFile& file, Conversion& conversion, size_t index) {
  const tinygltf::Material& material = file.model.materials[index];
  const tinygltf::PbrMetallicRoughness& pbr = material.pbrMetallicRoughness;
  const std::string what = matbase::concat("material ", index);

  using P = matmaterial::MaterialParameter;
  matmaterial::MaterialInputs desc(material.name.empty() ? matbase::concat("material", index) : material.name);
  if (pbr.baseColorFactor.size() != 4) matbase::fail(file.path, what + ": baseColorFactor needs 4 numbers");
  glm::dvec3 base_color;
  for (int c = 0; c < 3; ++c) {
    base_color[c] = checked_factor(file, P::BaseColor, pbr.baseColorFactor[static_cast<size_t>(c)],
                                   what + " baseColorFactor");
  }
  desc.set(P::BaseColor, base_color);
  // alphaMode BLEND and MASK link Alpha to baseColorFactor[3] x the base texture's A; Blender
  // 3.4's importer turns MASK's alphaCutoff into an EEVEE clip threshold that Cycles ignores,
  // so MASK renders with the same fractional alpha as BLEND. OPAQUE leaves Alpha at 1.
  const bool uses_alpha = material.alphaMode == "BLEND" || material.alphaMode == "MASK";
  if (!uses_alpha && material.alphaMode != "OPAQUE")
    matbase::fail(file.path, matbase::concat(what, ": alphaMode ", matbase::excerpt(material.alphaMode), " is not OPAQUE, MASK or BLEND"));
  if (uses_alpha)
    desc.set(P::Alpha, checked_factor(file, P::Alpha, pbr.baseColorFactor[3], what + " baseColorFactor alpha"));
  desc.set(P::Metallic, checked_factor(file, P::Metallic, pbr.metallicFactor, what + " metallicFactor"));
  desc.set(P::Roughness, checked_factor(file, P::Roughness, pbr.roughnessFactor, what + " roughnessFactor"));
  if (material.emissiveFactor.size() != 3) matbase::fail(file.path, what + ": emissiveFactor needs 3 numbers");
  glm::dvec3 emission;
  for (int c = 0; c < 3; ++c)
    emission[c] = checked_factor(file, P::Emission, material.emissiveFactor[static_cast<size_t>(c)],
                                 what + " emissiveFactor");
  desc.set(P::Emission, emission);
  const auto strength = material.extensions.find(kEmissiveStrength);
  if (strength != material.extensions.end() && strength->second.Has("emissiveStrength")) {
    const tinygltf::Value& value = strength->second.Get("emissiveStrength");
    if (!value.IsNumber()) matbase::fail(file.path, what + ": emissiveStrength is not a number");
    desc.set(P::EmissionStrength, checked_factor(file, P::EmissionStrength, value.GetNumberAsDouble(),
                                                 what + " emissiveStrength"));
  }
  desc.set(P::Ior, kDefaultIor);
  const auto ior = material.extensions.find(kIor);
  if (ior != material.extensions.end())
    desc.set(P::Ior, checked_factor(file, P::Ior, extension_number(file, ior->second, "ior", what).value_or(kDefaultIor),
                                    matbase::concat(what, " ", kIor, " ior")));
  const auto clearcoat = material.extensions.find(kClearcoat);
  if (clearcoat != material.extensions.end()) read_clearcoat(file, conversion, clearcoat->second, desc, what);
  const auto transmission = material.extensions.find(kTransmission);
  if (transmission != material.extensions.end()) read_transmission(file, conversion, transmission->second, desc, what);
  const auto sheen = material.extensions.find(kSheen);
  if (sheen != material.extensions.end()) read_sheen(file, conversion, sheen->second, desc, what);
  if (!std::isfinite(material.normalTexture.scale))
    matbase::fail(file.path, what + ": non-finite normal scale");
  desc.normal_strength = material.normalTexture.scale;

  // A specular-glossiness material is built from its extension alone, as Blender's importer does.
  const auto specular_glossiness = material.extensions.find(kSpecularGlossiness);
  const bool from_specular_glossiness = specular_glossiness != material.extensions.end();
  TextureRef base, metallic_roughness;
  if (from_specular_glossiness) {
    base = read_specular_glossiness(file, conversion, specular_glossiness->second, uses_alpha, desc, what);
  } else {
    base = resolve_texture(file, conversion, pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord,
                           pbr.baseColorTexture.extensions, what + " baseColorTexture");
    metallic_roughness = resolve_texture(file, conversion, pbr.metallicRoughnessTexture.index,
                                         pbr.metallicRoughnessTexture.texCoord, pbr.metallicRoughnessTexture.extensions,
                                         what + " metallicRoughnessTexture");
  }
  const TextureRef normal = resolve_texture(file, conversion, material.normalTexture.index, material.normalTexture.texCoord,
                                           material.normalTexture.extensions, what + " normalTexture");
  const TextureRef emissive =
      resolve_texture(file, conversion, material.emissiveTexture.index, material.emissiveTexture.texCoord,
                      material.emissiveTexture.extensions, what + " emissiveTexture");
  if (base.image >= 0) desc.set_image(P::BaseColor, base.image, 0, base.transform);
  if (base.image >= 0 && uses_alpha) desc.set_image(P::Alpha, base.image, kBaseColorAlphaChannel, base.transform);
  if (emissive.image >= 0) desc.set_image(P::Emission, emissive.image, 0, emissive.transform);
  if (metallic_roughness.image >= 0)
    desc.set_metallic_roughness_image(metallic_roughness.image, metallic_roughness.transform);
  desc.normal_image = normal.image;
  desc.normal_transform = normal.transform;
  // The wrap mode follows the most visible texture: base colour, else roughness, else normal.
  for (const TextureRef& ref : {base, metallic_roughness, normal}) {
    if (ref.image < 0) continue;
    desc.wrap = ref.wrap;
    break;
  }
  return desc;
}

}  // namespace

GltfMaterials::GltfMaterials(const GltfFile& file) : file_(file), conversion_(std::make_unique<Conversion>(file)) {}

GltfMaterials::~GltfMaterials() = default;

const ConvertedMaterial& GltfMaterials::material(size_t index) {
  const auto found = converted_.find(index);
  if (found != converted_.end()) return found->second;
  conversion_->uv_set.reset();
  ConvertedMaterial converted{convert_material(file_, *conversion_, index), conversion_->uv_set};
  return converted_.emplace(index, std::move(converted)).first->second;
}

std::vector<matbase::ImagePixels> GltfMaterials::take_images() { return conversion_->images.take_images(); }

std::vector<std::string> GltfMaterials::take_notes() { return std::move(conversion_->notes); }

}  // namespace matgeom::gltf
