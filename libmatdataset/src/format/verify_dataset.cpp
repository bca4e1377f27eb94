#include "matdataset/format/verify_dataset.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <set>

#include <fmt/format.h>
#include <OpenImageIO/imageio.h>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>
#include <yaml-cpp/yaml.h>

#include "matbase/image/image_header.h"
#include "matbase/number_text.h"
#include "matdataset/format/dataset_folders.h"
#include "matdataset/format/dataset_index.h"
#include "matdataset/format/dataset_writer.h"
#include "matdataset/format/decoded_image.h"
#include "matmaterial/material_classes.h"

namespace matdataset {
namespace {

namespace fs = std::filesystem;

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
    const int id = material["label_id"].get<int>();
    const auto family = material.find("material_family");
    if (family != material.end() && family->is_string() && family->get<std::string>() != matmaterial::label_name(id))
      problems.push_back(fmt::format("{}: used_materials.{} is of family \"{}\" but has label {} ({})",
                                     (folder / "metadata.json").string(), slot, family->get<std::string>(), id,
                                     matmaterial::label_name(id)));
    labels.insert(id);
  }
  return labels;
}

// The class table's names by label id, which the labels are read with.
std::map<int, std::string> class_table() {
  std::map<int, std::string> table;
  for (const matmaterial::MaterialClassInfo& info : matmaterial::kMaterialClasses) table[matmaterial::label_id(info.id)] = info.name;
  return table;
}

// What a segmentation map says that the class table does not: the repository's loader reads the
// labels with the map, this library with the table, so they must be the same.
void verify_map_against_table(const fs::path& file, const std::map<int, std::string>& map,
                              std::vector<std::string>& problems) {
  const std::map<int, std::string> table = class_table();
  if (map == table) return;
  for (const auto& [id, name] : table) {
    const auto it = map.find(id);
    if (it == map.end())
      problems.push_back(fmt::format("{}: label {} ({}) is missing", file.string(), id, name));
    else if (it->second != name)
      problems.push_back(fmt::format("{}: names label {} \"{}\", but it is {}", file.string(), id, it->second, name));
  }
  for (const auto& [id, name] : map)
    if (!table.count(id)) problems.push_back(fmt::format("{}: label {} (\"{}\") is no class", file.string(), id, name));
}

// A variant's material_segmentation_map.json: id_to_material_family and its inverse, both the table.
void verify_segmentation_json(const fs::path& file, std::vector<std::string>& problems) {
  const nlohmann::json json = read_json(file, problems);
  if (!json.is_object()) return;
  const auto names = json.find("id_to_material_family"), ids = json.find("material_family_to_id");
  if (names == json.end() || !names->is_object() || ids == json.end() || !ids->is_object()) {
    problems.push_back(file.string() + ": needs id_to_material_family and material_family_to_id mappings");
    return;
  }
  std::map<int, std::string> by_id, inverse;
  for (const auto& [id, name] : names->items()) {
    const std::optional<int64_t> number = matbase::whole_number(id);
    if (!number || !name.is_string()) {
      problems.push_back(file.string() + ": id_to_material_family." + id + " is not a label id and a name");
      return;
    }
    by_id[static_cast<int>(*number)] = name.get<std::string>();
  }
  for (const auto& [name, id] : ids->items()) {
    if (!id.is_number_integer()) {
      problems.push_back(file.string() + ": material_family_to_id." + name + " is not a label id");
      return;
    }
    inverse[id.get<int>()] = name;
  }
  verify_map_against_table(file, by_id, problems);
  if (inverse != by_id)
    problems.push_back(file.string() + ": material_family_to_id is not the inverse of id_to_material_family");
}

