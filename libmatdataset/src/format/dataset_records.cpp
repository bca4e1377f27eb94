#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>
#include <yaml-cpp/yaml.h>

#include "matbase/file/atomic_file.h"
#include "matdataset/format/dataset_writer.h"
#include "matmaterial/material_classes.h"

namespace matdataset {
namespace {

namespace fs = std::filesystem;
using nlohmann::ordered_json;

// The repository's constant per-frame "rotation" (a placeholder of NeRF's synthetic format, -1
// degree in radians), kept so readers that expect the key find it.
constexpr double kPlaceholderRotation = -0.0174533;

void write_json(const fs::path& path, const ordered_json& json) {
  matbase::write_file_atomically(path, json.dump(2) + "\n");
}

}  // namespace

CameraIntrinsics pinhole_intrinsics(int width, int height, double vertical_fov) {
  CameraIntrinsics k;
  k.width = width;
  k.height = height;
  k.fl_y = 0.5 * height / std::tan(0.5 * vertical_fov);
  k.fl_x = k.fl_y;
  k.cx = 0.5 * width;
  k.cy = 0.5 * height;
  return k;
}

void write_transforms(const fs::path& variant_folder, const CameraIntrinsics& k, const std::vector<FramePose>& frames,
                      const FrameContents& contents) {
  ordered_json json;
  json["camera_angle_x"] = 2.0 * std::atan(0.5 * k.width / k.fl_x);
  json["camera_angle_y"] = 2.0 * std::atan(0.5 * k.height / k.fl_y);
  json["fl_x"] = k.fl_x;
  json["fl_y"] = k.fl_y;
  json["cx"] = k.cx;
  json["cy"] = k.cy;
  json["w"] = k.width;
  json["h"] = k.height;
  json["frames"] = ordered_json::array();
  for (const FramePose& frame : frames) {
    ordered_json entry;
    // The repository's keys first, in its order, then the maps it does not list.
    for (const DatasetMap map : {DatasetMap::Images, DatasetMap::Albedo, DatasetMap::NormalObject, DatasetMap::Orm,
                                 DatasetMap::Depth, DatasetMap::Label, DatasetMap::NormalMaterial,
                                 DatasetMap::SampleCount}) {
      const DatasetMapInfo& info = dataset_maps()[static_cast<size_t>(map)];
      entry[info.transforms_key] = std::string(info.folder) + "/" + frame.stem;  // no extension, as the repository
    }
    for (const DatasetMap map : {DatasetMap::Region, DatasetMap::HdrImages}) {
      const DatasetMapInfo& info = dataset_maps()[static_cast<size_t>(map)];
      if (frame_has_map(info, contents)) entry[info.transforms_key] = std::string(info.folder) + "/" + frame.stem;
    }
    entry["rotation"] = kPlaceholderRotation;
    const ordered_json lighting = frame.lighting_json.empty() ? ordered_json() : ordered_json::parse(frame.lighting_json);
    // The repository's key for the frame's environment map: the image, when one lights it.
    const bool environment = lighting.is_object() && lighting.contains("background") &&
                             lighting.at("background").is_object() && lighting.at("background").contains("environment");
    entry["envmap"] = environment ? lighting.at("background").at("environment") : ordered_json(nullptr);
    entry["transform_matrix"] = frame.camera_to_world;
    if (!lighting.is_null()) entry["lighting"] = lighting;
    if (!frame.surroundings_json.empty()) entry["surroundings"] = ordered_json::parse(frame.surroundings_json);
    json["frames"].push_back(std::move(entry));
  }
  write_json(variant_folder / "transforms.json", json);
}

std::string variant_metadata_text(const VariantMetadata& metadata) {
  ordered_json variant_map = ordered_json::object(), used = ordered_json::object();
  std::map<std::string, const SlotMaterial*> by_slot;  // the repository sorts used_materials by key
  for (const SlotMaterial& slot : metadata.materials) {
    const std::optional<matmaterial::MaterialClass> family = matmaterial::material_class_of_label(slot.label_id);
    if (!family || *family == matmaterial::MaterialClass::Background)
      throw std::invalid_argument("slot \"" + slot.slot + "\": material \"" + slot.material + "\" has label " +
                                  std::to_string(slot.label_id) + ", which is no material class");
    variant_map[slot.slot] = slot.material;
    by_slot[slot.slot] = &slot;
  }
  for (const auto& [key, slot] : by_slot)
    used[key] = {{"material", slot->material},
                 {"material_family", matmaterial::material_class(*matmaterial::material_class_of_label(slot->label_id)).name},
                 {"label_id", slot->label_id}};
  ordered_json structure = ordered_json::array();
  for (const DatasetMapInfo& info : dataset_maps())
    if (frame_has_map(info, metadata.contents)) structure.push_back(info.folder);
  const ordered_json provenance = ordered_json::parse(metadata.provenance_json, nullptr, false);
  if (!provenance.is_object()) throw std::invalid_argument("variant metadata: the provenance is not a JSON object");

  ordered_json json;
  json["variant_map"] = variant_map;
  json["used_materials"] = used;
  json["render_summary"] = {{"resolution", {{"width", metadata.width}, {"height", metadata.height}}},
                            {"samples", metadata.samples},
                            {"output_structure", structure}};
  json["provenance"] = provenance;
  return json.dump(2) + "\n";
}

void write_variant_metadata(const fs::path& variant_folder, const VariantMetadata& metadata) {
  matbase::write_file_atomically(variant_folder / "metadata.json", variant_metadata_text(metadata));
}

void write_segmentation_map_json(const fs::path& variant_folder) {
  ordered_json id_to_family = ordered_json::object(), family_to_id = ordered_json::object();
  for (const matmaterial::MaterialClassInfo& info : matmaterial::kMaterialClasses) {
    id_to_family[std::to_string(matmaterial::label_id(info.id))] = info.name;
    family_to_id[info.name] = matmaterial::label_id(info.id);
  }
  write_json(variant_folder / "material_segmentation_map.json",
             {{"id_to_material_family", id_to_family}, {"material_family_to_id", family_to_id}});
}

void write_segmentation_map_yaml(const fs::path& root) {
  YAML::Emitter out;
  out << YAML::BeginMap << YAML::Key << "material_segmentation_map" << YAML::Value << YAML::BeginMap;
  for (const matmaterial::MaterialClassInfo& info : matmaterial::kMaterialClasses)
    out << YAML::Key << info.name << YAML::Value << matmaterial::label_id(info.id);
  out << YAML::EndMap << YAML::EndMap;
  matbase::write_file_atomically(root / "material_segmentation_map.yaml", std::string(out.c_str()) + "\n");
}

}  // namespace matdataset
