#include "matdataset/format/dataset_index.h"

#include <algorithm>
#include <functional>
#include <map>
#include <stdexcept>

#include <yaml-cpp/yaml.h>

#include "matdataset/format/dataset_error.h"
#include "matdataset/format/sample_reader.h"

namespace matdataset {
namespace {

namespace fs = std::filesystem;

// The paper's layout: the screenshots' folder.
constexpr const char* kScreenshots = "rendered_cropped";

std::vector<fs::path> sorted_subdirectories(const fs::path& dir) {
  std::vector<fs::path> dirs;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir))
    if (entry.is_directory() && entry.path().filename().string().rfind("_tmp", 0) != 0) dirs.push_back(entry.path());
  std::sort(dirs.begin(), dirs.end());
  return dirs;
}

std::vector<std::string> sorted_png_stems(const fs::path& dir) {
  std::vector<std::string> stems;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir))
    if (entry.is_regular_file() && entry.path().extension() == ".png") stems.push_back(entry.path().stem().string());
  std::sort(stems.begin(), stems.end());
  return stems;
}

// Every PNG in the folders `frames_folder` names under each <object>/<variant>/ of `top`, as a
// sample: the images/ of the repository's variants, the screenshots of the paper's materials.
std::vector<SampleId> frames_under(const fs::path& top, const std::function<fs::path(const fs::path&)>& frames_folder) {
  std::vector<SampleId> samples;
  for (const fs::path& object : sorted_subdirectories(top))
    for (const fs::path& variant : sorted_subdirectories(object)) {
      const fs::path folder = frames_folder(variant);
      if (!fs::is_directory(folder)) continue;  // not a variant: it has no frames to miss
      for (const std::string& stem : sorted_png_stems(folder))
        samples.push_back({object.filename().string(), variant.filename().string(), stem});
    }
  return samples;
}

void require_dataset_root(const fs::path& root) {
  if (!fs::is_directory(root)) throw DatasetError("dataset root " + root.string() + " is not a directory");
}

DatasetError split_file_error(const fs::path& path, const std::string& problem) {
  return DatasetError("split file " + path.string() + ": " + problem);
}

// The ids of list `key`, each a well-formed sample id.
std::vector<std::string> split_list(const YAML::Node& root, const char* key, const fs::path& path) {
  const YAML::Node node = root[key];
  if (!node || !node.IsSequence()) throw split_file_error(path, std::string("'") + key + "' is missing or not a list");
  std::vector<std::string> ids;
  for (const YAML::Node& item : node) {
    if (!item.IsScalar()) throw split_file_error(path, std::string("an entry of '") + key + "' is not a string");
    ids.push_back(item.as<std::string>());
    try {
      SampleId::parse(ids.back());
    } catch (const std::invalid_argument& e) {
      throw split_file_error(path, std::string("'") + key + "': " + e.what());
    }
  }
  return ids;
}

// A sample in two places would be counted twice, or trained on and then scored as unseen.
void require_listed_once(const SplitFile& file) {
  std::map<std::string, const char*> list_of;
  for (const auto& [key, ids] : {std::pair{"train", &file.train}, {"val", &file.val}, {"test", &file.test}})
    for (const std::string& id : *ids) {
      const auto [it, added] = list_of.emplace(id, key);
      if (!added)
        throw split_file_error(file.path, "lists " + id + " twice (" +
                                              (it->second == key ? std::string("in ") + key
                                                                 : std::string("in ") + it->second + " and in " + key) +
                                              "); each sample belongs in one list, once");
    }
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
  require_dataset_root(root);
  const std::vector<SampleId> samples =
      dataset_layout(root) == DatasetLayout::paper_textures
          ? frames_under(root / kScreenshots, [](const fs::path& material) { return material; })
          : frames_under(root, [](const fs::path& variant) { return variant / "images"; });
  require_sample_files(root, samples, SampleSettings{}, root.string());
  return samples;
}

SplitFile read_split_file(const fs::path& path) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(path.string());
  } catch (const YAML::Exception& e) {
    throw split_file_error(path, e.what());
  }
  if (!root.IsMap()) throw split_file_error(path, "not a YAML mapping");
  SplitFile file;
  file.path = path;
  try {
    if (root["name"]) file.name = root["name"].as<std::string>();
    if (root["strategy"]) file.strategy = root["strategy"].as<std::string>();
    if (root["seed"]) file.seed = root["seed"].as<int64_t>();
  } catch (const YAML::Exception& e) {
    throw split_file_error(path, e.what());
  }
  file.train = split_list(root, "train", path);
  file.val = split_list(root, "val", path);
  file.test = split_list(root, "test", path);
  require_listed_once(file);
  return file;
}

std::vector<SampleId> split_samples(const SplitFile& file, const std::string& split, const fs::path& root) {
  const std::vector<std::string>* ids = split == "train" ? &file.train
                                        : split == "val" ? &file.val
                                        : split == "test" ? &file.test
                                                          : nullptr;
  if (!ids) throw std::invalid_argument("split '" + split + "' is not train, val or test");
  require_dataset_root(root);
  std::vector<SampleId> samples;
  samples.reserve(ids->size());
  for (const std::string& id : *ids) samples.push_back(SampleId::parse(id));
  const std::string source = !file.path.empty() ? file.path.string() : file.name.empty() ? "the split" : file.name;
  require_sample_files(root, samples, SampleSettings{}, "the " + split + " list of " + source);
  return samples;
}

}  // namespace matdataset
