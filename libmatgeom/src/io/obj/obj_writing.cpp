#include "io/obj/obj_writing.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>

#include <glm/glm.hpp>

#include "io/obj/mtl_placement.h"
#include "matbase/file/file_error.h"
#include "matbase/image/image_pixels.h"

namespace matgeom::obj {
namespace {

// Nine significant digits identify every float, so positions, normals and UVs read back exactly.
std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.9g", value);
  return text;
}

std::string triple(const glm::dvec3& v) {
  return number(v.x) + " " + number(v.y) + " " + number(v.z);
}

// Blender's +Z up to OBJ's +Y up, the inverse of obj_to_blender (obj_parts.cpp).
glm::dvec3 blender_to_obj(const glm::vec3& v) { return {v.x, v.z, -v.y}; }

void check_image(const ObjectAsset& asset, int image, const matmaterial::MaterialInputs& material) {
  if (image < 0) return;
  if (static_cast<size_t>(image) >= asset.images.size()) {
    throw std::invalid_argument(matbase::concat("write_obj: material '", material.name, "' refers to image ",
                                       image, " but the asset has ", asset.images.size()));
  }
  const matbase::ImagePixels& pixels = asset.images[static_cast<size_t>(image)];
  if (!matbase::is_well_formed(pixels)) {
    throw std::invalid_argument(matbase::concat("write_obj: image ", image, " (", pixels.name,
                                       ") has inconsistent size or channels"));
  }
}

// The maps mtl_text writes must be placed as -o and -s can say (mtl_placement.h), and as read_obj
// reads them back: without rotation, by numbers a float holds, at a scale other than 0.
void check_placement(const matmaterial::TextureTransform& transform, const matmaterial::MaterialInputs& material, const char* map) {
  const std::optional<MtlPlacement> placed = mtl_placement(transform);
  if (!placed) {
    throw std::invalid_argument(matbase::concat("write_obj: material '", material.name, "' rotates its ", map,
                                       " texture; MTL's -o and -s cannot rotate one"));
  }
  const auto in_float = [](double v) { return std::abs(v) <= std::numeric_limits<float>::max(); };
  const bool readable = in_float(placed->origin.x) && in_float(placed->origin.y) && in_float(placed->scale.x) &&
                        in_float(placed->scale.y) && static_cast<float>(placed->scale.x) != 0.0f &&
                        static_cast<float>(placed->scale.y) != 0.0f;
  if (!readable) {
    throw std::invalid_argument(matbase::concat("write_obj: material '", material.name, "' places its ", map,
                                       " texture by a scale of 0 or a number beyond a float"));
  }
}

// "-o u v 0 -s u v 1 " for a texture placed otherwise than as it lies, else nothing.
std::string placement_options(const matmaterial::TextureTransform& transform) {
  if (transform.is_identity()) return "";
  const MtlPlacement placed = *mtl_placement(transform);
  return "-o " + number(placed.origin.x) + " " + number(placed.origin.y) + " 0 -s " + number(placed.scale.x) + " " +
         number(placed.scale.y) + " 1 ";
}

// One channel of every pixel as a grey image; grey and grey-alpha images give their grey.
matbase::ImagePixels channel_image(const matbase::ImagePixels& image, int channel) {
  matbase::ImagePixels grey = matbase::blank_image("", image.width, image.height, 1);
  for (size_t i = 0; i < grey.data.size(); ++i) grey.data[i] = matbase::texel_channel(image, i, channel);
  return grey;
}

// tinyobjloader splits "mtllib" at spaces and takes '\' as an escape.
std::string escaped_library_name(const std::string& name) {
  std::string escaped;
  for (const char c : name) {
    if (c == ' ' || c == '\\') escaped += '\\';
    escaped += c;
  }
  return escaped;
}

// Corner reference "v", "v/vt", "v//vn" or "v/vt/vn"; every attribute shares the vertex's index.
std::string corner_reference(uint32_t vertex, bool uvs, bool normals) {
  const std::string index = std::to_string(vertex + 1);
  if (!uvs && !normals) return index;
  return index + "/" + (uvs ? index : "") + (normals ? "/" + index : "");
}

}  // namespace