// The root's material_segmentation_map.yaml: family -> id, the table.
void verify_segmentation_yaml(const fs::path& file, std::vector<std::string>& problems) {
  std::map<int, std::string> by_id;
  try {
    const YAML::Node map = YAML::LoadFile(file.string())["material_segmentation_map"];
    if (!map.IsMap()) {
      problems.push_back(file.string() + ": needs a material_segmentation_map mapping");
      return;
    }
    for (const auto& entry : map) {
      const std::optional<int64_t> id = matbase::whole_number(entry.second.IsScalar() ? entry.second.Scalar() : "");
      if (!id) {
        problems.push_back(file.string() + ": " + entry.first.Scalar() + " has no label id");
        return;
      }
      if (const auto [it, inserted] = by_id.emplace(static_cast<int>(*id), entry.first.Scalar()); !inserted) {
        problems.push_back(fmt::format("{}: label {} is given to both {} and {}", file.string(), *id, it->second,
                                       entry.first.Scalar()));
        return;
      }
    }
  } catch (const YAML::Exception& e) {
    problems.push_back(file.string() + ": not valid YAML: " + e.msg);
    return;
  }
  verify_map_against_table(file, by_id, problems);
}

// The object's bounding sphere, in world metres.
struct Sphere {
  glm::dvec3 center{0.0};
  double radius = 0.0;
};

// What every frame of a variant must agree with.
struct VariantExpectations {
  int width = 0, height = 0;
  std::set<int> labels;        // metadata.json's used_materials
  std::optional<int> samples;  // metadata.json's provenance.render.samples, where it says
  std::optional<Sphere> bounds;  // metadata.json's provenance.lights.bounds, where it says
  bool surroundings = false;     // metadata.json's provenance records surroundings: frames have region maps
};

// The object's bounding sphere as the variant's metadata.json states it.
std::optional<Sphere> stated_bounds(const nlohmann::json& metadata) {
  if (!metadata.is_object()) return std::nullopt;
  const nlohmann::json::json_pointer pointer("/provenance/lights/bounds");
  if (!metadata.contains(pointer)) return std::nullopt;
  const nlohmann::json& bounds = metadata[pointer];
  if (!bounds.is_object() || !bounds.contains("center") || !bounds.contains("radius") || !bounds["center"].is_array() ||
      bounds["center"].size() != 3 || !bounds["radius"].is_number())
    return std::nullopt;
  Sphere sphere;
  for (int k = 0; k < 3; ++k) {
    if (!bounds["center"][static_cast<size_t>(k)].is_number()) return std::nullopt;
    sphere.center[k] = bounds["center"][static_cast<size_t>(k)].get<double>();
  }
  sphere.radius = bounds["radius"].get<double>();
  if (!std::isfinite(sphere.radius) || sphere.radius < 0.0 || !std::isfinite(glm::length(sphere.center)))
    return std::nullopt;
  return sphere;
}

// The camera's position and viewing direction (Blender's camera looks down its -Z), from a
// frame's transform_matrix (camera to world, rows); nothing when it is not 4 x 4 finite numbers.
struct CameraAxis {
  glm::dvec3 position, forward;
};
std::optional<CameraAxis> camera_axis(const nlohmann::json& matrix) {
  double m[3][4];
  for (size_t r = 0; r < 3; ++r) {
    if (!matrix[r].is_array() || matrix[r].size() != 4) return std::nullopt;
    for (size_t c = 0; c < 4; ++c) {
      if (!matrix[r][c].is_number()) return std::nullopt;
      m[r][c] = matrix[r][c].get<double>();
      if (!std::isfinite(m[r][c])) return std::nullopt;
    }
  }
  const glm::dvec3 back(m[0][2], m[1][2], m[2][2]);
  if (glm::length(back) == 0.0) return std::nullopt;
  return CameraAxis{{m[0][3], m[1][3], m[2][3]}, -glm::normalize(back)};
}

