#include "shaders_ref/cycles_reference.h"

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <variant>

#include <OpenImageIO/imageio.h>
#include <nlohmann/json.hpp>

#ifndef MATPREDICT_CYCLES_SCRIPT
#error "MATPREDICT_CYCLES_SCRIPT must name shaders_ref/cycles_render.py"
#endif
#ifndef MATPREDICT_GLTF_IMPORT_SCRIPT
#error "MATPREDICT_GLTF_IMPORT_SCRIPT must name shaders_ref/blender_gltf_import.py"
#endif
#ifndef MATPREDICT_UDIM_PROBE_SCRIPT
#error "MATPREDICT_UDIM_PROBE_SCRIPT must name shaders_ref/blender_udim_probe.py"
#endif

namespace shaders_ref {
namespace {

using nlohmann::json;

json column_major(const glm::dmat4& m) {
  json values = json::array();
  for (int column = 0; column < 4; ++column)
    for (int row = 0; row < 4; ++row) values.push_back(m[column][row]);
  return values;
}

// Every row of the material table as Blender node name -> input name -> value (a colour as RGB),
// so that the script sets exactly what libmatrender shades with.
json node_inputs(const matrender::Material& m) {
  json nodes = json::object();
  for (const matmaterial::BlenderNode node : {matmaterial::BlenderNode::PrincipledBsdf, matmaterial::BlenderNode::VelvetBsdf})
    nodes[matmaterial::blender_node_name(node)] = json::object();
  for (const matmaterial::MaterialParameterInfo& info : matmaterial::kMaterialParameters) {
    const glm::vec3 value = m.parameters[static_cast<size_t>(info.id)].value;
    nodes[matmaterial::blender_node_name(info.node)][info.blender_input] =
        info.kind == matmaterial::ParameterKind::Color ? json{value.r, value.g, value.b} : json(value.x);
  }
  return nodes;
}

json rgb(const glm::dvec3& c) { return {c.r, c.g, c.b}; }
json xyz(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

json describe_lamp(const matrender::Lamp& light) {
  if (const auto* rect = std::get_if<matrender::RectLamp>(&light))
    return {{"type", "area"},
            {"light_to_world", column_major(rect->light_to_world)},
            {"size_x", rect->size_x},
            {"size_y", rect->size_y},
            {"power", rect->power},
            {"color", rgb(rect->color)}};
  if (const auto* point = std::get_if<matrender::PointLamp>(&light))
    return {{"type", "point"},
            {"position", xyz(point->position)},
            {"radius", point->radius},
            {"power", point->power},
            {"color", rgb(point->color)}};
  if (const auto* spot = std::get_if<matrender::SpotLamp>(&light))
    return {{"type", "spot"},          {"position", xyz(spot->position)}, {"direction", xyz(spot->direction)},
            {"radius", spot->radius},  {"spot_angle", spot->spot_angle},  {"blend", spot->blend},
            {"power", spot->power},    {"color", rgb(spot->color)}};
  const auto& sun = std::get<matrender::SunLamp>(light);
  return {{"type", "sun"},
          {"direction", xyz(sun.direction)},
          {"angle", sun.angle},
          {"strength", sun.strength},
          {"color", rgb(sun.color)}};
}

// The mesh in its one material, as cycles_render.py rebuilds them.
// The material, with at most a base colour image file (on the mesh's UVs, when `with_uvs`).
// The Sky Texture node's settings by their Blender names (cycles_render.py, blender_sky_probe.py).
json sky_json(const matrender::NishitaSky& sky) {
  return {{"sun_elevation", sky.sun_elevation}, {"sun_rotation", sky.sun_rotation}, {"sun_size", sky.sun_size},
          {"sun_intensity", sky.sun_intensity}, {"sun_disc", sky.sun_disc},        {"altitude", sky.altitude},
          {"air_density", sky.air_density},     {"dust_density", sky.dust_density}, {"ozone_density", sky.ozone_density},
          {"strength", sky.strength}};
}

json describe_material(const CyclesScene& scene, bool with_uvs) {
  const matrender::Material& m = scene.material;
  // One texture is passed: a base colour image file under a white factor, on the mesh's UVs.
  const matrender::ParameterValue& base = m[matmaterial::MaterialParameter::BaseColor];
  json base_color_image = nullptr;
  if (base.texture) {
    if (!with_uvs || base.value != glm::vec3(1.0f) || !(base.uv_transform == matmaterial::UvAffine{}) ||
        !std::filesystem::exists(base.texture->name()) || scene.mesh.uvs.size() != scene.mesh.positions.size())
      throw std::invalid_argument("render_with_cycles: a base colour texture must be an image file under a white "
                                  "factor, untransformed, on a mesh with one UV per vertex");
    base_color_image = base.texture->name();
  }
  matrender::Material untextured = m;
  untextured[matmaterial::MaterialParameter::BaseColor].texture = nullptr;
  if (untextured.textured() || m.normal_map)
    throw std::invalid_argument("render_with_cycles: textures other than the base colour are not passed to Blender");
  return {{"material", node_inputs(m)},
          {"base_color_image", base_color_image},
          {"distribution", m.distribution == matrender::SpecularDistribution::MultiscatterGGX ? "MULTI_GGX" : "GGX"}};
}

json describe_mesh_object(const CyclesScene& scene) {
  json positions = json::array(), normals = json::array(), triangles = json::array();
  for (const glm::vec3& p : scene.mesh.positions) positions.push_back({p.x, p.y, p.z});
  for (const glm::vec3& n : scene.mesh.normals) normals.push_back({n.x, n.y, n.z});
  for (const glm::uvec3& t : scene.mesh.triangles) triangles.push_back({t.x, t.y, t.z});
  json uvs = json::array();
  if (scene.material[matmaterial::MaterialParameter::BaseColor].texture)
    for (const glm::vec2& uv : scene.mesh.uvs) uvs.push_back({uv.x, uv.y});
  if (scene.mesh.normals.size() != scene.mesh.positions.size())
    throw std::invalid_argument("render_with_cycles: the mesh needs one normal per vertex");
  json description = describe_material(scene, true);
  description["mesh"] = {{"positions", positions},
                         {"normals", normals},
                         {"triangles", triangles},
                         {"uvs", uvs},
                         {"shadow_terminator_geometry_offset", scene.shadow_terminator_geometry_offset}};
  return description;
}

json describe(const CyclesScene& scene) {
  json description;
  if (!scene.gltf_path.empty()) {
    description = {{"gltf", scene.gltf_path}};
  } else if (!scene.mesh_file_path.empty()) {
    description = describe_material(scene, false);
    description["mesh_file"] = {{"path", scene.mesh_file_path},
                                {"shadow_terminator_geometry_offset", scene.shadow_terminator_geometry_offset}};
  } else {
    description = describe_mesh_object(scene);
  }
  json lamps = json::array();
  for (const matrender::Lamp& lamp : scene.lamps) {
    json described = describe_lamp(lamp);
    if (scene.lamp_blackbody_kelvin) {
      described["color"] = {1.0, 1.0, 1.0};
      described["blackbody_kelvin"] = *scene.lamp_blackbody_kelvin;
    }
    lamps.push_back(described);
  }
  description["lamps"] = lamps;
  const matrender::Camera& c = scene.camera;
  description["camera"] = {{"camera_to_world", column_major(c.camera_to_world)},
                           {"vertical_fov", c.vertical_fov},
                           {"width", c.width},
                           {"height", c.height}};
  description["background"] = {scene.background.r, scene.background.g, scene.background.b};
  description["sky"] = nullptr;
  if (scene.sky) description["sky"] = sky_json(*scene.sky);
  description["environment"] = nullptr;
  if (scene.environment)
    description["environment"] = {{"path", scene.environment->exr_path},
                                  {"strength", scene.environment->strength},
                                  {"rotation_z", scene.environment->rotation_z}};
  const CyclesBounces& b = scene.bounces;
  description["bounces"] = {
      {"total", b.total}, {"diffuse", b.diffuse}, {"glossy", b.glossy}, {"transmission", b.transmission}};
  description["settings"] = scene.settings == CyclesSettings::Parity ? "parity" : "blender_defaults";
  return description;
}

std::string quoted(const std::string& s) { return "'" + s + "'"; }

// Runs `script` in headless Blender with `arguments` after "--", its output into `log_path`;
// throws "<failure>; see <log_path>" when Blender or the script fails.
void run_blender_script(const std::string& blender, const std::string& script, const std::vector<std::string>& arguments,
                        const std::string& log_path, const std::string& failure) {
  std::string command = quoted(blender) + " -b --factory-startup -noaudio --python-exit-code 1 -P " + quoted(script) + " --";
  for (const std::string& argument : arguments) command += " " + quoted(argument);
  command += " > " + quoted(log_path) + " 2>&1";
  if (std::system(command.c_str()) != 0) throw std::runtime_error(failure + "; see " + log_path);
}

}  // namespace

bool cycles_available(const std::string& blender) {
  const std::string command = quoted(blender) + " --version 2>/dev/null";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  if (!pipe) return false;
  std::array<char, 256> line{};
  return fgets(line.data(), line.size(), pipe.get()) && std::string(line.data()).rfind("Blender 3.4", 0) == 0;
}

void render_with_cycles(const CyclesScene& scene, std::vector<CyclesRender>& renders, int threads,
                        const std::string& folder, const std::string& blender) {
  std::filesystem::create_directories(folder);
  json description = describe(scene);
  description["threads"] = threads;
  description["timings_path"] = folder + "/cycles_timings.json";
  json jobs = json::array();
  for (CyclesRender& render : renders) {
    const json threshold = render.noise_threshold ? json(*render.noise_threshold) : json(nullptr);
    render.exr_path = folder + "/cycles_" + std::to_string(render.samples_per_pixel) + "_" +
                      std::to_string(render.seed) + (render.noise_threshold ? "_threshold_" + threshold.dump() : "") +
                      ".exr";
    jobs.push_back({{"spp", render.samples_per_pixel},
                    {"seed", render.seed},
                    {"noise_threshold", threshold},
                    {"path", render.exr_path}});
  }
  description["renders"] = jobs;
  const std::string scene_path = folder + "/scene.json", log_path = folder + "/blender.log";
  std::ofstream(scene_path) << description.dump();

  run_blender_script(blender, MATPREDICT_CYCLES_SCRIPT, {scene_path}, log_path, "Blender failed to render " + scene_path);
  json timings;
  std::ifstream(folder + "/cycles_timings.json") >> timings;
  for (CyclesRender& render : renders) render.seconds = timings.at(render.exr_path).get<double>();
}

BlenderMaterials import_gltf_with_blender(const std::string& gltf_path, const std::string& folder,
                                          const std::string& blender) {
  std::filesystem::create_directories(folder);
  const std::string out_path = folder + "/blender_materials.json", log_path = folder + "/blender.log";
  run_blender_script(blender, MATPREDICT_GLTF_IMPORT_SCRIPT, {gltf_path, out_path}, log_path,
                     "Blender failed to import " + gltf_path);
  json materials;
  std::ifstream(out_path) >> materials;
  BlenderMaterials result;
  for (const auto& [name, nodes] : materials.items())
    for (const auto& [node, inputs] : nodes.items())
      for (const auto& [input, state] : inputs.items()) {
        BlenderInput& out = result[name][node][input];
        out.linked = state.at("linked").get<bool>();
        const json& value = state.at("value");
        if (value.is_array())
          out.value = value.get<std::vector<double>>();
        else if (value.is_number())
          out.value = {value.get<double>()};
        const json& mapping = state.at("mapping");
        if (mapping.is_null()) continue;
        if (mapping.at("vector_type").get<std::string>() != "POINT")
          throw std::runtime_error(gltf_path + ": Blender's Mapping node for " + input + " is not of type Point");
        const auto location = mapping.at("location").get<std::vector<double>>();
        const auto scale = mapping.at("scale").get<std::vector<double>>();
        out.mapping = BlenderUvMapping{{location.at(0), location.at(1)}, mapping.at("rotation_z").get<double>(),
                                       {scale.at(0), scale.at(1)}};
      }
  return result;
}

std::vector<UdimProbe> probe_udim_with_blender(const std::string& folder, const std::string& blender) {
  std::filesystem::create_directories(folder);
  const std::string out_path = folder + "/udim_probe.json", log_path = folder + "/blender.log";
  run_blender_script(blender, MATPREDICT_UDIM_PROBE_SCRIPT, {folder, out_path}, log_path, "Blender's UDIM probe failed");
  json probes;
  std::ifstream(out_path) >> probes;
  std::vector<UdimProbe> result;
  for (const auto& [name, probe] : probes.items()) {
    const auto uv = probe.at("uv").get<std::vector<double>>();
    const auto rgb = probe.at("rgb").get<std::vector<double>>();
    result.push_back({name, glm::vec2(uv.at(0), uv.at(1)), glm::vec3(rgb.at(0), rgb.at(1), rgb.at(2))});
  }
  return result;
}

SkyProbe probe_sky_with_blender(const matrender::NishitaSky& sky, int width, const std::string& folder,
                                const std::string& blender) {
  std::filesystem::create_directories(folder);
  const std::string sky_path = folder + "/sky.json", directions_path = folder + "/directions.exr",
                    radiance_path = folder + "/sky.exr";
  json description = sky_json(sky);
  description["width"] = width;
  std::ofstream(sky_path) << description.dump(2);
  run_blender_script(blender, MATPREDICT_SKY_PROBE_SCRIPT, {sky_path, directions_path, radiance_path},
                     folder + "/blender.log", "Blender's sky probe failed");
  const std::vector<float> encoded = read_rgb_exr(directions_path, width, width / 2);
  const std::vector<float> radiance = read_rgb_exr(radiance_path, width, width / 2);
  SkyProbe probe;
  for (size_t i = 0; i < encoded.size(); i += 3) {
    // The script's world shows (d + 1) / 2.
    probe.directions.push_back(glm::normalize(2.0 * glm::dvec3(encoded[i], encoded[i + 1], encoded[i + 2]) - 1.0));
    probe.radiance.emplace_back(radiance[i], radiance[i + 1], radiance[i + 2]);
  }
  return probe;
}

std::vector<float> read_rgb_exr(const std::string& path, int width, int height) {
  auto input = OIIO::ImageInput::open(path);
  if (!input) throw std::runtime_error(path + ": cannot open: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = input->spec();
  if (spec.width != width || spec.height != height || spec.nchannels < 3)
    throw std::runtime_error(path + ": expected a " + std::to_string(width) + "x" + std::to_string(height) +
                             " RGB image");
  std::vector<float> rgb(static_cast<size_t>(width) * static_cast<size_t>(height) * 3);
  if (!input->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, rgb.data()))
    throw std::runtime_error(path + ": " + input->geterror());
  return rgb;
}

}  // namespace shaders_ref
