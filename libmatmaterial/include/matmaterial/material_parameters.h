#pragma once
// The material parameters, declared once: the Principled BSDF's inputs, and the Velvet BSDF that
// Blender's glTF importer adds to it for KHR_materials_sheen. Scene files, the object readers'
// material mapping, the renderer's constant-or-textured decision, the material AOVs, parameter
// checks, the Cycles reference driver and the scene-format docs all follow this table; adding a
// parameter is one row here (and its enum value) plus the shading code that uses it.
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace matmaterial {

// How 8-bit texels of an image map to values: sRGB-encoded colour, or plain data.
enum class ColorSpace { SRGB, NonColor };

// Row order of the table; the values index Material::parameters.
enum class MaterialParameter : unsigned {
  BaseColor,
  Metallic,
  Roughness,
  Specular,
  SpecularTint,
  Ior,
  Sheen,
  SheenTint,
  Emission,
  EmissionStrength,
  Clearcoat,
  ClearcoatRoughness,
  Transmission,
  TransmissionRoughness,
  Alpha,
  VelvetColor,
  VelvetSigma,
};
constexpr size_t kMaterialParameterCount = 17;

// The Blender 3.4 shader node whose input a parameter mirrors. A material is a Principled BSDF,
// plus a Velvet BSDF joined to it by an Add Shader where the velvet colour is not black (what
// Blender's glTF importer builds for KHR_materials_sheen).
enum class BlenderNode { PrincipledBsdf, VelvetBsdf };

// The node's name in a new Blender material ("Principled BSDF") and in the docs.
constexpr const char* blender_node_name(BlenderNode node) {
  return node == BlenderNode::PrincipledBsdf ? "Principled BSDF" : "Velvet BSDF";
}

enum class ParameterKind {
  Color,   // RGB, from the RGB of a texture
  Scalar,  // one number, from one channel of a texture
};

struct MaterialParameterInfo {
  MaterialParameter id;
  const char* name;           // key in scene files and name in the docs
  BlenderNode node;           // the Blender 3.4 node it is an input of
  const char* blender_input;  // the name of that node's input
  ParameterKind kind;
  double default_value;      // Blender's default (every channel of a colour)
  double min, max;           // valid values (every channel of a colour)
  bool texturable;           // may come from an image
  ColorSpace texture_space;  // how its images are read unless a file says otherwise
  int packed_channel;        // its channel in a packed metallic-roughness image (glTF: G, B)
  bool default_aov;          // its AOV is among the ones written unless others are asked for
  const char* description;   // one line for the docs
};

constexpr std::array<MaterialParameterInfo, kMaterialParameterCount> kMaterialParameters = {{
    {MaterialParameter::BaseColor, "base_color", BlenderNode::PrincipledBsdf, "Base Color", ParameterKind::Color, 0.8,
     0.0, 1.0, true, ColorSpace::SRGB, 0, true, "diffuse albedo of dielectrics, specular colour of metals"},
    {MaterialParameter::Metallic, "metallic", BlenderNode::PrincipledBsdf, "Metallic", ParameterKind::Scalar, 0.0, 0.0,
     1.0, true, ColorSpace::NonColor, 2, true, "0 dielectric, 1 metal, mixed linearly between"},
    {MaterialParameter::Roughness, "roughness", BlenderNode::PrincipledBsdf, "Roughness", ParameterKind::Scalar, 0.5,
     0.0, 1.0, true, ColorSpace::NonColor, 1, true,
     "GGX alpha = roughness^2; also the principled diffuse retro-reflection"},
    {MaterialParameter::Specular, "specular", BlenderNode::PrincipledBsdf, "Specular", ParameterKind::Scalar, 0.5, 0.0,
     1.0, true, ColorSpace::NonColor, 0, false,
     "dielectric reflectance at normal incidence F0 = 0.08 specular (0.5: 4 %)"},
    {MaterialParameter::SpecularTint, "specular_tint", BlenderNode::PrincipledBsdf, "Specular Tint",
     ParameterKind::Scalar, 0.0, 0.0, 1.0, true, ColorSpace::NonColor, 0, false,
     "tints dielectric reflection toward the base colour's hue"},
    {MaterialParameter::Ior, "ior", BlenderNode::PrincipledBsdf, "IOR", ParameterKind::Scalar, 1.45, 1.0, 1000.0, false,
     ColorSpace::NonColor, 0, false,
     "the glass's index of refraction (entering through the front face, leaving through the back)"},
    {MaterialParameter::Sheen, "sheen", BlenderNode::PrincipledBsdf, "Sheen", ParameterKind::Scalar, 0.0, 0.0, 1.0,
     true, ColorSpace::NonColor, 0, false,
     "cloth's grazing sheen: f = sheen (1 - metallic) colour (1 - L.H)^5, added to the diffuse"},
    {MaterialParameter::SheenTint, "sheen_tint", BlenderNode::PrincipledBsdf, "Sheen Tint", ParameterKind::Scalar, 0.5,
     0.0, 1.0, true, ColorSpace::NonColor, 0, false, "mixes the sheen colour from white toward the base colour's hue"},
    {MaterialParameter::Emission, "emission", BlenderNode::PrincipledBsdf, "Emission", ParameterKind::Color, 0.0, 0.0,
     1.0, true, ColorSpace::SRGB, 0, false,
     "emitted radiance, times emission_strength, from both sides (strength 1: a white one shows as 1)"},
    {MaterialParameter::EmissionStrength, "emission_strength", BlenderNode::PrincipledBsdf, "Emission Strength",
     ParameterKind::Scalar, 1.0, 0.0, 1e6, true, ColorSpace::NonColor, 0, false, "scales the emission"},
    {MaterialParameter::Clearcoat, "clearcoat", BlenderNode::PrincipledBsdf, "Clearcoat", ParameterKind::Scalar, 0.0,
     0.0, 1.0, true, ColorSpace::NonColor, 0, false,
     "a lacquer layer on top: GGX-shadowed GTR1 reflection of weight 0.25 clearcoat with the Fresnel of ior 1.5"},
    {MaterialParameter::ClearcoatRoughness, "clearcoat_roughness", BlenderNode::PrincipledBsdf, "Clearcoat Roughness",
     ParameterKind::Scalar, 0.03, 0.0, 1.0, true, ColorSpace::NonColor, 0, false,
     "the lacquer's roughness: GTR1 alpha = clearcoat_roughness^2"},
    {MaterialParameter::Transmission, "transmission", BlenderNode::PrincipledBsdf, "Transmission",
     ParameterKind::Scalar, 0.0, 0.0, 1.0, true, ColorSpace::NonColor, 0, false,
     "glass: GGX reflection and refraction with the IOR, weighted transmission (1 - metallic), tinted by the base "
     "colour"},
    {MaterialParameter::TransmissionRoughness, "transmission_roughness", BlenderNode::PrincipledBsdf,
     "Transmission Roughness", ParameterKind::Scalar, 0.0, 0.0, 1.0, true, ColorSpace::NonColor, 0, false,
     "roughens the refraction only: its roughness is 1 - (1 - roughness)(1 - transmission_roughness)"},
    // Named as MatSynth's opacity maps: "alpha" is the film's coverage AOV.
    {MaterialParameter::Alpha, "opacity", BlenderNode::PrincipledBsdf, "Alpha", ParameterKind::Scalar, 1.0, 0.0, 1.0,
     true, ColorSpace::NonColor, 0, false,
     "Blender's Alpha: the surface scatters and emits this fraction of the light, the rest passes straight through"},
    // glTF's sheen (KHR_materials_sheen) as Blender 3.4 imports it; not scaled by opacity, metallic or transmission.
    {MaterialParameter::VelvetColor, "velvet_color", BlenderNode::VelvetBsdf, "Color", ParameterKind::Color, 0.0, 0.0,
     1.0, true, ColorSpace::SRGB, 0, false,
     "glTF sheen colour: a Velvet BSDF (Ashikhmin's cloth lobe) of this weight added to the material; black: none"},
    {MaterialParameter::VelvetSigma, "velvet_sigma", BlenderNode::VelvetBsdf, "Sigma", ParameterKind::Scalar, 1.0, 0.0,
     1.0, true, ColorSpace::NonColor, 0, false,
     "glTF sheen roughness: the velvet's width (at least 0.01); small values keep its light at grazing angles"},
}};

constexpr const MaterialParameterInfo& material_parameter(MaterialParameter id) {
  return kMaterialParameters[static_cast<size_t>(id)];
}

// `value` clamped to the parameter's valid range.
constexpr double clamp_to_range(MaterialParameter id, double value) {
  const MaterialParameterInfo& info = material_parameter(id);
  return value < info.min ? info.min : (value > info.max ? info.max : value);
}

// The parameter a scene-file key names, if any.
std::optional<MaterialParameter> material_parameter_named(std::string_view name);

// The table as the markdown table of docs/scene_format.md (a test holds the docs to it).
std::string material_parameters_markdown();

}  // namespace matmaterial
