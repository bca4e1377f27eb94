#include "matgeom/io/gltf/gltf_writer.h"


#include <algorithm>
#include <cstring>
#include <filesystem>
#include <initializer_list>
#include <limits>
#include <map>
#include <stdexcept>
#include <tuple>
#include <utility>

#include <tiny_gltf.h>

#include "io/gltf/extensions.h"
#include "io/gltf/metallic_roughness_image.h"
#include "matbase/file/atomic_file.h"
#include "matgeom/mesh_parts.h"

namespace matgeom {
namespace {

constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;

glm::vec3 blender_to_gltf(const glm::vec3& v) { return {v.x, v.z, -v.y}; }

// Appends raw values to the single buffer as a new buffer view; returns the view's index.
template <class T>
int add_buffer_view(tinygltf::Model& model, const std::vector<T>& values, int target) {
  std::vector<unsigned char>& bytes = model.buffers[0].data;
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = bytes.size();
  view.byteLength = values.size() * sizeof(T);
  view.target = target;
  bytes.resize(bytes.size() + view.byteLength);
  std::memcpy(bytes.data() + view.byteOffset, values.data(), view.byteLength);
  model.bufferViews.push_back(view);
  return static_cast<int>(model.bufferViews.size()) - 1;
}

int add_accessor(tinygltf::Model& model, int view, int component_type, int type, size_t count) {
  tinygltf::Accessor accessor;
  accessor.bufferView = view;
  accessor.componentType = component_type;
  accessor.type = type;
  accessor.count = count;
  model.accessors.push_back(accessor);
  return static_cast<int>(model.accessors.size()) - 1;
}

template <class T>
int add_float_attribute(tinygltf::Model& model, const std::vector<T>& values, int type) {
  return add_accessor(model, add_buffer_view(model, values, kArrayBuffer), TINYGLTF_COMPONENT_TYPE_FLOAT, type,
                      values.size());
}

tinygltf::Primitive make_primitive(tinygltf::Model& model, const TriangleMesh& part, int material) {
  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  primitive.material = material;

  std::vector<glm::vec3> positions(part.positions.size());
  std::transform(part.positions.begin(), part.positions.end(), positions.begin(), blender_to_gltf);
  const int position = add_float_attribute(model, positions, TINYGLTF_TYPE_VEC3);
  // glTF requires the bounds of POSITION.
  glm::vec3 lower(std::numeric_limits<float>::max()), upper(std::numeric_limits<float>::lowest());
  for (const glm::vec3& p : positions) lower = glm::min(lower, p), upper = glm::max(upper, p);
  model.accessors[static_cast<size_t>(position)].minValues = {lower.x, lower.y, lower.z};
  model.accessors[static_cast<size_t>(position)].maxValues = {upper.x, upper.y, upper.z};
  primitive.attributes["POSITION"] = position;

  if (!part.normals.empty()) {
    std::vector<glm::vec3> normals(part.normals.size());
    std::transform(part.normals.begin(), part.normals.end(), normals.begin(), blender_to_gltf);
    primitive.attributes["NORMAL"] = add_float_attribute(model, normals, TINYGLTF_TYPE_VEC3);
  }
  if (!part.uvs.empty()) {
    // glTF's v runs down the image from its top-left corner (see read_gltf).
    std::vector<glm::vec2> uvs(part.uvs.size());
    std::transform(part.uvs.begin(), part.uvs.end(), uvs.begin(),
                   [](const glm::vec2& uv) { return glm::vec2(uv.x, 1.0f - uv.y); });
    primitive.attributes["TEXCOORD_0"] = add_float_attribute(model, uvs, TINYGLTF_TYPE_VEC2);
    if (!part.tangents.empty()) {
      // The bitangent sign carries over unchanged with the v flip (see read_gltf).
      std::vector<glm::vec4> tangents(part.tangents.size());
      std::transform(part.tangents.begin(), part.tangents.end(), tangents.begin(), [](const glm::vec4& t) {
        return glm::vec4(blender_to_gltf(glm::vec3(t)), t.w < 0.0f ? -1.0f : 1.0f);
      });
      primitive.attributes["TANGENT"] = add_float_attribute(model, tangents, TINYGLTF_TYPE_VEC4);
    }
  }
  std::vector<uint32_t> indices;
  indices.reserve(3 * part.triangles.size());
  for (const glm::uvec3& t : part.triangles) indices.insert(indices.end(), {t.x, t.y, t.z});
  primitive.indices = add_accessor(model, add_buffer_view(model, indices, kElementArrayBuffer),
                                   TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, indices.size());
  return primitive;
}

// Textures are (image, wrap) pairs; each distinct pair is written once. Images are the asset's,
// then the ones the writer adds (indices from the asset's image count on).
// KHR_texture_transform's object for a transform that is not the identity (the inverse of
// read_gltf's read_texture_transform).
tinygltf::Value transform_extension(const matmaterial::TextureTransform& transform) {
  tinygltf::Value::Object object;
  object["offset"] = tinygltf::Value(tinygltf::Value::Array{tinygltf::Value(transform.offset.x), tinygltf::Value(transform.offset.y)});
  object["rotation"] = tinygltf::Value(transform.rotation);
  object["scale"] = tinygltf::Value(tinygltf::Value::Array{tinygltf::Value(transform.scale.x), tinygltf::Value(transform.scale.y)});
  return tinygltf::Value(object);
}

class TextureTable {
 public:
  TextureTable(tinygltf::Model& model, const std::vector<matbase::ImagePixels>& images) : model_(model), images_(images) {}