// Depth along the camera axis at the object's pixels: finite, positive, and within the range the
// object's bounding sphere spans along the axis (with room for rounding); a NaN, a 0 or a depth
// beyond the object is no depth of it.
// `object_ids`, when given, says which covered pixels are the object's (with surroundings, the
// label's): only there must the depth be within its bounds.
void verify_depth(const fs::path& file, const matbase::FloatImage& depth, const std::optional<Sphere>& bounds,
                  const std::optional<CameraAxis>& camera, const std::vector<int32_t>* object_ids,
                  std::vector<std::string>& problems) {
  double near = 0.0, far = INFINITY;
  if (bounds && camera) {
    const double centre = glm::dot(bounds->center - camera->position, camera->forward);
    const double slack = 1e-4 * (std::abs(centre) + bounds->radius) + 1e-6;
    near = centre - bounds->radius - slack;
    far = centre + bounds->radius + slack;
  }
  size_t not_finite = 0, not_positive = 0, outside = 0;
  for (size_t p = 0; p < depth.values.size() / 4; ++p) {
    if (depth.values[4 * p + 3] <= 0.0f) continue;  // no surface
    const float d = depth.values[4 * p];
    const bool object = !object_ids || (p < object_ids->size() && (*object_ids)[p] > 0);
    if (!std::isfinite(d)) ++not_finite;
    else if (d <= 0.0f) ++not_positive;
    else if (object && (d < near || d > far)) ++outside;
  }
  if (not_finite > 0) problems.push_back(fmt::format("{}: {} covered pixels have a depth that is NaN or infinite", file.string(), not_finite));
  if (not_positive > 0) problems.push_back(fmt::format("{}: {} covered pixels have a depth of 0 or less", file.string(), not_positive));
  if (outside > 0)
    problems.push_back(fmt::format("{}: {} of the object's pixels have a depth outside {:.4g} to {:.4g} m, the "
                                   "object's bounding sphere along the camera axis",
                                   file.string(), outside, near, far));
}

// The most samples a pixel may have taken, as the variant's metadata.json states it.
std::optional<int> stated_samples(const nlohmann::json& metadata) {
  if (!metadata.is_object()) return std::nullopt;
  const nlohmann::json::json_pointer pointer("/provenance/render/samples");
  if (!metadata.contains(pointer) || !metadata[pointer].is_number_integer()) return std::nullopt;
  return metadata[pointer].get<int>();
}

// A sample count map's problems: pixels without a sample, or with more than the render took.
void verify_sample_counts(const fs::path& file, const matbase::FloatImage& counts, std::optional<int> samples,
                          std::vector<std::string>& problems) {
  size_t none = 0, beyond = 0;
  for (const float value : counts.values) {
    const long count = std::lround(value * static_cast<float>(kMaxSampleCount));
    if (count < 1) ++none;
    if (samples && count > *samples) ++beyond;
  }
  if (none > 0) problems.push_back(fmt::format("{}: {} pixels took no sample", file.string(), none));
  if (beyond > 0)
    problems.push_back(fmt::format("{}: {} pixels took more than the {} samples metadata.json states", file.string(),
                                   beyond, *samples));
}

// What is wrong with the size a map's header declares, against transforms.json's and what the
// file can hold; nothing when it matches or the header cannot be read (decoding then says why).
std::optional<std::string> declared_size_mismatch(const fs::path& file, int width, int height) {
  if (const std::optional<std::string> problem = matbase::declared_size_problem(file))
    return file.string() + ": " + *problem;
  const auto input = OIIO::ImageInput::open(file.string());
  if (!input) {
    OIIO::geterror();  // cleared: decode reports it
    return std::nullopt;
  }
  const OIIO::ImageSpec& spec = input->spec();
  if (spec.width == width && spec.height == height) return std::nullopt;
  return fmt::format("{}: declares {} x {} pixels, but transforms.json says the frames are {} x {}", file.string(),
                     spec.width, spec.height, width, height);
}

