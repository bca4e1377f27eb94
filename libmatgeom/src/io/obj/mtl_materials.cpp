#include "io/obj/mtl_materials.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include <glm/glm.hpp>
#include <tiny_obj_loader.h>

#include "matbase/file/file_error.h"
#include "io/obj/mtl_placement.h"
#include "io/obj/mtl_texture_paths.h"
#include "io/obj/mtl_textures.h"

// Materials: MTL to the Principled BSDF as Blender's OBJ importer builds it
// (io/wavefront_obj/importer/obj_import_mtl.cc, set_bsdf_socket_values and add_image_textures).
// Blender 3.4 reads the classic MTL statements and Ni, d, Ke, Tf, Pc, Pcr, Ps, map_Ke and map_d,
// and links map_Ks to Specular, map_Ns to Roughness, refl to Metallic and map_Ps to Sheen
// (checked by importing files into Blender 3.4.1); the PBR extension (Pr, Pm, map_Pr, map_Pm) is
// read as Blender 3.5 added it: its values, when given, replace the ones derived from Ns and Ka,
// and its maps the ones of map_Ns and refl. Not applied, as by Blender: Tr, map_Ka, disp (said in
// the file's notes), anisotropy, and the texture option -type. Blender ignores -clamp, so textures repeat. The options -o and -s place each map as
// Blender's Mapping node does (mtl_placement.h). tinyobjloader reads Kt as Tf; Blender may not.

namespace matgeom::obj {
namespace {

namespace fs = std::filesystem;

struct IllumFlags {
  bool highlight = false;
  bool reflection = false;
  bool transparency = false;
  bool glass = false;
};

// Blender: illum 2 turns highlights on, 3 to 8 turn reflection on, 4, 6, 7 and 9 transparency,
// 4 and 9 glass.
IllumFlags illum_flags(int illum) {
  return {illum == 2, illum >= 3 && illum <= 8, illum == 4 || illum == 6 || illum == 7 || illum == 9,
          illum == 4 || illum == 9};
}

bool given3(const tinyobj::real_t* values) { return values[0] >= 0.0f && values[1] >= 0.0f && values[2] >= 0.0f; }

// The screening refused every value outside its parameter's range as written
// (mtl_text_screening.cpp); tinyobjloader's own decimal arithmetic ("100e-2" is 100 x 5^-2 x 2^-2)
// can still land a rounding step outside it.
double clamped(matmaterial::MaterialParameter p, double value) { return matmaterial::clamp_to_range(p, value); }

double mean3(const tinyobj::real_t* values) {
  return (static_cast<double>(values[0]) + values[1] + values[2]) / 3.0;
}

class MaterialConverter {
 public:
  MaterialConverter(const ObjFile& file, TextureTable& textures, std::vector<std::string>& notes)
      : file_(file), textures_(textures), notes_(notes) {}

  matmaterial::MaterialInputs convert(size_t index) const {
    const tinyobj::material_t& material = file_.materials[index];
    const std::string what =
        matbase::concat(file_.material_libraries[index], ": material ", matbase::excerpt(material.name));
    check_finite_values(material, what);
    matmaterial::MaterialInputs desc(material.name);
    check_ambient(material, what);
    set_scalars(material, desc);
    check_ior(material, what, desc);
    set_textures(material, index, what, desc);
    return desc;
  }

 private:
  // The screening checked every number as written; tinyobjloader's own arithmetic can still make
  // a NaN or an infinity of one (0e999 is 0 x inf to it).
  void check_finite_values(const tinyobj::material_t& material, const std::string& what) const {
    const auto finite3 = [](const tinyobj::real_t* v) {
      return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
    };
    const bool finite = finite3(material.diffuse) && finite3(material.specular) &&
                        finite3(material.ambient) && std::isfinite(material.shininess) &&
                        std::isfinite(material.roughness) && std::isfinite(material.metallic) &&
                        std::isfinite(material.bump_texopt.bump_multiplier) &&
                        std::isfinite(material.normal_texopt.bump_multiplier) && std::isfinite(material.ior) &&
                        std::isfinite(material.dissolve) && finite3(material.emission) &&
                        finite3(material.transmittance) && std::isfinite(material.clearcoat_thickness) &&
                        std::isfinite(material.clearcoat_roughness) && std::isfinite(material.sheen);
    if (!finite) matbase::fail(file_.path, what + ": non-finite value");
  }