  // The texture for glTF's metallicRoughnessTexture (-1 for none); an image packed for it is
  // added once per distinct pair of inputs.
  int metallic_roughness_texture(const matmaterial::MaterialInputs& desc, const std::string& what) {
    const matmaterial::MaterialInput& roughness = desc[matmaterial::MaterialParameter::Roughness];
    const matmaterial::MaterialInput& metallic = desc[matmaterial::MaterialParameter::Metallic];
    const auto key = std::make_tuple(roughness.image, roughness.channel, metallic.image, metallic.channel);
    auto found = packed_images_.find(key);
    if (found == packed_images_.end()) {
      gltf::MetallicRoughnessImage image = gltf::metallic_roughness_image(desc, images_, what);
      if (image.packed) {
        added_.push_back(std::move(*image.packed));
        image.image = static_cast<int>(images_.size() + added_.size()) - 1;
      }
      found = packed_images_.emplace(key, image.image).first;
    }
    return texture(found->second, desc.wrap, what);
  }

  // Writes a textureInfo's placement into its extensions (nothing for the identity), and
  // remembers that the file uses KHR_texture_transform.
  void place(const matmaterial::TextureTransform& transform, tinygltf::ExtensionMap& extensions) {
    if (transform.is_identity()) return;
    extensions[gltf::kTextureTransform] = transform_extension(transform);
    transforms_placed_ = true;
  }
  bool transforms_placed() const { return transforms_placed_; }

  int texture(int image, matmaterial::TextureWrap wrap, const std::string& what) {
    if (image < 0) return -1;
    if (static_cast<size_t>(image) >= images_.size() + added_.size())
      throw std::invalid_argument("write_gltf: " + what + " refers to image " + std::to_string(image) +
                                  " but the asset has " + std::to_string(images_.size()));
    const auto key = std::make_pair(image, wrap);
    const auto found = textures_.find(key);
    if (found != textures_.end()) return found->second;
    tinygltf::Texture texture;
    texture.source = gltf_image(image);
    texture.sampler = sampler(wrap);
    model_.textures.push_back(texture);
    const int index = static_cast<int>(model_.textures.size()) - 1;
    textures_.emplace(key, index);
    return index;
  }

 private:
  int gltf_image(int image) {
    const auto found = gltf_images_.find(image);
    if (found != gltf_images_.end()) return found->second;
    const size_t source = static_cast<size_t>(image);
    const matbase::ImagePixels& pixels = source < images_.size() ? images_[source] : added_[source - images_.size()];
    if (!matbase::is_well_formed(pixels))
      throw std::invalid_argument("write_gltf: image " + std::to_string(image) + " (" + pixels.name +
                                  ") has inconsistent size or channels");
    tinygltf::Image out;
    out.name = pixels.name;
    out.width = pixels.width;
    out.height = pixels.height;
    out.component = pixels.channels;
    out.bits = 8;
    out.pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    out.mimeType = "image/png";
    out.image = pixels.data;
    model_.images.push_back(std::move(out));
    const int index = static_cast<int>(model_.images.size()) - 1;
    gltf_images_.emplace(image, index);
    return index;
  }