void verify_frame(const fs::path& folder, const std::string& stem, const VariantExpectations& expected,
                  const std::optional<CameraAxis>& camera, std::vector<std::string>& problems) {
  const int width = expected.width, height = expected.height;
  std::map<DatasetMap, matbase::FloatImage> maps;
  for (const DatasetMapInfo& info : dataset_maps()) {
    // Our own maps are checked where the variant has their folder: the repository's datasets
    // have none of them.
    if (!info.repository && !fs::is_directory(folder / info.folder) &&
        !(info.presence == MapPresence::WithSurroundings && expected.surroundings))
      continue;
    const fs::path file = folder / info.folder / (stem + info.extension);
    if (!fs::is_regular_file(file)) {
      problems.push_back(file.string() + ": missing");
      continue;
    }
    // The header first: a map declaring another size is not decoded (nor allocated for).
    if (const std::optional<std::string> problem = declared_size_mismatch(file, width, height)) {
      problems.push_back(*problem);
      continue;
    }
    matbase::FloatImage map;
    try {
      map = decode(file);
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
  const fs::path depth_file = folder / "depth" / (stem + ".exr"), label_file = folder / "label" / (stem + ".png");
  // Alone, every covered pixel is the object's; with surroundings only the label's are, so there
  // the depth is held to the object's bounds once the label is read (and not at all without it).
  if (depth != maps.end() && !expected.surroundings)
    verify_depth(depth_file, depth->second, expected.bounds, camera, nullptr, problems);
  const auto depth_without_label = [&] {
    if (depth != maps.end() && expected.surroundings)
      verify_depth(depth_file, depth->second, std::nullopt, camera, nullptr, problems);
  };
  if (label == maps.end()) return depth_without_label();
  // The ids as written, 8 or 16 bits (decoded as floats a 16-bit 7 would read as 0).
  DecodedIds ids;
  try {
    ids = decode_ids(label_file);
  } catch (const std::runtime_error& e) {
    problems.push_back(one_line(e.what()));
    return depth_without_label();
  }
  if (depth != maps.end() && expected.surroundings)
    verify_depth(depth_file, depth->second, expected.bounds, camera, &ids.ids, problems);
  // With surroundings the label is the target's alone: nonzero exactly where the region map says
  // the target is the first hit, while coverage, depth and ORM cover every surface.
  std::optional<DecodedIds> regions;
  const fs::path region_file = folder / "region" / (stem + ".png");
  if (maps.count(DatasetMap::Region)) {
    try {
      regions = decode_ids(region_file);
    } catch (const std::runtime_error& e) {
      problems.push_back(one_line(e.what()));
    }
  }
  std::set<int> found;
  size_t mask_disagreements = 0, region_disagreements = 0, unknown_regions = 0;
  for (size_t p = 0; p < ids.ids.size(); ++p) {
    const int id = ids.ids[p];
    found.insert(id);
    const bool object = id > 0;
    const bool covered = depth != maps.end() && depth->second.values[4 * p + 3] > 0.0f;
    const bool orm_alpha = orm != maps.end() && orm->second.values[4 * p + 3] > 0.0f;
    if (regions) {
      const int32_t region = regions->ids[p];
      if (region < 0 || region > static_cast<int32_t>(FrameRegion::Target)) {
        ++unknown_regions;
        continue;
      }
      const bool surface = region != static_cast<int32_t>(FrameRegion::Background);
      if (object != (region == static_cast<int32_t>(FrameRegion::Target)) ||
          (depth != maps.end() && surface != covered) || (orm != maps.end() && surface != orm_alpha))
        ++region_disagreements;
    } else if ((depth != maps.end() && object != covered) || (orm != maps.end() && object != orm_alpha)) {
      ++mask_disagreements;
    }
  }
  if (unknown_regions > 0)
    problems.push_back(fmt::format("{}: {} pixels hold a region that is none of 0 (background), 1 (surroundings) and "
                                   "2 (the target)",
                                   region_file.string(), unknown_regions));
  if (region_disagreements > 0)
    problems.push_back(fmt::format("{}: at {} pixels the label's object mask is not where the region map's first hit is "
                                   "the target, or a surface of the region map has no coverage in depth/ or ORM's alpha",
                                   label_file.string(), region_disagreements));
  if (found.size() == 1 && found.count(0))
    problems.push_back(label_file.string() + ": the object is in no pixel of the frame (is the camera too far, or "
                                             "looking away?)");
  for (const int id : found) {
    if (id == 0) continue;
    if (!matmaterial::material_class_of_label(id))
      problems.push_back(fmt::format("{}: label {} is no class of the table", label_file.string(), id));
    else if (!labels.count(id))
      problems.push_back(fmt::format("{}: label {} ({}) is not among the variant's used_materials", label_file.string(),
                                     id, matmaterial::label_name(id)));
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
  expected.bounds = stated_bounds(metadata);
  expected.surroundings = metadata.is_object() && metadata.contains(nlohmann::json::json_pointer("/provenance/surroundings"));
  verify_segmentation_json(folder / "material_segmentation_map.json", problems);
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
    verify_frame(folder, stem, expected, camera_axis(frame["transform_matrix"]), problems);
  }
}

// The counts a split file states beside its lists, read as written: a file edited by hand (or by
// a script that appended ids) states numbers its lists contradict.
void verify_split_counts(const fs::path& file, const SplitFile& split, std::vector<std::string>& problems) {
  YAML::Node counts;
  try {
    counts = YAML::LoadFile(file.string())["counts"];
  } catch (const YAML::Exception&) {
    return;  // read_split_file has parsed it; this cannot fail on the same text
  }
  if (!counts.IsDefined()) return;  // the repository's own files state counts; older ones may not
  if (!counts.IsMap()) {
    problems.push_back(file.string() + ": counts is not a mapping of train, val, test and total");
    return;
  }
  const size_t total = split.train.size() + split.val.size() + split.test.size();
  const std::vector<std::pair<std::string, size_t>> listed = {
      {"train", split.train.size()}, {"val", split.val.size()}, {"test", split.test.size()}, {"total", total}};
  for (const auto& [key, size] : listed) {
    const YAML::Node stated = counts[key];
    const std::string text = stated.IsScalar() ? stated.Scalar() : "";
    if (!stated.IsDefined() || text != std::to_string(size))
      problems.push_back(fmt::format("{}: counts.{} is {}, but its {} lists {} frames", file.string(), key,
                                     stated.IsDefined() ? (text.empty() ? "not a number" : text) : "missing",
                                     key == "total" ? "three" : key, size));
  }
}

// A split file lists frames of the dataset, each once, and every frame of the dataset: a frame in
// no list (of a second run's objects, say) is never trained or tested on.
void verify_split_file(const fs::path& file, const std::set<std::string>& ids, std::vector<std::string>& problems) {
  SplitFile split;
  try {
    split = read_split_file(file);
  } catch (const std::exception& e) {
    problems.push_back(one_line(e.what()));
    return;
  }
  std::set<std::string> listed;
  for (const std::vector<std::string>* list : {&split.train, &split.val, &split.test})
    for (const std::string& id : *list) {
      if (!ids.count(id)) problems.push_back(file.string() + ": lists " + id + ", no frame of the dataset");
      if (!listed.insert(id).second) problems.push_back(file.string() + ": lists " + id + " twice");
    }
  std::vector<std::string> unlisted;
  for (const std::string& id : ids)
    if (!listed.count(id)) unlisted.push_back(id);
  if (!unlisted.empty())
    problems.push_back(fmt::format("{}: {} frames of the dataset are in none of its lists (the first: {}); was a "
                                   "second run with other objects made into this folder?",
                                   file.string(), unlisted.size(), unlisted.front()));
  verify_split_counts(file, split, problems);
}

}  // namespace

VerifyReport verify_dataset(const fs::path& root) {
  const std::vector<fs::path> variants = variant_folders(root, "images");
  VerifyReport report;
  if (!fs::is_regular_file(root / kSegmentationMapFile))
    report.problems.push_back((root / kSegmentationMapFile).string() + ": missing");
  else
    verify_segmentation_yaml(root / kSegmentationMapFile, report.problems);
  std::set<std::string> ids;
  for (const fs::path& variant : variants) verify_variant(variant, report, ids);
  for (const char* name : kSplitFiles)
    if (!fs::is_regular_file(root / kConfigFolder / name))
      report.problems.push_back((root / kConfigFolder / name).string() + ": missing");
  if (fs::is_directory(root / kConfigFolder))
    for (const fs::directory_entry& entry : fs::directory_iterator(root / kConfigFolder))
      if (entry.path().extension() == ".yaml") verify_split_file(entry.path(), ids, report.problems);
  return report;
}

}  // namespace matdataset