  // Ka shades only as the metallic of a reflecting illum model without Pm: there it must be a
  // fraction; elsewhere any Ka the format allows is read (and does nothing, as in Blender).
  void check_ambient(const tinyobj::material_t& material, const std::string& what) const {
    const double ka = mean3(material.ambient);
    if (!illum_flags(material.illum).reflection || material.metallic >= 0.0f || ka < 0.0) return;
    const matmaterial::MaterialParameterInfo& metallic = matmaterial::material_parameter(matmaterial::MaterialParameter::Metallic);
    if (ka > metallic.max)
      matbase::fail(file_.path, matbase::concat(what, ": Ka's mean ", ka, " is the metallic of illum ", material.illum,
                                                ", which must be from ", metallic.min, " to ", metallic.max));
  }

  // Ni reaches the render only through glass (Principled's transmission): a material that transmits
  // needs an IOR the parameter can hold; any other keeps Ni clamped into the range, which changes
  // nothing it shades (Blender reads "Ni 0", which exporters write for "unset", as written).
  void check_ior(const tinyobj::material_t& material, const std::string& what, const matmaterial::MaterialInputs& desc) const {
    using P = matmaterial::MaterialParameter;
    if (material.ior < 0.0f || desc.scalar(P::Transmission) == 0.0) return;
    const matmaterial::MaterialParameterInfo& ior = matmaterial::material_parameter(P::Ior);
    if (material.ior < ior.min)
      matbase::fail(file_.path, matbase::concat(what, ": Ni ", material.ior, " with transmission ", desc.scalar(P::Transmission),
                                                ": glass needs an IOR from ", ior.min, " to ", ior.max));
  }

  // The -1 "not given" markers come from kNotGivenMarkers (obj_text_screening.cpp).
  static void set_scalars(const tinyobj::material_t& material, matmaterial::MaterialInputs& desc) {
    using P = matmaterial::MaterialParameter;
    const IllumFlags illum = illum_flags(material.illum);
    // Base colour: Kd when given; otherwise Principled's default grey, which MaterialInputs
    // already holds.
    const glm::dvec3 kd(material.diffuse[0], material.diffuse[1], material.diffuse[2]);
    if (given3(material.diffuse)) {
      desc.set(P::BaseColor, glm::dvec3(clamped(P::BaseColor, kd.r), clamped(P::BaseColor, kd.g), clamped(P::BaseColor, kd.b)));
    }
    // Specular: the mean of Ks; without Ks, 1 with highlights and 0 otherwise.
    const double ks = mean3(material.specular);
    desc.set(P::Specular, ks >= 0.0 ? clamped(P::Specular, ks) : (illum.highlight ? 1.0 : 0.0));
    // Roughness: Pr; otherwise 1 - sqrt(Ns / 1000) with Ns clamped to [0, 1000]; without Ns,
    // 0 with highlights and 1 otherwise.
    if (material.roughness >= 0.0f) {
      desc.set(P::Roughness, clamped(P::Roughness, material.roughness));
    } else if (material.shininess >= 0.0f) {
      desc.set(P::Roughness, 1.0 - std::sqrt(std::clamp<double>(material.shininess, 0.0, 1000.0) / 1000.0));
    } else {
      desc.set(P::Roughness, illum.highlight ? 0.0 : 1.0);
    }
    // Metallic: Pm; otherwise for reflecting illum models the mean of Ka (1 without Ka), and 0
    // for all others -- OBJ materials are dielectric unless they say otherwise, unlike glTF's.
    const double ka = mean3(material.ambient);
    if (material.metallic >= 0.0f) {
      desc.set(P::Metallic, clamped(P::Metallic, material.metallic));
    } else {
      desc.set(P::Metallic, illum.reflection ? (ka >= 0.0 ? clamped(P::Metallic, ka) : 1.0) : 0.0);
    }
    // IOR: Ni; without it 1.5 for glass, 1 for other transparency, else the node's default.
    if (material.ior >= 0.0f) {
      desc.set(P::Ior, clamped(P::Ior, material.ior));
    } else if (illum.glass || illum.transparency) {
      desc.set(P::Ior, illum.glass ? 1.5 : 1.0);
    }
    // Opacity: d (Blender's Alpha); transparency without d keeps 1.
    if (material.dissolve >= 0.0f) desc.set(P::Alpha, clamped(P::Alpha, material.dissolve));
    // Emission: Ke. Blender takes it as the colour at strength 1 whatever its size; the table
    // keeps colours in [0, 1], so a brighter Ke becomes its largest component as the strength
    // and the rest as the colour: the same radiance.
    if (given3(material.emission)) {
      const glm::dvec3 ke(material.emission[0], material.emission[1], material.emission[2]);
      const double strength = std::max({ke.r, ke.g, ke.b, 1.0});
      desc.set(P::Emission, ke / strength);
      desc.set(P::EmissionStrength, clamped(P::EmissionStrength, strength));
    }
    // Transmission: the mean of Tf.
    if (given3(material.transmittance)) desc.set(P::Transmission, clamped(P::Transmission, mean3(material.transmittance)));
    // Blender 3.4 has no 0.25 factor on Pc: it is the Clearcoat input itself.
    if (material.clearcoat_thickness >= 0.0f) desc.set(P::Clearcoat, clamped(P::Clearcoat, material.clearcoat_thickness));
    if (material.clearcoat_roughness >= 0.0f)
      desc.set(P::ClearcoatRoughness, clamped(P::ClearcoatRoughness, material.clearcoat_roughness));
    if (material.sheen >= 0.0f) desc.set(P::Sheen, clamped(P::Sheen, material.sheen));
  }

