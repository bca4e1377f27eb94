#include "matrender/scene_file.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <functional>
#include <optional>
#include <sstream>

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include "lights/light_checks.h"
#include "matbase/document/json_document.h"
#include "matbase/number_text.h"
#include "matbase/text.h"
#include "matgeom/builtin/builtin_objects.h"
#include "matgeom/camera_grid.h"
#include "matgeom/io/mesh_io.h"
#include "matgeom/shading_normals.h"
#include "matmaterial/material_classes.h"
#include "matmaterial/material_parameters.h"
#include "matrender/builtin_environments.h"
#include "matrender/image_io.h"
#include "matrender/render_setting_reading.h"
#include "scene_description/lamp_reading.h"
#include "scene_description/scene_file_values.h"

namespace matrender {
namespace {

namespace fs = std::filesystem;
using matbase::DocumentNode;
using matbase::quoted_list;

// ---- small value types ----------------------------------------------------------------------

// [min, max] with min < max, both accepted by `element`.
std::pair<double, double> read_range(const DocumentNode& node,
                                     const std::function<double(const DocumentNode&)>& element) {
  const std::vector<DocumentNode> ends = node.items(2, "[min, max]");
  const double lo = element(ends[0]), hi = element(ends[1]);
  if (!(lo < hi)) node.fail("expected [min, max] with min < max");
  return {lo, hi};
}

// 4 rows of 4 numbers, row-major as written; glm stores columns.
glm::dmat4 read_matrix(const DocumentNode& node) {
  const std::vector<DocumentNode> rows = node.items(4, "a 4x4 matrix as 4 rows of 4 numbers");
  glm::dmat4 m(1.0);
  for (size_t r = 0; r < 4; ++r) {
    const std::vector<DocumentNode> row = rows[r].items(4, "a row of 4 numbers");
    for (size_t c = 0; c < 4; ++c) m[static_cast<int>(c)][static_cast<int>(r)] = row[c].number();
  }
  if (m[0][3] != 0.0 || m[1][3] != 0.0 || m[2][3] != 0.0 || m[3][3] != 1.0)
    node.fail("expected an affine matrix (last row 0, 0, 0, 1)");
  return m;
}

// A camera matrix must be a rotation and a translation: any scale or shear would silently change
// the field of view or skew the image.
glm::dmat4 read_rigid_matrix(const DocumentNode& node) {
  const glm::dmat4 m = read_matrix(node);
  const glm::dmat3 r(m);
  const glm::dmat3 should_be_identity = glm::transpose(r) * r;
  double worst = std::abs(glm::determinant(r) - 1.0);
  for (int c = 0; c < 3; ++c)
    for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(should_be_identity[c][k] - (c == k ? 1.0 : 0.0)));
  if (worst > 1e-4) node.fail("expected a rotation and a translation (orthonormal, right-handed upper 3x3)");
  return m;
}

std::string read_existing_file(const DocumentNode& node, const fs::path& folder) {
  const std::string text = node.text();
  if (text.empty()) node.fail("expected a file path");
  const fs::path path = fs::path(text).is_absolute() ? fs::path(text) : (folder / text).lexically_normal();
  std::error_code ec;
  if (!fs::exists(path, ec)) node.fail("file not found: " + path.string());
  if (fs::is_directory(path, ec)) node.fail("is a folder, expected a file: " + path.string());
  return path.string();
}

// ---- camera ---------------------------------------------------------------------------------

GridPlacement read_grid(const DocumentNode& node) {
  node.expect_keys({"cell", "n_phi", "n_theta", "radius", "phi_range_deg", "theta_range_deg", "center"});
  GridPlacement grid;
  matgeom::CameraGridSpec& spec = grid.spec;
  if (auto n = node.find("n_phi")) spec.n_phi = n->integer_at_least(1);
  if (auto n = node.find("n_theta")) spec.n_theta = n->integer_at_least(1);
  if (auto r = node.find("radius")) spec.radius = r->positive();
  if (auto range = node.find("phi_range_deg")) {
    const auto [lo, hi] = read_range(*range, [](const DocumentNode& n) {
      return n.number_in(0.0, 180.0);
    });
    spec.phi_min = glm::radians(lo);
    spec.phi_max = glm::radians(hi);
  }
  if (auto range = node.find("theta_range_deg")) {
    const auto [lo, hi] = read_range(*range, [](const DocumentNode& n) { return n.number(); });
    spec.theta_min = glm::radians(lo);
    spec.theta_max = glm::radians(hi);
  }
  if (auto center = node.find("center")) {
    if (center->is_text()) {
      if (center->text() != "centroid") center->fail("expected \"centroid\" or [x, y, z]");
    } else {
      grid.center_on_centroid = false;
      spec.center = read_vec3(*center);
    }
  }
  const DocumentNode cell = node.required("cell");
  const std::vector<DocumentNode> ij = cell.items(2, "[i, j]");
  grid.i = ij[0].integer_in(0, spec.n_phi - 1);
  grid.j = ij[1].integer_in(0, spec.n_theta - 1);
  return grid;
}

LookAtPlacement read_look_at(const DocumentNode& node) {
  LookAtPlacement look;
  look.position = read_vec3(node.required("position"));
  look.target = read_vec3(node.required("look_at"));
  if (look.target == look.position) node.required("look_at").fail("expected a point different from \"position\"");
  if (auto up = node.find("up")) look.up = read_direction(*up);
  return look;
}

CameraDescription read_camera(const DocumentNode& node) {
  if (!node.is_mapping()) node.fail_expected("a mapping of keys");
  const int kinds = int{node.has("position")} + int{node.has("grid")} + int{node.has("matrix")};
  if (kinds != 1) node.fail("expected exactly one of \"position\" (with \"look_at\"), \"grid\" or \"matrix\"");
  CameraDescription camera;
  if (node.has("position")) {
    node.expect_keys({"position", "look_at", "up", "fov_deg", "width", "height"});
    camera.placement = read_look_at(node);
  } else if (node.has("grid")) {
    node.expect_keys({"grid", "fov_deg", "width", "height"});
    camera.placement = read_grid(node.required("grid"));
  } else {
    node.expect_keys({"matrix", "fov_deg", "width", "height"});
    camera.placement = MatrixPlacement{read_rigid_matrix(node.required("matrix"))};
  }
  if (auto fov = node.find("fov_deg"))
    camera.vertical_fov = glm::radians(
        fov->number_where([](double v) { return v > 0.0 && v < 180.0; }, "a number greater than 0 and less than 180"));
  if (auto w = node.find("width")) camera.width = w->integer_in(1, kMaxImageSide);
  if (auto h = node.find("height")) camera.height = h->integer_in(1, kMaxImageSide);
  return camera;
}

// ---- lights ---------------------------------------------------------------------------------

LightsDescription read_lights(const DocumentNode& node) {
  if (!node.is_list()) {
    if (!node.is_mapping()) node.fail_expected("a list of lights or {\"rig\": {...}}");
    node.expect_keys({"rig"});
    const DocumentNode rig_node = node.required("rig");
    rig_node.expect_keys({"target_illuminance_lux"});
    LightRigDescription rig;
    if (auto lux = rig_node.find("target_illuminance_lux")) rig.target_illuminance_lux = lux->positive();
    return rig;
  }
  std::vector<Lamp> lights;
  for (const DocumentNode& light : node.items("a list of lights")) {
    lights.push_back(read_lamp(light));
    // Values each valid alone may still not render: a lamp 1e-300 m wide, a power of 1e308 W.
    if (const std::optional<std::string> problem = lamp_problem(lights.back())) light.fail(*problem);
  }
  return lights;
}

// {"sky": {"sun_elevation_deg": 30, ...}, "strength": s}: the keys of sky_settings() and sun_disc,
// each checked against its range where it is read.
SkyDescription read_sky(const DocumentNode& node) {
  node.expect_keys({"sky", "strength"});
  const DocumentNode settings = node.required("sky");
  if (!settings.is_mapping()) settings.fail_expected("a mapping of the sky's settings");
  std::vector<const char*> keys = {"sun_disc"};
  for (const SkySetting& setting : sky_settings()) keys.push_back(setting.key);
  settings.expect_keys(keys);
  SkyDescription description;
  description.origin = origin_of(node);
  NishitaSky& sky = description.sky;
  for (const SkySetting& setting : sky_settings())
    if (auto value = settings.find(setting.key)) {
      sky.*setting.field = value->number() * setting.unit;
      if (const std::optional<std::string> problem = sky_problem(sky)) value->fail(*problem);
    }
  if (auto disc = settings.find("sun_disc")) sky.sun_disc = disc->boolean();
  if (auto strength = node.find("strength")) sky.strength = strength->non_negative();
  return description;
}

// [r, g, b], {"environment": path, "strength", "rotation_z_deg", "color_space"}, or a sky.
BackgroundDescription read_background(const DocumentNode& node, const fs::path& folder) {
  if (!node.is_mapping()) return glm::vec3(read_color(node));
  if (node.has("sky")) return read_sky(node);
  node.expect_keys({"environment", "strength", "rotation_z_deg", "color_space"});
  EnvironmentDescription environment;
  const DocumentNode file = node.required("environment");
  if (file.is_text() && is_builtin_environment(file.text())) {
    try {
      environment.path = builtin_environment_path(file.text());
    } catch (const matbase::InputError& e) {
      file.fail(e.what());
    }
  } else {
    environment.path = read_existing_file(file, folder);
  }
  environment.origin = origin_of(node);
  if (auto strength = node.find("strength"))
    environment.strength = strength->non_negative();
  if (auto rotation = node.find("rotation_z_deg")) environment.rotation_z = glm::radians(rotation->number());
  if (auto space = node.find("color_space"))
    environment.color_space = space->choice({"sRGB", "non-color"}) == 0 ? ColorSpace::SRGB : ColorSpace::NonColor;
  return environment;
}

// ---- materials ------------------------------------------------------------------------------

// {"texture": path, ...}: the keys every texture reference shares.
// A texture file, or a UDIM set's pattern (name.<UDIM>.png), whose folder must exist; its tiles
// are found when it is loaded.
std::string read_texture_path(const DocumentNode& node, const fs::path& folder) {
  const std::string text = node.text();
  if (text.find("<UDIM>") == std::string::npos) return read_existing_file(node, folder);
  const fs::path path = fs::path(text).is_absolute() ? fs::path(text) : (folder / text).lexically_normal();
  std::error_code ec;
  if (!fs::is_directory(path.parent_path().empty() ? fs::path(".") : path.parent_path(), ec))
    node.fail("folder not found: " + path.parent_path().string());
  return path.string();
}

TextureFile read_texture_file(const DocumentNode& node, const fs::path& folder, ColorSpace default_space) {
  TextureFile file;
  file.path = read_texture_path(node.required("texture"), folder);
  file.origin = origin_of(node);
  file.color_space = default_space;
  if (auto space = node.find("color_space"))
    file.color_space = space->choice({"sRGB", "non-color"}) == 0 ? ColorSpace::SRGB
                                                                  : ColorSpace::NonColor;
  if (auto wrap = node.find("wrap"))
    file.wrap = wrap->choice({"repeat", "clamp"}) == 0 ? TextureWrap::Repeat : TextureWrap::Clamp;
  return file;
}

// {"offset": [u, v], "rotation_deg": r, "scale": [u, v]}: glTF's KHR_texture_transform (in
// glTF's UVs, v down; matmaterial/texture_transform.h), each key optional.
matmaterial::UvAffine read_texture_transform(const DocumentNode& node) {
  node.expect_keys({"offset", "rotation_deg", "scale"});
  constexpr double kLargest = 1e6;  // a texture repeated a million times is already noise
  const auto bounded = [](const DocumentNode& n) {
    return n.number_in(-kLargest, kLargest);
  };
  const auto pair = [&](const char* key, glm::dvec2 fallback) {
    const auto n = node.find(key);
    if (!n) return fallback;
    const std::vector<DocumentNode> uv = n->items(2, "[u, v]");
    return glm::dvec2(bounded(uv[0]), bounded(uv[1]));
  };
  matmaterial::TextureTransform transform;
  transform.offset = pair("offset", transform.offset);
  transform.scale = pair("scale", transform.scale);
  if (auto n = node.find("rotation_deg")) transform.rotation = glm::radians(bounded(*n));
  return matmaterial::uv_affine(transform);
}

// A value of `info` within its range: [r, g, b] for a colour, a number for a scalar. `or_else`
// completes the message when something else would also do.
glm::vec3 read_parameter_constant(const DocumentNode& node, const matmaterial::MaterialParameterInfo& info,
                                  const std::string& or_else = "") {
  const double low = info.min, high = info.max;
  if (info.kind == matmaterial::ParameterKind::Scalar)
    return glm::vec3(static_cast<float>(node.number_where([&](double v) { return v >= low && v <= high; },
                                                          matbase::number_expectation(low, high, false) + or_else)));
  const std::vector<DocumentNode> rgb =
      node.items(3, fmt::format("[r, g, b] with components from {:g} to {:g}", low, high) + or_else);
  return glm::vec3(glm::dvec3(rgb[0].number_in(low, high), rgb[1].number_in(low, high), rgb[2].number_in(low, high)));
}

// A constant, or (where the table allows it) a texture times an optional factor: a colour takes
// the texture's RGB, a scalar one channel of it (R unless "channel" says otherwise).
void read_parameter(const DocumentNode& node, const matmaterial::MaterialParameterInfo& info, const fs::path& folder,
                    ParameterValue& value, std::optional<TextureFile>& texture) {
  const bool color = info.kind == matmaterial::ParameterKind::Color;
  if (!node.is_mapping() || !info.texturable) {
    value.value = read_parameter_constant(node, info, info.texturable ? " or {\"texture\": ...}" : "");
    return;
  }
  if (color) node.expect_keys({"texture", "factor", "color_space", "wrap", "transform"});
  else node.expect_keys({"texture", "channel", "factor", "color_space", "wrap", "transform"});
  texture = read_texture_file(node, folder, info.texture_space);
  if (auto n = node.find("transform")) value.uv_transform = read_texture_transform(*n);
  value.value = node.has("factor") ? read_parameter_constant(node.required("factor"), info) : glm::vec3(1.0f);
  value.channel = node.has("channel") ? static_cast<int>(node.required("channel").choice({"R", "G", "B", "A"})) : 0;
}

// A material class's name ("wood", matmaterial/material_classes.h) or any integer a 16-bit label
// PNG holds.
int read_label_id(const DocumentNode& node) {
  if (!node.is_text()) return node.integer_in(0, 65535);
  const std::string name = node.text();
  if (const std::optional<matmaterial::MaterialClass> c = matmaterial::material_class_named(name)) return matmaterial::label_id(*c);
  std::vector<std::string> names;
  for (const matmaterial::MaterialClassInfo& info : matmaterial::kMaterialClasses) names.push_back(info.name);
  node.fail("unknown material class \"" + name + "\" (known: " + quoted_list(names) + ")");
}

// {"matsynth": folder}: a material folder, optionally with its label.
MaterialDescription read_folder_material(const DocumentNode& node, const std::string& name, const fs::path& folder) {
  node.expect_keys({"matsynth", "label_id"});
  MaterialDescription material;
  material.constants.name = name;
  const DocumentNode path_node = node.required("matsynth");
  const fs::path path = folder / path_node.text();
  std::error_code error;
  if (!fs::is_directory(path, error))
    path_node.fail("expected a material folder (matgeom's MatSynth layout), found no folder at " + path.string());
  material.folder = MaterialFolderFile{path.string(), origin_of(path_node)};
  if (auto n = node.find("label_id")) material.label_id = read_label_id(*n);
  return material;
}

// {"class": "wood", "style": "wicker", "seed": 3, "resolution": 1024}: a material of the
// procedural library, optionally with its label.
MaterialDescription read_library_material(const DocumentNode& node, const std::string& name) {
  node.expect_keys({"class", "style", "seed", "resolution", "label_id"});
  MaterialDescription material;
  material.constants.name = name;
  LibraryMaterialRequest request;
  const DocumentNode class_node = node.required("class");
  const std::optional<matmaterial::MaterialClass> material_class = matmaterial::material_class_named(class_node.text());
  if (!material_class || *material_class == matmaterial::MaterialClass::Background) {
    std::vector<std::string> names;
    for (const matmaterial::MaterialClassInfo& info : matmaterial::kMaterialClasses)
      if (info.id != matmaterial::MaterialClass::Background) names.push_back(info.name);
    class_node.fail("unknown material class \"" + class_node.text() + "\" (known: " + quoted_list(names) + ")");
  }
  request.spec.material_class = *material_class;
  if (auto n = node.find("seed")) request.spec.seed = n->uint32();
  if (auto n = node.find("style")) {
    request.spec.style = n->text();
    try {
      matmaterial::resolved_style(request.spec);
    } catch (const std::invalid_argument& e) {
      n->fail(e.what());
    }
  }
  if (auto n = node.find("resolution"))
    request.resolution = n->integer_in(matmaterial::kMinLibraryResolution, matmaterial::kMaxLibraryResolution);
  request.origin = origin_of(node);
  material.library = request;
  if (auto n = node.find("label_id")) material.label_id = read_label_id(*n);
  return material;
}

MaterialDescription read_material(const DocumentNode& node, const std::string& name, const fs::path& folder) {
  if (node.has("matsynth")) return read_folder_material(node, name, folder);
  if (node.has("class")) return read_library_material(node, name);
  std::vector<const char*> keys = {"normal_map", "label_id", "diffuse_model", "distribution"};
  for (const matmaterial::MaterialParameterInfo& info : matmaterial::kMaterialParameters) keys.push_back(info.name);
  node.expect_keys(keys);
  MaterialDescription material;
  Material& m = material.constants;
  m.name = name;
  for (const matmaterial::MaterialParameterInfo& info : matmaterial::kMaterialParameters)
    if (auto n = node.find(info.name))
      read_parameter(*n, info, folder, m[info.id], material.textures[static_cast<size_t>(info.id)]);
  if (auto n = node.find("normal_map")) {
    n->expect_keys({"texture", "strength", "wrap", "transform"});
    material.normal_map = read_texture_file(*n, folder, ColorSpace::NonColor);
    if (auto t = n->find("transform")) m.normal_map_uv_transform = read_texture_transform(*t);
    if (auto strength = n->find("strength")) m.normal_strength = static_cast<float>(strength->non_negative());
  }
  if (auto n = node.find("label_id")) m.label_id = read_label_id(*n);
  if (auto n = node.find("distribution"))
    m.distribution = n->choice({"ggx", "multiscatter_ggx"}) == 0 ? SpecularDistribution::GGX
                                                                 : SpecularDistribution::MultiscatterGGX;
  if (auto n = node.find("diffuse_model"))
    m.diffuse_model = n->choice({"principled", "lambert"}) == 0 ? DiffuseModel::Principled
                                                                : DiffuseModel::Lambert;
  return material;
}

std::map<std::string, MaterialDescription> read_materials(const DocumentNode& node, const fs::path& folder) {
  std::map<std::string, MaterialDescription> materials;
  for (const auto& [name, material] : node.members()) materials[name] = read_material(material, name, folder);
  return materials;
}

// ---- objects --------------------------------------------------------------------------------

// Blender's XYZ Euler order: rotate about X first, then Y, then Z (R = Rz Ry Rx).
glm::dmat4 euler_xyz_degrees(const glm::dvec3& degrees) {
  const glm::dmat4 identity(1.0);
  return glm::rotate(identity, glm::radians(degrees.z), glm::dvec3(0, 0, 1)) *
         glm::rotate(identity, glm::radians(degrees.y), glm::dvec3(0, 1, 0)) *
         glm::rotate(identity, glm::radians(degrees.x), glm::dvec3(1, 0, 0));
}

// {"matrix": ...} or Blender's translate * rotate * scale.
glm::dmat4 read_transform(const DocumentNode& node) {
  if (node.has("matrix")) {
    node.expect_keys({"matrix"});
    const glm::dmat4 m = read_matrix(node.required("matrix"));
    if (std::abs(glm::determinant(glm::dmat3(m))) < 1e-12)
      node.required("matrix").fail("expected an invertible matrix");
    return m;
  }
  node.expect_keys({"translate", "rotate_deg", "scale"});
  glm::dvec3 scale(1.0);
  if (auto s = node.find("scale")) {
    if (s->is_number()) {
      scale = glm::dvec3(s->positive());
    } else {
      const std::vector<DocumentNode> xyz = s->items(3, "a positive number or [x, y, z]");
      scale = {xyz[0].positive(), xyz[1].positive(), xyz[2].positive()};
    }
  }
  const glm::dvec3 translate = node.has("translate") ? read_vec3(node.required("translate")) : glm::dvec3(0.0);
  const glm::dvec3 rotate = node.has("rotate_deg") ? read_vec3(node.required("rotate_deg")) : glm::dvec3(0.0);
  return glm::translate(glm::dmat4(1.0), translate) * euler_xyz_degrees(rotate) *
         glm::scale(glm::dmat4(1.0), scale);
}

std::string read_material_name(const DocumentNode& node, const std::map<std::string, MaterialDescription>& materials) {
  const std::string name = node.text();
  if (materials.count(name) == 0) {
    std::vector<std::string> defined;
    for (const auto& entry : materials) defined.push_back(entry.first);
    node.fail(fmt::format("unknown material \"{}\" ({})", name,
                          defined.empty() ? "the file defines no \"materials\""
                                          : "defined: " + quoted_list(defined)));
  }
  return name;
}

// An object's "material": a name from "materials", or a material given in place (a folder,
// {"matsynth": folder}, or the library's, {"class": ...}), added to the scene's materials under
// its JSON pointer.
std::string read_object_material(const DocumentNode& node, const fs::path& folder,
                                 std::map<std::string, MaterialDescription>& materials) {
  if (!node.is_mapping()) return read_material_name(node, materials);
  if (!node.has("matsynth") && !node.has("class"))
    node.fail("expected a material name, {\"matsynth\": folder} or {\"class\": CLASS, \"seed\": SEED}");
  const std::string name = *origin_of(node).pointer;
  materials[name] = node.has("matsynth") ? read_folder_material(node, name, folder) : read_library_material(node, name);
  return name;
}

}  // namespace