std::string obj_safe_name(const std::string& name, const std::string& fallback) {
  if (name.empty()) return fallback;
  std::string safe = name;
  for (char& c : safe) {
    const unsigned char byte = static_cast<unsigned char>(c);
    if (byte <= ' ' || byte == 0x7f) c = '_';
  }
  return safe;
}

std::string UniqueNames::claim(const std::string& wanted) {
  std::string name = wanted;
  for (int suffix = 2; taken_.count(name) != 0; ++suffix) name = matbase::concat(wanted, "_", suffix);
  taken_.insert(name);
  return name;
}

void check_writable(const ObjectAsset& asset) {
  validate_mesh(asset.mesh, "write_obj");
  if (asset.mesh.triangles.empty())
    throw std::invalid_argument("write_obj: the mesh has no triangles");
  if (asset.materials.size() < asset.mesh.part_count()) {
    throw std::invalid_argument(matbase::concat("write_obj: ", asset.mesh.part_count(), " parts but ",
                                       asset.materials.size(), " materials"));
  }
  for (const matmaterial::MaterialInputs& material : asset.materials) {
    std::vector<double> values = {material.normal_strength};
    for (const matmaterial::MaterialInput& input : material.inputs) values.insert(values.end(), {input.value.r, input.value.g, input.value.b});
    if (!std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); })) {
      throw std::invalid_argument("write_obj: material '" + material.name +
                                  "' has a non-finite value");
    }
    for (const matmaterial::MaterialParameterInfo& info : matmaterial::kMaterialParameters) {
      const matmaterial::MaterialInput& input = material[info.id];
      check_image(asset, input.image, material);
      if (input.channel < 0 || input.channel > 3) {
        throw std::invalid_argument(matbase::concat("write_obj: material '", material.name, "' reads ", info.name,
                                           " from image channel ", input.channel, "; channels are 0 to 3"));
      }
    }
    check_image(asset, material.normal_image, material);
    using P = matmaterial::MaterialParameter;
    for (const P p : {P::BaseColor, P::Roughness, P::Metallic}) {
      if (material[p].image >= 0) check_placement(material[p].transform, material, matmaterial::material_parameter(p).name);
    }
    if (material.normal_image >= 0) check_placement(material.normal_transform, material, "normal");
  }
}

MaterialMaps ImageFiles::maps_of(const matmaterial::MaterialInputs& material) {
  using P = matmaterial::MaterialParameter;
  MaterialMaps maps;
  if (material[P::BaseColor].image >= 0) maps.base_color = image_file(material[P::BaseColor].image);
  if (material.normal_image >= 0) maps.normal = image_file(material.normal_image);
  const auto scalar_map = [&](P p) {
    const matmaterial::MaterialInput& input = material[p];
    return input.image < 0 ? std::string() : channel_file(input.image, input.channel, matmaterial::material_parameter(p).name);
  };
  maps.roughness = scalar_map(P::Roughness);
  maps.metallic = scalar_map(P::Metallic);
  return maps;
}

std::string ImageFiles::image_file(int image) {
  return add(matbase::concat(stem_, "_image", image, ".png"), images_[static_cast<size_t>(image)]);
}

std::string ImageFiles::channel_file(int image, int channel, const char* what) {
  const std::string name = matbase::concat(stem_, "_image", image, "_", what, ".png");
  if (written_.count(name) != 0) return name;
  return add(name, channel_image(images_[static_cast<size_t>(image)], channel));
}

std::string ImageFiles::add(const std::string& name, const matbase::ImagePixels& pixels) {
  if (written_.insert(name).second) files_.push_back({name, pixels});
  return name;
}