  // A connected Image Texture replaces the socket value in Blender, so an input with a map has
  // factor 1 (for metallic-roughness only the mapped channel has, see TextureTable).
  void set_textures(const tinyobj::material_t& material, size_t index, const std::string& what,
                    matmaterial::MaterialInputs& desc) const {
    if (!material.diffuse_texname.empty()) {
      const TextureSource kd = source(material.diffuse_texname, index, what + " map_Kd");
      desc.set_image(matmaterial::MaterialParameter::BaseColor, textures_.color_texture(kd), 0, placement(material.diffuse_texopt, kd));
      desc.set(matmaterial::MaterialParameter::BaseColor, 1.0);
    }
    // map_Ke: the emission colour, at strength 1.
    if (!material.emissive_texname.empty()) {
      const TextureSource ke = source(material.emissive_texname, index, what + " map_Ke");
      desc.set_image(matmaterial::MaterialParameter::Emission, textures_.color_texture(ke), 0, placement(material.emissive_texopt, ke));
      desc.set(matmaterial::MaterialParameter::Emission, 1.0).set(matmaterial::MaterialParameter::EmissionStrength, 1.0);
    }
    // map_d: Blender links the image's Alpha output (1 for an image without alpha).
    if (!material.alpha_texname.empty()) {
      const TextureSource d = source(material.alpha_texname, index, what + " map_d");
      desc.set_image(matmaterial::MaterialParameter::Alpha, textures_.color_texture(d), 3, placement(material.alpha_texopt, d));
      desc.set(matmaterial::MaterialParameter::Alpha, 1.0);
    }
    set_metallic_roughness_texture(material, index, what, desc);
    set_normal_texture(material, index, what, desc);
    // Blender links map_Ks to Specular and map_Ps to Sheen, a colour read by a float input.
    set_luminance_texture(material.specular_texname, material.specular_texopt, index, what + " map_Ks",
                          matmaterial::MaterialParameter::Specular, desc);
    set_luminance_texture(material.sheen_texname, material.sheen_texopt, index, what + " map_Ps",
                          matmaterial::MaterialParameter::Sheen, desc);
    // Nor does Blender 3.4 apply these.
    if (!material.ambient_texname.empty()) add_note(notes_, what + ": map_Ka is not applied (nor by Blender)");
    if (!material.displacement_texname.empty())
      add_note(notes_, what + ": disp (displacement) is not applied (nor by Blender's importer)");
  }

  void set_luminance_texture(const std::string& name, const tinyobj::texture_option_t& options, size_t index,
                             const std::string& what, matmaterial::MaterialParameter p, matmaterial::MaterialInputs& desc) const {
    if (name.empty()) return;
    const TextureSource map = source(name, index, what);
    desc.set(p, 1.0).set_image(p, textures_.luminance_texture(map), 0, placement(options, map));
  }

  // Roughness: map_Pr, else map_Ns, which Blender 3.4 links to Roughness as it is (no 1 - sqrt);
  // metallic: map_Pm, else refl, which Blender 3.4 links to Metallic.
  void set_metallic_roughness_texture(const tinyobj::material_t& material, size_t index,
                                      const std::string& what, matmaterial::MaterialInputs& desc) const {
    const bool pr = !material.roughness_texname.empty(), pm = !material.metallic_texname.empty();
    const std::string& roughness_name = pr ? material.roughness_texname : material.specular_highlight_texname;
    const std::string& metallic_name = pm ? material.metallic_texname : material.reflection_texname;
    const tinyobj::texture_option_t& roughness_options = pr ? material.roughness_texopt : material.specular_highlight_texopt;
    const tinyobj::texture_option_t& metallic_options = pm ? material.metallic_texopt : material.reflection_texopt;
    if (roughness_name.empty() && metallic_name.empty()) return;
    std::optional<TextureSource> roughness, metallic;
    if (!roughness_name.empty()) roughness = source(roughness_name, index, what + (pr ? " map_Pr" : " map_Ns"));
    if (!metallic_name.empty()) metallic = source(metallic_name, index, what + (pm ? " map_Pm" : " refl"));
    const int packed = textures_.metallic_roughness_texture(roughness ? &*roughness : nullptr, metallic ? &*metallic : nullptr);
    // One image, each map still placed by its own -o and -s.
    const auto link = [&](matmaterial::MaterialParameter p, const tinyobj::texture_option_t& options, const TextureSource& map) {
      desc.set(p, 1.0).set_image(p, packed, matmaterial::material_parameter(p).packed_channel, placement(options, map));
    };
    if (roughness) link(matmaterial::MaterialParameter::Roughness, roughness_options, *roughness);
    if (metallic) link(matmaterial::MaterialParameter::Metallic, metallic_options, *metallic);
  }

