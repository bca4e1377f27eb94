#include "verify_dataset.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <optional>
#include <set>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "dataset_config.h"
#include "dataset_folders.h"
#include "matgeom/material_classes.h"
#include "matlearn/dataset_index.h"
#include "matlearn/decoded_image.h"
#include "matlearn/dataset_writer.h"

namespace make_dataset {
namespace {

namespace fs = std::filesystem;
using matlearn::DatasetMap;

// OpenImageIO's errors may span lines: one problem, one line.
std::string one_line(std::string text) {
  while (!text.empty() && text.back() == '\n') text.pop_back();
  for (char& c : text) c = c == '\n' ? ';' : c;
  return text;
}

nlohmann::json read_json(const fs::path& file, std::vector<std::string>& problems) {
  std::ifstream in(file);
  if (!in) {
    problems.push_back(file.string() + ": missing");
    return nullptr;
  }
  const nlohmann::json json = nlohmann::json::parse(in, nullptr, false);
  if (json.is_discarded() || !json.is_object()) problems.push_back(file.string() + ": not a JSON object");
  return json.is_discarded() ? nlohmann::json(nullptr) : json;
}

// The label ids the variant's metadata.json says it uses.
std::set<int> used_labels(const fs::path& folder, const nlohmann::json& metadata, std::vector<std::string>& problems) {
  std::set<int> labels;
  if (!metadata.is_object()) return labels;
  const auto used = metadata.find("used_materials");
  if (used == metadata.end() || !used->is_object()) {
    problems.push_back((folder / "metadata.json").string() + ": no used_materials");
    return labels;
  }
  for (const auto& [slot, material] : used->items()) {
    if (!material.is_object() || !material.contains("label_id") || !material["label_id"].is_number_integer()) {
      problems.push_back((folder / "metadata.json").string() + ": used_materials." + slot + " has no label_id");
      continue;
    }
    labels.insert(material["label_id"].get<int>());
  }
  return labels;
}

// What every frame of a variant must agree with.
struct VariantExpectations {
  int width = 0, height = 0;
  std::set<int> labels;       // metadata.json's used_materials
  std::optional<int> samples;  // metadata.json's provenance.render.samples, where it says
};

// The most samples a pixel may have taken, as the variant's metadata.json states it.
std::optional<int> stated_samples(const nlohmann::json& metadata) {
  if (!metadata.is_object()) return std::nullopt;
  const nlohmann::json::json_pointer pointer("/provenance/render/samples");
  if (!metadata.contains(pointer) || !metadata[pointer].is_number_integer()) return std::nullopt;
  return metadata[pointer].get<int>();
}

// A sample count map's problems: pixels without a sample, or with more than the render took.
void verify_sample_counts(const fs::path& file, const matlearn::Decoded& counts, std::optional<int> samples,
                          std::vector<std::string>& problems) {
  size_t none = 0, beyond = 0;
  for (const float value : counts.values) {
    const long count = std::lround(value * static_cast<float>(matlearn::kMaxSampleCount));
    if (count < 1) ++none;
    if (samples && count > *samples) ++beyond;
  }
  if (none > 0) problems.push_back(fmt::format("{}: {} pixels took no sample", file.string(), none));
  if (beyond > 0)
    problems.push_back(fmt::format("{}: {} pixels took more than the {} samples metadata.json states", file.string(),
                                   beyond, *samples));
}

void verify_frame(const fs::path& folder, const std::string& stem, const VariantExpectations& expected,
                  std::vector<std::string>& problems) {
  const int width = expected.width, height = expected.height;
  std::map<DatasetMap, matlearn::Decoded> maps;
  for (const matlearn::DatasetMapInfo& info : matlearn::dataset_maps()) {
    // Our own maps are checked where the variant has their folder: the repository's datasets
    // have none of them.
    if (!info.repository && !fs::is_directory(folder / info.folder)) continue;
    const fs::path file = folder / info.folder / (stem + info.extension);
    if (!fs::is_regular_file(file)) {
      problems.push_back(file.string() + ": missing");
      continue;
    }
    matlearn::Decoded map;
    try {
      map = matlearn::decode(file);
    } catch (const std::runtime_error& e) {
      problems.push_back(one_line(e.what()));
      continue;
    }
    if (map.width != width || map.height != height || map.channels != info.channels) {
      problems.push_back(fmt::format("{}: {}x{} with {} channels, expected {}x{} with {}", file.string(), map.width,
                                     map.height, map.channels, width, height, info.channels));
      continue;
    }
    maps.emplace(info.map, std::move(map));
  }
  if (const auto counts = maps.find(DatasetMap::SampleCount); counts != maps.end())
    verify_sample_counts(folder / "sample_count" / (stem + ".png"), counts->second, expected.samples, problems);
  const std::set<int>& labels = expected.labels;
  const auto label = maps.find(DatasetMap::Label), depth = maps.find(DatasetMap::Depth), orm = maps.find(DatasetMap::Orm);
  if (label == maps.end()) return;
  const fs::path label_file = folder / "label" / (stem + ".png");
  std::set<int> found;
  size_t mask_disagreements = 0;
  for (size_t p = 0; p < label->second.values.size(); ++p) {
    const int id = static_cast<int>(std::lround(label->second.values[p] * 255.0f));
    found.insert(id);
    const bool object = id > 0;
    const bool covered = depth != maps.end() && depth->second.values[4 * p + 3] > 0.0f;
    const bool orm_alpha = orm != maps.end() && orm->second.values[4 * p + 3] > 0.0f;
    if ((depth != maps.end() && object != covered) || (orm != maps.end() && object != orm_alpha)) ++mask_disagreements;
  }
  for (const int id : found) {
    if (id == 0) continue;
    if (!matgeom::material_class_of_label(id))
      problems.push_back(fmt::format("{}: label {} is no class of the table", label_file.string(), id));
    else if (!labels.count(id))
      problems.push_back(fmt::format("{}: label {} ({}) is not among the variant's used_materials", label_file.string(),
                                     id, matgeom::label_name(id)));
  }
  if (mask_disagreements > 0)
    problems.push_back(fmt::format("{}: at {} pixels the label's object mask differs from the coverage in depth/ or "
                                   "ORM's alpha",
                                   label_file.string(), mask_disagreements));
}

void verify_variant(const fs::path& folder, VerifyReport& report, std::set<std::string>& ids) {
  ++report.variants;
  std::vector<std::string>& problems = report.problems;
  const fs::path transforms_file = folder / "transforms.json";
  const nlohmann::json transforms = read_json(transforms_file, problems);
  const nlohmann::json metadata = read_json(folder / "metadata.json", problems);
  VariantExpectations expected;
  expected.labels = used_labels(folder, metadata, problems);
  expected.samples = stated_samples(metadata);
  if (!fs::is_regular_file(folder / "material_segmentation_map.json"))
    problems.push_back((folder / "material_segmentation_map.json").string() + ": missing");
  if (!transforms.is_object()) return;
  if (!transforms.contains("w") || !transforms.contains("h") || !transforms["w"].is_number_integer() ||
      !transforms["h"].is_number_integer() || !transforms.contains("frames") || !transforms["frames"].is_array()) {
    problems.push_back(transforms_file.string() + ": needs w, h and a frames list");
    return;
  }
  expected.width = transforms["w"].get<int>();
  expected.height = transforms["h"].get<int>();
  for (const nlohmann::json& frame : transforms["frames"]) {
    if (!frame.is_object() || !frame.contains("file_path") || !frame["file_path"].is_string() ||
        !frame.contains("transform_matrix") || !frame["transform_matrix"].is_array() ||
        frame["transform_matrix"].size() != 4) {
      problems.push_back(transforms_file.string() + ": a frame lacks file_path or a 4 x 4 transform_matrix");
      continue;
    }
    const std::string path = frame["file_path"].get<std::string>();
    const std::string stem = path.substr(path.rfind('/') + 1);
    ++report.frames;
    ids.insert(folder.parent_path().filename().string() + "/" + folder.filename().string() + "/" + stem);
    verify_frame(folder, stem, expected, problems);
  }
}

}  // namespace

VerifyReport verify_dataset(const fs::path& root) {
  const std::vector<fs::path> variants = variant_folders(root, "images");
  VerifyReport report;
  if (!fs::is_regular_file(root / kSegmentationMapFile))
    report.problems.push_back((root / kSegmentationMapFile).string() + ": missing");
  std::set<std::string> ids;
  for (const fs::path& variant : variants) verify_variant(variant, report, ids);
  // Every split file lists frames of the dataset, each once.
  if (fs::is_directory(root / kConfigFolder))
    for (const fs::directory_entry& entry : fs::directory_iterator(root / kConfigFolder)) {
      if (entry.path().extension() != ".yaml") continue;
      try {
        const matlearn::SplitFile split = matlearn::read_split_file(entry.path());
        std::set<std::string> listed;
        for (const std::vector<std::string>* list : {&split.train, &split.val, &split.test})
          for (const std::string& id : *list) {
            if (!ids.count(id)) report.problems.push_back(entry.path().string() + ": lists " + id + ", no frame of the dataset");
            if (!listed.insert(id).second) report.problems.push_back(entry.path().string() + ": lists " + id + " twice");
          }
      } catch (const std::exception& e) {
        report.problems.push_back(e.what());
      }
    }
  return report;
}

}  // namespace make_dataset