double read_auto_smooth_deg(const DocumentNode& node) {
  return node.number_in(0.0, matgeom::kMaxAutoSmoothDeg, /*low_open=*/true);
}

namespace {

// A mesh object's source: the file "mesh" names, or, where "mesh" is {"given": K}, the K-th
// object the program gave the reader.
decltype(ObjectDescription::source) read_mesh_source(const DocumentNode& node, const fs::path& folder,
                                                     const std::vector<GivenObject>& given) {
  const DocumentNode mesh = node.required("mesh");
  if (mesh.is_mapping()) {
    mesh.expect_keys({"given"});
    if (given.empty()) mesh.fail("an object given in memory, but none was given: in a scene file, \"mesh\" is a file's path");
    if (auto angle = node.find("auto_smooth_deg"))
      angle->fail("only a mesh file's faces can be smoothed (an object given in memory has its own normals)");
    for (const char* key : {"only_parts", "except_parts"})
      if (auto parts = node.find(key)) parts->fail("only a mesh file's parts can be chosen");
    return given[static_cast<size_t>(mesh.required("given").whole_number(0, static_cast<int64_t>(given.size()) - 1))];
  }
  const std::string path = read_existing_file(mesh, folder);
  const std::vector<std::string>& extensions = matgeom::object_file_extensions();
  if (std::find(extensions.begin(), extensions.end(), matbase::lowercase_extension(path)) == extensions.end())
    mesh.fail("expected a .glb, .gltf, .ply or .obj file");
  MeshFile file{path, {}, {}, {}};
  if (auto angle = node.find("auto_smooth_deg")) file.read_options.auto_smooth_deg = read_auto_smooth_deg(*angle);
  if (node.has("only_parts") && node.has("except_parts")) node.fail("give either \"only_parts\" or \"except_parts\", not both");
  for (auto [key, names] : {std::pair{"only_parts", &file.only_parts}, std::pair{"except_parts", &file.except_parts}}) {
    const std::optional<DocumentNode> parts = node.find(key);
    if (!parts) continue;
    for (const DocumentNode& part : parts->items("a list of part names")) names->push_back(part.text());
    if (names->empty()) parts->fail("expected a list of one or more part names");
  }
  return file;
}

// A room's measurements (matgeom/room.h): "floor_center", "half_width", "height", "walls",
// "ceiling", "cove_radius", "metres_per_uv", "turn_z_deg".
RoomObject read_room(const DocumentNode& node) {
  node.expect_keys({"floor_center", "half_width", "height", "walls", "ceiling", "cove_radius", "metres_per_uv", "turn_z_deg"});
  matgeom::RoomSpec spec;
  spec.floor_center = read_vec3(node.required("floor_center"));
  spec.half_width = node.required("half_width").positive();
  if (auto height = node.find("height")) spec.height = height->positive();
  if (auto walls = node.find("walls"))
    spec.walls = std::array{matgeom::RoomWalls::None, matgeom::RoomWalls::Box,
                            matgeom::RoomWalls::Cyclorama}[walls->choice({"none", "box", "cyclorama"})];
  if (auto ceiling = node.find("ceiling")) spec.ceiling = ceiling->boolean();
  if (auto radius = node.find("cove_radius")) spec.cove_radius = radius->positive();
  if (auto length = node.find("metres_per_uv")) spec.metres_per_uv = length->positive();
  if (auto turn = node.find("turn_z_deg")) spec.turn_z = glm::radians(turn->number_in(-360.0, 360.0));
  if (const std::optional<std::string> problem = matgeom::room_spec_problem(spec)) node.fail(*problem);
  return {spec};
}

ObjectDescription read_object(const DocumentNode& node, const fs::path& folder,
                              std::map<std::string, MaterialDescription>& materials, const std::vector<GivenObject>& given) {
  if (!node.is_mapping()) node.fail_expected("a mapping of keys");
  if (node.has("mesh") + node.has("builtin") + node.has("room") != 1)
    node.fail("expected exactly one of \"mesh\", \"builtin\" or \"room\"");
  ObjectDescription object;
  object.origin = origin_of(node);
  if (node.has("mesh")) {
    node.expect_keys({"mesh", "auto_smooth_deg", "only_parts", "except_parts", "uv_pass", "uv_scale", "transform",
                      "material", "materials", "shadow_terminator_geometry_offset", "surroundings"});
    object.source = read_mesh_source(node, folder, given);
  } else if (node.has("room")) {
    node.expect_keys({"room", "material", "materials", "surroundings"});
    object.source = read_room(node.required("room"));
    object.surroundings = true;
  } else {
    node.expect_keys({"builtin", "seed", "uv_pass", "uv_scale", "transform", "material", "materials",
                      "shadow_terminator_geometry_offset", "surroundings"});
    BuiltinObject builtin;
    const std::vector<std::string> names = matgeom::builtin_object_names();
    builtin.name = names[node.required("builtin").choice(names)];
    if (auto seed = node.find("seed")) builtin.seed = seed->uint32();
    object.source = builtin;
  }
  if (auto mode = node.find("uv_pass"))
    object.uv_pass = std::array{UvPassMode::Never, UvPassMode::WhenMissing,
                                UvPassMode::Always}[mode->choice({"never", "when_missing", "always"})];
  if (auto scale = node.find("uv_scale")) object.uv_scale = scale->number_in(kMinUvScale, kMaxUvScale);
  if (auto transform = node.find("transform")) object.object_to_world = read_transform(*transform);
  if (auto offset = node.find("shadow_terminator_geometry_offset"))
    object.shadow_terminator_geometry_offset = static_cast<float>(
        offset->unit_interval());
  if (node.has("material") && node.has("materials")) node.fail("give either \"material\" or \"materials\", not both");
  if (auto material = node.find("material")) object.material = read_object_material(*material, folder, materials);
  if (auto parts = node.find("materials"))
    for (const auto& [part, name] : parts->members()) object.part_materials[part] = read_material_name(name, materials);
  if (auto surroundings = node.find("surroundings")) object.surroundings = surroundings->boolean();
  return object;
}

std::vector<ObjectDescription> read_objects(const DocumentNode& node, const fs::path& folder,
                                            std::map<std::string, MaterialDescription>& materials,
                                            const std::vector<GivenObject>& given) {
  const std::vector<DocumentNode> items = node.items("a non-empty list of objects");
  if (items.empty()) node.fail_expected("a non-empty list of objects");
  std::vector<ObjectDescription> objects;
  for (const DocumentNode& item : items) objects.push_back(read_object(item, folder, materials, given));
  return objects;
}

// ---- render settings ------------------------------------------------------------------------

// The declared scene settings (matrender/render_setting_declarations.h) by their own names, and
// the display exposure, which is the scene's and no render setting.
void read_render(const DocumentNode& node, SceneDescription& scene) {
  std::vector<const char*> keys;
  for (const RenderSettingDeclaration& setting : render_setting_declarations())
    if (setting.scope == SettingScope::Scene) keys.push_back(setting.name.data());
  keys.push_back("exposure");
  node.expect_keys(keys);
  for (const RenderSettingDeclaration& setting : render_setting_declarations())
    if (setting.scope == SettingScope::Scene)
      if (auto value = node.find(std::string(setting.name))) read_render_setting(*value, setting, scene.settings);
  if (const std::optional<SettingConflict> conflict = settings_conflict(scene.settings))
    node.fail(conflict_refusal(*conflict, conflict->first, conflict->second));
  if (auto n = node.find("exposure"))
    scene.exposure_stops = n->number_where([](double v) { return std::abs(v) <= matbase::kMaxExposureStops; },
                                           fmt::format("a number of stops from {} to {}", -matbase::kMaxExposureStops, matbase::kMaxExposureStops));
}

}  // namespace

