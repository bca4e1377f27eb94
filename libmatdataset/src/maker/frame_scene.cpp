#include "matdataset/maker/frame_scene.h"

#include <variant>

#include <nlohmann/json.hpp>

#include "matbase/file/input_file.h"
#include "matbase/input_error.h"
#include "matdataset/maker/dataset_config.h"
#include "matdataset/maker/render_keys.h"
#include "matrender/render_setting_declarations.h"

namespace matdataset {
namespace {

namespace fs = std::filesystem;
using nlohmann::ordered_json;

ordered_json read_json(const fs::path& file) {
  std::string text;
  if (const std::optional<std::string> problem = matbase::read_whole_file(file, text)) throw matbase::InputError(*problem);
  ordered_json json = ordered_json::parse(text, nullptr, false);
  if (json.is_discarded() || !json.is_object()) throw matbase::InputError(file.string() + ": not a JSON object");
  return json;
}

// The member at `key` of `json`, refused naming the file when it is missing.
const ordered_json& member(const ordered_json& json, const std::string& key, const fs::path& file) {
  if (!json.is_object() || !json.contains(key))
    throw matbase::InputError(file.string() + ": no \"" + key + "\"; was it written by make_dataset?");
  return json[key];
}

// Every scene setting of `settings` as the scene file's render block spells it.
ordered_json render_block(const matrender::RenderSettings& settings) {
  ordered_json render = ordered_json::object();
  for (const matrender::RenderSettingDeclaration& setting : matrender::render_setting_declarations())
    if (setting.scope == matrender::SettingScope::Scene) render[std::string(setting.name)] = render_setting_json(settings, setting);
  return render;
}

}  // namespace

FrameScene dataset_frame_scene(const fs::path& frame) {
  // ".../var000/images/003.png" or ".../var000/003".
  fs::path variant = frame.parent_path();
  std::string stem = frame.stem().string();
  if (!fs::exists(variant / "metadata.json") && fs::exists(variant.parent_path() / "metadata.json"))
    variant = variant.parent_path();
  const fs::path metadata_file = variant / "metadata.json", transforms_file = variant / "transforms.json";
  for (const fs::path& file : {metadata_file, transforms_file})
    if (!fs::exists(file))
      throw matbase::InputError(frame.string() + ": no " + file.filename().string() + " in " + variant.string() +
                                "; give a frame of a make_dataset variant folder (dataset/OBJECT/VARIANT/STEM)");
  const ordered_json metadata = read_json(metadata_file);
  const ordered_json& provenance = member(metadata, "provenance", metadata_file);
  const fs::path root = variant.parent_path().parent_path();
  // Its relative paths are relative to the folder it was read from, which is recorded where that
  // is not the dataset's parent folder.
  const auto recorded_folder = provenance.find("configuration_folder");
  if (recorded_folder != provenance.end() && !recorded_folder->is_string())
    throw matbase::InputError(metadata_file.string() + ": provenance.configuration_folder is not text");
  const fs::path folder = recorded_folder != provenance.end() ? fs::path(recorded_folder->get<std::string>())
                                                              : fs::absolute(root).parent_path();
  const DatasetConfig config = parse_config(member(provenance, "configuration", metadata_file).get<std::string>(),
                                            metadata_file.string() + ": configuration", folder, {});

  const std::string object_name = member(member(provenance, "object", metadata_file), "name", metadata_file);
  const ObjectConfig* object = nullptr;
  for (const ObjectConfig& candidate : config.objects)
    if (candidate.name == object_name) object = &candidate;
  if (!object) throw matbase::InputError(metadata_file.string() + ": the configuration has no object \"" + object_name + "\"");

  ordered_json scene;
  ordered_json object_json;
  if (const auto* builtin = std::get_if<matrender::BuiltinObject>(&object->source)) {
    object_json = {{"builtin", builtin->name}, {"seed", builtin->seed}};
  } else {
    const auto& mesh = std::get<matrender::MeshFile>(object->source);
    object_json = {{"mesh", mesh.path}};
    if (mesh.read_options.auto_smooth_deg) object_json["auto_smooth_deg"] = *mesh.read_options.auto_smooth_deg;
    if (!mesh.only_parts.empty()) object_json["only_parts"] = mesh.only_parts;
  }
  const char* uv_pass[] = {"never", "when_missing", "always"};
  object_json["uv_pass"] = uv_pass[static_cast<int>(object->uv_pass)];
  // The variant's UV scale, as its provenance records it (1 where it records none).
  if (object->uv_pass != matrender::UvPassMode::Never) {
    const ordered_json& source = member(member(provenance, "object", metadata_file), "source", metadata_file);
    const auto scale = source.find("uv_scale");
    if (scale != source.end() && !scale->is_number())
      throw matbase::InputError(metadata_file.string() + ": provenance.object.source.uv_scale is not a number");
    object_json["uv_scale"] = scale != source.end() ? scale->get<double>() : 1.0;
  }

  // The variant's material in each slot, by the name the provenance records.
  ordered_json materials = ordered_json::object(), part_materials = ordered_json::object();
  const ordered_json& slots = member(member(provenance, "variant", metadata_file), "slots", metadata_file);
  for (const ordered_json& slot : slots) {
    const std::string key = member(slot, "slot", metadata_file), name = member(slot, "material", metadata_file);
    const MaterialCandidate* chosen = nullptr;
    for (const SlotConfig& config_slot : object->slots)
      if (config_slot.key == key)
        for (const MaterialCandidate& candidate : config_slot.candidates)
          if (candidate.name == name) chosen = &candidate;
    if (!chosen)
      throw matbase::InputError(metadata_file.string() + ": slot \"" + key + "\" has no material \"" + name +
                                "\" in the recorded configuration");
    materials[name] = candidate_scene_json(*chosen, config.render.material_resolution);
    const ordered_json& parts = member(slot, "parts", metadata_file);
    bool every_part = false;
    for (const SlotConfig& config_slot : object->slots) every_part |= config_slot.key == key && config_slot.parts.empty();
    if (every_part) object_json["material"] = name;
    else
      for (const ordered_json& part : parts) part_materials[part.get<std::string>()] = name;
  }
  if (!part_materials.empty()) object_json["materials"] = part_materials;
  scene["objects"] = ordered_json::array({object_json});
  // The room the variant drew, as recorded, in its recorded materials.
  const auto surroundings = provenance.find("surroundings");
  if (surroundings != provenance.end() && object->surroundings.kind == SurroundingsKind::Scan) {
    // The rest of the scan, in its own materials.
    const auto& mesh = std::get<matrender::MeshFile>(object->source);
    ordered_json scan_json = {{"mesh", mesh.path}, {"except_parts", object->surroundings.scan.target}, {"surroundings", true}};
    if (mesh.read_options.auto_smooth_deg) scan_json["auto_smooth_deg"] = *mesh.read_options.auto_smooth_deg;
    scene["objects"].push_back(scan_json);
  } else if (surroundings != provenance.end()) {
    ordered_json room_json = {{"room", member(*surroundings, "room", metadata_file)}, {"surroundings", true}};
    ordered_json room_materials = ordered_json::object();
    for (const auto& [part, material] : member(*surroundings, "materials", metadata_file).items()) {
      const std::string name = member(material, "name", metadata_file);
      materials[name] = member(material, "scene", metadata_file);
      room_materials[part] = name;
    }
    room_json["materials"] = room_materials;
    scene["objects"].push_back(room_json);
  }
  scene["materials"] = materials;

  const ordered_json transforms = read_json(transforms_file);
  const ordered_json* entry = nullptr;
  for (const ordered_json& candidate : member(transforms, "frames", transforms_file))
    if (candidate.value("file_path", "") == "images/" + stem) entry = &candidate;
  if (!entry) throw matbase::InputError(transforms_file.string() + ": no frame \"" + stem + "\"");
  // The frame's distractors, each its slot's object and material, at its recorded place.
  // (A scan's frames record only how much of the target shows.)
  const auto frame_surroundings = entry->find("surroundings");
  if (frame_surroundings != entry->end() && object->surroundings.kind == SurroundingsKind::Distractors) {
    const ordered_json& distractor_slots =
        member(member(member(provenance, "surroundings", metadata_file), "distractors", metadata_file), "slots",
               metadata_file);
    for (const ordered_json& placed : member(*frame_surroundings, "distractors", transforms_file)) {
      const ordered_json& slot_index = member(placed, "slot", transforms_file);
      if (!slot_index.is_number_unsigned() || slot_index.get<size_t>() >= distractor_slots.size())
        throw matbase::InputError(transforms_file.string() + ": frame \"" + stem + "\" places a distractor of no slot");
      const ordered_json& slot = distractor_slots[slot_index.get<size_t>()];
      const ordered_json& material = member(slot, "material", metadata_file);
      const std::string name = member(material, "name", metadata_file);
      scene["materials"][name] = member(material, "scene", metadata_file);
      ordered_json distractor = member(slot, "object", metadata_file);
      distractor["uv_pass"] = "when_missing";
      distractor["transform"] = {{"matrix", member(placed, "transform", transforms_file)}};
      distractor["material"] = name;
      distractor["surroundings"] = true;
      scene["objects"].push_back(distractor);
    }
  }
  const ordered_json& lighting = member(*entry, "lighting", transforms_file);
  scene["camera"] = {{"matrix", member(*entry, "transform_matrix", transforms_file)},
                     {"fov_deg", config.camera.vertical_fov_deg},
                     {"width", config.render.width},
                     {"height", config.render.height}};
  scene["lights"] = member(lighting, "lights", transforms_file);
  scene["background"] = member(lighting, "background", transforms_file);

  matrender::RenderSettings settings = config.render.settings;
  const ordered_json& seeds = member(member(provenance, "render", metadata_file), "frame_seeds", metadata_file);
  settings.seed = member(seeds, stem, metadata_file).get<uint32_t>();
  settings.transparent_background = !member(lighting, "background_visible", transforms_file).get<bool>();
  ordered_json render = render_block(settings);
  render["exposure"] = member(lighting, "exposure_stops", transforms_file);
  scene["render"] = render;
  return {scene.dump(2), folder.string()};
}

}  // namespace matdataset
