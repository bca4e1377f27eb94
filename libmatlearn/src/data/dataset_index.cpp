#include "matlearn/dataset_index.h"

#include <algorithm>
#include <stdexcept>

#include <yaml-cpp/yaml.h>

namespace matlearn {
namespace {

namespace fs = std::filesystem;

// The maps a frame needs to count as a sample (the loader's rule).
constexpr const char* kRequiredMaps[] = {"images", "albedo", "ORM"};
// The paper's layout: the screenshots' folder, and the reference maps a material needs.
constexpr const char* kScreenshots = "rendered_cropped";
constexpr const char* kRequiredReferences[] = {"ground_truth_basecolour", "ground_truth_roughness"};

std::vector<fs::path> sorted_subdirectories(const fs::path& dir) {
  std::vector<fs::path> dirs;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir))
    if (entry.is_directory() && entry.path().filename().string().rfind("_tmp", 0) != 0) dirs.push_back(entry.path());
  std::sort(dirs.begin(), dirs.end());
  return dirs;
}

bool frame_complete(const fs::path& variant_dir, const std::string& stem) {
  return std::all_of(std::begin(kRequiredMaps), std::end(kRequiredMaps),
                     [&](const char* map) { return fs::is_regular_file(variant_dir / map / (stem + ".png")); });
}

bool material_complete(const fs::path& root, const std::string& material) {
  return std::all_of(std::begin(kRequiredReferences), std::end(kRequiredReferences),
                     [&](const char* map) { return fs::is_regular_file(root / map / (material + ".png")); });
}

bool sample_complete(const fs::path& root, DatasetLayout layout, const SampleId& id) {
  if (layout == DatasetLayout::paper_textures)
    return material_complete(root, id.variant) &&
           fs::is_regular_file(root / kScreenshots / id.object / id.variant / (id.stem + ".png"));
  return frame_complete(root / id.object / id.variant, id.stem);
}

std::vector<std::string> sorted_png_stems(const fs::path& dir) {
  std::vector<std::string> stems;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir))
    if (entry.is_regular_file() && entry.path().extension() == ".png") stems.push_back(entry.path().stem().string());
  std::sort(stems.begin(), stems.end());
  return stems;
}

std::vector<SampleId> index_paper_layout(const fs::path& root) {
  std::vector<SampleId> samples;
  for (const fs::path& object : sorted_subdirectories(root / kScreenshots))
    for (const fs::path& material : sorted_subdirectories(object)) {
      if (!material_complete(root, material.filename().string())) continue;
      for (const std::string& stem : sorted_png_stems(material))
        samples.push_back({object.filename().string(), material.filename().string(), stem});
    }
  return samples;
}

}  // namespace

SampleId SampleId::parse(const std::string& id) {
  const size_t first = id.find('/'), second = first == std::string::npos ? first : id.find('/', first + 1);
  if (first == 0 || second == std::string::npos || second == first + 1 || second + 1 >= id.size() ||
      id.find('/', second + 1) != std::string::npos)
    throw std::invalid_argument("sample id '" + id + "' is not <object>/<variant>/<stem>");
  return {id.substr(0, first), id.substr(first + 1, second - first - 1), id.substr(second + 1)};
}

DatasetLayout dataset_layout(const fs::path& root) {
  return fs::is_directory(root / kScreenshots) ? DatasetLayout::paper_textures : DatasetLayout::repository;
}

std::vector<SampleId> index_dataset(const fs::path& root) {
  if (!fs::is_directory(root)) throw std::runtime_error("dataset root " + root.string() + " is not a directory");
  if (dataset_layout(root) == DatasetLayout::paper_textures) return index_paper_layout(root);
  std::vector<SampleId> samples;
  for (const fs::path& object : sorted_subdirectories(root)) {
    for (const fs::path& variant : sorted_subdirectories(object)) {
      if (!std::all_of(std::begin(kRequiredMaps), std::end(kRequiredMaps),
                       [&](const char* map) { return fs::is_directory(variant / map); }))
        continue;
      for (const std::string& stem : sorted_png_stems(variant / "images"))
        if (frame_complete(variant, stem))
          samples.push_back({object.filename().string(), variant.filename().string(), stem});
    }
  }
  return samples;
}

SplitFile read_split_file(const fs::path& path) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(path.string());
  } catch (const YAML::Exception& e) {
    throw std::runtime_error("split file " + path.string() + ": " + e.what());
  }
  if (!root.IsMap()) throw std::runtime_error("split file " + path.string() + ": not a YAML mapping");
  SplitFile file;
  const auto list = [&](const char* key) {
    const YAML::Node node = root[key];
    if (!node || !node.IsSequence())
      throw std::runtime_error("split file " + path.string() + ": '" + key + "' is missing or not a list");
    std::vector<std::string> ids;
    for (const YAML::Node& item : node) {
      if (!item.IsScalar())
        throw std::runtime_error("split file " + path.string() + ": an entry of '" + key + "' is not a string");
      ids.push_back(item.as<std::string>());
    }
    return ids;
  };
  try {
    if (root["name"]) file.name = root["name"].as<std::string>();
    if (root["strategy"]) file.strategy = root["strategy"].as<std::string>();
    if (root["seed"]) file.seed = root["seed"].as<int64_t>();
  } catch (const YAML::Exception& e) {
    throw std::runtime_error("split file " + path.string() + ": " + e.what());
  }
  file.train = list("train");
  file.val = list("val");
  file.test = list("test");
  return file;
}

std::vector<SampleId> split_samples(const SplitFile& file, const std::string& split, const fs::path& root) {
  const std::vector<std::string>* ids = split == "train" ? &file.train
                                        : split == "val" ? &file.val
                                        : split == "test" ? &file.test
                                                          : nullptr;
  if (!ids) throw std::invalid_argument("split '" + split + "' is not train, val or test");
  std::vector<SampleId> samples;
  samples.reserve(ids->size());
  const DatasetLayout layout = dataset_layout(root);
  for (const std::string& id : *ids) {
    const SampleId sample = SampleId::parse(id);
    if (!sample_complete(root, layout, sample))
      throw std::runtime_error("split '" + split + "' of " + (file.name.empty() ? "the split file" : file.name) +
                               " lists " + id + ", whose maps are not all under " + root.string());
    samples.push_back(sample);
  }
  return samples;
}

}  // namespace matlearn