namespace {

SceneDescription read_scene(const matbase::DocumentValue& document, const std::string& source_name, const fs::path& folder,
                            const std::vector<GivenObject>& given) {
  const matbase::DocumentSource source(source_name, matbase::PathStyle::JsonPointer);
  const DocumentNode root(document, source);
  root.expect_keys({"description", "camera", "lights", "background", "materials", "objects", "render"});
  SceneDescription scene;
  if (auto description = root.find("description")) description->text();  // free text; only its type matters
  scene.camera = read_camera(root.required("camera"));
  scene.lights = read_lights(root.required("lights"));
  if (auto background = root.find("background")) scene.background = read_background(*background, folder);
  if (auto materials = root.find("materials")) scene.materials = read_materials(*materials, folder);
  scene.objects = read_objects(root.required("objects"), folder, scene.materials, given);
  if (auto render = root.find("render")) read_render(*render, scene);
  return scene;
}

}  // namespace

SceneDescription read_scene_file(const std::string& path) {
  return read_scene(matbase::read_json_document(path), path, fs::path(path).parent_path(), {});
}

SceneDescription read_scene_text(const std::string& json, const std::string& source, const std::string& folder,
                                 const std::vector<GivenObject>& given) {
  std::istringstream text(json);
  return read_scene(matbase::parse_json_document(text, source), source, folder, given);
}

CameraDescription read_camera_text(const std::string& json, const std::string& source) {
  std::istringstream text(json);
  const matbase::DocumentValue document = matbase::parse_json_document(text, source);
  return read_camera(DocumentNode(document, matbase::DocumentSource(source, matbase::PathStyle::JsonPointer)));
}

SceneLighting read_lighting_text(const std::string& json, const std::string& source, const std::string& folder) {
  std::istringstream text(json);
  const matbase::DocumentValue document = matbase::parse_json_document(text, source);
  const matbase::DocumentSource where(source, matbase::PathStyle::JsonPointer);
  const DocumentNode root(document, where);
  root.expect_keys({"lights", "background"});
  SceneLighting lighting;
  lighting.lights = read_lights(root.required("lights"));
  if (auto background = root.find("background")) lighting.background = read_background(*background, folder);
  return lighting;
}

}  // namespace matrender