std::string mtl_text(const std::vector<NamedMaterial>& materials) {
  std::string text = "# matpredict\n";
  for (const NamedMaterial& material : materials) {
    const matmaterial::MaterialInputs& desc = *material.desc;
    text += "\nnewmtl " + material.name + "\n";
    using P = matmaterial::MaterialParameter;
    const double roughness = desc.scalar(P::Roughness), metallic = desc.scalar(P::Metallic);
    text += "Kd " + triple(desc.color(P::BaseColor)) + "\n";
    text += "Ks " + triple(glm::dvec3(desc.scalar(P::Specular))) + "\n";
    // For readers without the PBR extension (Blender before 3.5): Ns inverts Blender's
    // roughness = 1 - sqrt(Ns / 1000), and under illum 3 Blender's metallic is the mean of Ka.
    text += "Ns " + number(1000.0 * (1.0 - roughness) * (1.0 - roughness)) + "\n";
    text += "Ka " + triple(glm::dvec3(metallic)) + "\n";
    text += metallic > 0.0 ? "illum 3\n" : "illum 2\n";
    text += "Pr " + number(roughness) + "\n";
    text += "Pm " + number(metallic) + "\n";
    // The other inputs Blender 3.4's importer reads, where they differ from its defaults.
    text += "Ni " + number(desc.scalar(P::Ior)) + "\n";
    if (desc.scalar(P::Alpha) != 1.0) text += "d " + number(desc.scalar(P::Alpha)) + "\n";
    const glm::dvec3 radiance = desc.color(P::Emission) * desc.scalar(P::EmissionStrength);
    if (radiance != glm::dvec3(0.0)) text += "Ke " + triple(radiance) + "\n";
    if (desc.scalar(P::Transmission) != 0.0) text += "Tf " + triple(glm::dvec3(desc.scalar(P::Transmission))) + "\n";
    if (desc.scalar(P::Clearcoat) != 0.0) {
      text += "Pc " + number(desc.scalar(P::Clearcoat)) + "\n";
      text += "Pcr " + number(desc.scalar(P::ClearcoatRoughness)) + "\n";
    }
    if (desc.scalar(P::Sheen) != 0.0) text += "Ps " + number(desc.scalar(P::Sheen)) + "\n";
    const MaterialMaps& maps = material.maps;
    const auto map = [&](const std::string& keyword, const matmaterial::TextureTransform& transform, const std::string& file) {
      text += keyword + " " + placement_options(transform) + file + "\n";
    };
    if (!maps.base_color.empty()) map("map_Kd", desc[P::BaseColor].transform, maps.base_color);
    if (!maps.roughness.empty()) map("map_Pr", desc[P::Roughness].transform, maps.roughness);
    if (!maps.metallic.empty()) map("map_Pm", desc[P::Metallic].transform, maps.metallic);
    if (!maps.normal.empty()) map("map_Bump -bm " + number(desc.normal_strength), desc.normal_transform, maps.normal);
  }
  return text;
}

std::string obj_text(const TriangleMesh& mesh, const std::string& library,
                     const std::vector<std::string>& group_names,
                     const std::vector<NamedMaterial>& materials) {
  std::ostringstream text;
  text << "# matpredict\nmtllib " << escaped_library_name(library) << "\n";
  for (const glm::vec3& p : mesh.positions) text << "v " << triple(blender_to_obj(p)) << "\n";
  for (const glm::vec2& uv : mesh.uvs) text << "vt " << number(uv.x) << " " << number(uv.y) << "\n";
  for (const glm::vec3& n : mesh.normals) text << "vn " << triple(blender_to_obj(n)) << "\n";

  std::vector<std::vector<size_t>> triangles_of_part(group_names.size());
  for (size_t t = 0; t < mesh.triangle_count(); ++t) {
    triangles_of_part[mesh.triangle_parts.empty() ? 0 : mesh.triangle_parts[t]].push_back(t);
  }
  const bool uvs = !mesh.uvs.empty(), normals = !mesh.normals.empty();
  for (size_t part = 0; part < group_names.size(); ++part) {
    // A part without triangles would leave only an empty group, which readers drop anyway.
    if (triangles_of_part[part].empty()) continue;
    text << "g " << group_names[part] << "\nusemtl " << materials[part].name << "\n";
    for (const size_t t : triangles_of_part[part]) {
      const glm::uvec3& triangle = mesh.triangles[t];
      text << "f " << corner_reference(triangle[0], uvs, normals) << " "
           << corner_reference(triangle[1], uvs, normals) << " "
           << corner_reference(triangle[2], uvs, normals) << "\n";
    }
  }
  return text.str();
}

}  // namespace matgeom::obj