  int sampler(matmaterial::TextureWrap wrap) {
    const auto found = samplers_.find(wrap);
    if (found != samplers_.end()) return found->second;
    tinygltf::Sampler sampler;
    const int mode = wrap == matmaterial::TextureWrap::Clamp ? TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE : TINYGLTF_TEXTURE_WRAP_REPEAT;
    sampler.wrapS = mode;
    sampler.wrapT = mode;
    sampler.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
    sampler.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
    model_.samplers.push_back(sampler);
    const int index = static_cast<int>(model_.samplers.size()) - 1;
    samplers_.emplace(wrap, index);
    return index;
  }

  tinygltf::Model& model_;
  const std::vector<matbase::ImagePixels>& images_;
  std::vector<matbase::ImagePixels> added_;
  std::map<std::tuple<int, int, int, int>, int> packed_images_;
  std::map<std::pair<int, matmaterial::TextureWrap>, int> textures_;
  std::map<int, int> gltf_images_;
  std::map<matmaterial::TextureWrap, int> samplers_;
  bool transforms_placed_ = false;
};

// The one transform of inputs glTF reads through one textureInfo (metallic and roughness, base
// colour and its alpha); they cannot differ there.
matmaterial::TextureTransform shared_transform(const matmaterial::MaterialInputs& desc, std::initializer_list<matmaterial::MaterialParameter> inputs,
                                  const std::string& what) {
  const matmaterial::MaterialInput* first = nullptr;
  for (const matmaterial::MaterialParameter p : inputs) {
    const matmaterial::MaterialInput& input = desc[p];
    if (input.image < 0) continue;
    if (first && !(first->transform == input.transform))
      throw std::invalid_argument("write_gltf: " + what + " places the images of " +
                                  matmaterial::material_parameter(*inputs.begin()).name + " and " + matmaterial::material_parameter(p).name +
                                  " differently on the UVs, and glTF reads both through one texture");
    if (!first) first = &input;
  }
  return first ? first->transform : matmaterial::TextureTransform{};
}

// A textureInfo object for image `image` of a scalar that glTF reads from `channel`; the
// writer does not repack single-channel inputs, so another channel is an error.
tinygltf::Value::Object texture_info(const matmaterial::MaterialInputs& desc, matmaterial::MaterialParameter p, int channel, TextureTable& textures,
                                     const std::string& what) {
  const matmaterial::MaterialInput& input = desc[p];
  if (input.channel != channel)
    throw std::invalid_argument("write_gltf: " + what + " " + matmaterial::material_parameter(p).name + " reads image channel " +
                                std::to_string(input.channel) + ", but glTF reads it from channel " +
                                std::to_string(channel));
  tinygltf::Value::Object info;
  info["index"] = tinygltf::Value(textures.texture(input.image, desc.wrap, what));
  tinygltf::ExtensionMap extensions;
  textures.place(input.transform, extensions);
  if (!extensions.empty()) info["extensions"] = tinygltf::Value(tinygltf::Value::Object(extensions.begin(), extensions.end()));
  return info;
}

// An input as factor x one channel of a texture into `extension`, the inverse of read_gltf's
// read_extension_input.
void write_extension_input(const matmaterial::MaterialInputs& desc, matmaterial::MaterialParameter p, const char* factor_member,
                           const char* texture_member, int channel, TextureTable& textures, const std::string& what,
                           tinygltf::Value::Object& extension) {
  extension[factor_member] = tinygltf::Value(desc.scalar(p));
  if (desc[p].image >= 0)
    extension[texture_member] = tinygltf::Value(texture_info(desc, p, channel, textures, what));
}

// KHR_materials_clearcoat, the inverse of read_gltf's read_clearcoat.
tinygltf::Value::Object clearcoat_extension(const matmaterial::MaterialInputs& desc, TextureTable& textures, const std::string& what) {
  tinygltf::Value::Object extension;
  write_extension_input(desc, matmaterial::MaterialParameter::Clearcoat, "clearcoatFactor", "clearcoatTexture",
                        gltf::kClearcoatChannel, textures, what, extension);
  write_extension_input(desc, matmaterial::MaterialParameter::ClearcoatRoughness, "clearcoatRoughnessFactor",
                        "clearcoatRoughnessTexture", gltf::kClearcoatRoughnessChannel, textures, what, extension);
  return extension;
}

// KHR_materials_transmission, the inverse of read_gltf's read_transmission.
tinygltf::Value::Object transmission_extension(const matmaterial::MaterialInputs& desc, TextureTable& textures,
                                               const std::string& what) {
  tinygltf::Value::Object extension;
  write_extension_input(desc, matmaterial::MaterialParameter::Transmission, "transmissionFactor", "transmissionTexture",
                        gltf::kTransmissionChannel, textures, what, extension);
  return extension;
}

// KHR_materials_sheen, the inverse of read_gltf's read_sheen.
tinygltf::Value::Object sheen_extension(const matmaterial::MaterialInputs& desc, TextureTable& textures, const std::string& what) {
  using P = matmaterial::MaterialParameter;
  tinygltf::Value::Object extension;
  const glm::dvec3 colour = desc.color(P::VelvetColor);
  extension["sheenColorFactor"] = tinygltf::Value(
      tinygltf::Value::Array{tinygltf::Value(colour.r), tinygltf::Value(colour.g), tinygltf::Value(colour.b)});
  if (desc[P::VelvetColor].image >= 0)
    extension["sheenColorTexture"] = tinygltf::Value(texture_info(desc, P::VelvetColor, 0, textures, what));
  write_extension_input(desc, P::VelvetSigma, "sheenRoughnessFactor", "sheenRoughnessTexture",
                        gltf::kSheenRoughnessChannel, textures, what, extension);
  return extension;
}

// Opacity below 1 as alphaMode BLEND: its constant in baseColorFactor[3], its image (if any)
// the base colour texture's alpha, the only place glTF keeps it.
void write_opacity(const matmaterial::MaterialInputs& desc, const std::string& what, tinygltf::Material& material) {
  using P = matmaterial::MaterialParameter;
  const matmaterial::MaterialInput& opacity = desc[P::Alpha];
  if (opacity.image < 0 && opacity.value.x == 1.0) return;
  if (opacity.image >= 0 &&
      (opacity.image != desc[P::BaseColor].image || opacity.channel != gltf::kBaseColorAlphaChannel))
    throw std::invalid_argument("write_gltf: " + what +
                                " takes its opacity from an image that is not the base colour's alpha, and glTF "
                                "keeps opacity only there");
  material.alphaMode = "BLEND";
  material.pbrMetallicRoughness.baseColorFactor[3] = opacity.value.x;
}

// The inverse of read_gltf's mapping (docs/conventions.md: Blender's glTF importer).
tinygltf::Material make_material(const matmaterial::MaterialInputs& desc, TextureTable& textures) {
  tinygltf::Material material;
  material.name = desc.name;
  tinygltf::PbrMetallicRoughness& pbr = material.pbrMetallicRoughness;
  using P = matmaterial::MaterialParameter;
  const glm::dvec3 base_color = desc.color(P::BaseColor);
  pbr.baseColorFactor = {base_color.r, base_color.g, base_color.b, 1.0};
  pbr.metallicFactor = desc.scalar(P::Metallic);
  pbr.roughnessFactor = desc.scalar(P::Roughness);
  const std::string what = "material " + desc.name;
  pbr.baseColorTexture.index = textures.texture(desc[P::BaseColor].image, desc.wrap, what);
  textures.place(shared_transform(desc, {P::BaseColor, P::Alpha}, what), pbr.baseColorTexture.extensions);
  write_opacity(desc, what, material);
  pbr.metallicRoughnessTexture.index = textures.metallic_roughness_texture(desc, what);
  textures.place(shared_transform(desc, {P::Roughness, P::Metallic}, what), pbr.metallicRoughnessTexture.extensions);
  material.normalTexture.index = textures.texture(desc.normal_image, desc.wrap, what);
  if (desc.normal_image >= 0) textures.place(desc.normal_transform, material.normalTexture.extensions);
  material.normalTexture.scale = desc.normal_strength;
  const glm::dvec3 emission = desc.color(P::Emission);
  material.emissiveFactor = {emission.r, emission.g, emission.b};
  material.emissiveTexture.index = textures.texture(desc[P::Emission].image, desc.wrap, what);
  textures.place(shared_transform(desc, {P::Emission}, what), material.emissiveTexture.extensions);
  // glTF's factor stops at 1; the rest is the extension's (Blender's exporter writes it the same way).
  if (desc.scalar(P::EmissionStrength) != 1.0) {
    tinygltf::Value::Object strength;
    strength["emissiveStrength"] = tinygltf::Value(desc.scalar(P::EmissionStrength));
    material.extensions[gltf::kEmissiveStrength] = tinygltf::Value(strength);
  }
  if (desc.scalar(P::Ior) != gltf::kDefaultIor) {
    tinygltf::Value::Object ior;
    ior["ior"] = tinygltf::Value(desc.scalar(P::Ior));
    material.extensions[gltf::kIor] = tinygltf::Value(ior);
  }
  if (desc.scalar(P::Clearcoat) != 0.0 || desc[P::Clearcoat].image >= 0)
    material.extensions[gltf::kClearcoat] = tinygltf::Value(clearcoat_extension(desc, textures, what));
  // Blender's importer ignores the extension's texture when the factor is 0.
  if (desc.scalar(P::Transmission) != 0.0)
    material.extensions[gltf::kTransmission] = tinygltf::Value(transmission_extension(desc, textures, what));
  // Without the extension no velvet is made, which is what a black colour makes too.
  if (desc.color(P::VelvetColor) != glm::dvec3(0.0))
    material.extensions[gltf::kSheen] = tinygltf::Value(sheen_extension(desc, textures, what));
  return material;
}

tinygltf::Model make_model(const ObjectAsset& asset) {
  validate_mesh(asset.mesh, "write_gltf");
  if (asset.mesh.triangles.empty()) throw std::invalid_argument("write_gltf: the mesh has no triangles");
  if (asset.materials.size() < asset.mesh.part_count())
    throw std::invalid_argument("write_gltf: " + std::to_string(asset.mesh.part_count()) + " parts but " +
                                std::to_string(asset.materials.size()) + " materials");
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "matpredict";
  model.buffers.resize(1);
  TextureTable textures(model, asset.images);
  for (const matmaterial::MaterialInputs& desc : asset.materials) model.materials.push_back(make_material(desc, textures));
  if (textures.transforms_placed()) model.extensionsUsed.push_back(gltf::kTextureTransform);
  for (const char* extension :
       {gltf::kEmissiveStrength, gltf::kIor, gltf::kClearcoat, gltf::kTransmission, gltf::kSheen})
    for (const tinygltf::Material& material : model.materials)
      if (material.extensions.count(extension)) {
        model.extensionsUsed.push_back(extension);
        break;
      }

  tinygltf::Mesh mesh;
  for (const MeshPart& part : split_parts(asset.mesh))
    mesh.primitives.push_back(make_primitive(model, part.mesh, static_cast<int>(part.id)));
  model.meshes.push_back(mesh);
  tinygltf::Node node;
  node.mesh = 0;
  model.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.nodes = {0};
  model.scenes.push_back(scene);
  model.defaultScene = 0;
  return model;
}

}  // namespace

void write_gltf(const ObjectAsset& asset, const std::string& path) {
  const tinygltf::Model model = make_model(asset);
  const std::string extension = std::filesystem::path(path).extension().string();
  const bool binary = extension == ".glb" || extension == ".GLB";
  if (!binary && extension != ".gltf" && extension != ".GLTF")
    throw std::invalid_argument("write_gltf: " + path + ": the extension must be .glb or .gltf");
  matbase::write_atomically(path, [&](const std::filesystem::path& temporary) {
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToFile(&model, temporary.string(), /*embedImages=*/true, /*embedBuffers=*/true,
                                     /*prettyPrint=*/!binary, binary))
      throw std::runtime_error(path + ": cannot write the glTF file");
  });
}

}  // namespace matgeom