  // Blender connects map_Bump (or bump) through a Normal Map node: it is a tangent-space normal
  // map, not a height map, with strength max(0, -bm). Blender ignores "norm", the PBR
  // extension's normal map, which is read here when map_Bump is absent. Without -bm Blender 3.4
  // leaves its -1 marker, making the strength 0 and the map invisible; the MTL default -bm 1
  // (tinyobjloader's) is kept instead. A negative -bm, which would hide the map, is refused
  // (mtl_text_screening.cpp).
  void set_normal_texture(const tinyobj::material_t& material, size_t index,
                          const std::string& what, matmaterial::MaterialInputs& desc) const {
    const bool bump = !material.bump_texname.empty();
    if (!bump && material.normal_texname.empty()) return;
    const TextureSource normal = bump ? source(material.bump_texname, index, what + " map_Bump")
                                      : source(material.normal_texname, index, what + " norm");
    desc.normal_image = textures_.color_texture(normal);
    const tinyobj::texture_option_t& options = bump ? material.bump_texopt : material.normal_texopt;
    desc.normal_strength = options.bump_multiplier;
    desc.normal_transform = placement(options, normal);
  }

  // -o and -s as the texture's transform. The screening refused a non-finite number and a scale
  // of 0 as written; tinyobjloader's own arithmetic can still make one ("0e999" is 0 x inf to it,
  // and a float cannot hold 1e-50).
  matmaterial::TextureTransform placement(const tinyobj::texture_option_t& options, const TextureSource& map) const {
    const MtlPlacement placed{{options.origin_offset[0], options.origin_offset[1]}, {options.scale[0], options.scale[1]}};
    const bool finite = std::isfinite(placed.origin.x) && std::isfinite(placed.origin.y) &&
                        std::isfinite(placed.scale.x) && std::isfinite(placed.scale.y);
    if (!finite || placed.scale.x == 0.0 || placed.scale.y == 0.0) {
      matbase::fail(file_.path, matbase::concat(map.what, ": -o ", placed.origin.x, " ", placed.origin.y, " -s ", placed.scale.x, " ",
                              placed.scale.y, " cannot place a texture (a scale of 0 or a non-finite number)"));
    }
    return texture_transform(placed);
  }

  // Texture paths are relative to the .mtl's folder, with Blender's fallbacks for paths written
  // on another machine (mtl_texture_paths.h). A texture found nowhere is refused (Blender would
  // render a black placeholder), naming the places looked at.
  TextureSource source(const std::string& name, size_t index, const std::string& what) const {
    const fs::path library(file_.material_libraries[index]);
    const TexturePathSearch search = find_texture_file(library.parent_path(), name);
    if (!search.found) {
      std::string tried;
      for (const std::string& place : search.tried) tried += (tried.empty() ? "" : ", ") + matbase::cut_short(place, 300);
      matbase::fail(file_.path, matbase::concat(what, ": texture ", matbase::excerpt(name), " not found (looked at ", tried, ")"));
    }
    return {name, *search.found, what};
  }

  const ObjFile& file_;
  TextureTable& textures_;
  std::vector<std::string>& notes_;
};

}  // namespace

// ---------------------------------------------------------------------------------------------
// Assembly of the asset

std::vector<matmaterial::MaterialInputs> part_materials(const ObjFile& file, const PartTable& parts,
                                         std::vector<matbase::ImagePixels>& images, std::vector<std::string>& notes) {
  TextureTable textures(file.path);
  const MaterialConverter converter(file, textures, notes);
  std::map<int, matmaterial::MaterialInputs> converted;
  std::vector<matmaterial::MaterialInputs> materials;
  for (const int material : parts.materials) {
    auto found = converted.find(material);
    if (found == converted.end()) {
      const matmaterial::MaterialInputs desc =
          material < 0 ? matmaterial::MaterialInputs("default") : converter.convert(static_cast<size_t>(material));
      found = converted.emplace(material, desc).first;
    }
    materials.push_back(found->second);
  }
  images = textures.take_images();
  return materials;
}

}  // namespace matgeom::obj
