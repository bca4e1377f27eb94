#include "training_options.h"

#include <algorithm>
#include <filesystem>
#include <optional>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include <fmt/format.h>

#include "common/number_options.h"
#include "matbase/document/document_node.h"
#include "matbase/document/yaml_document.h"
#include "matdataset/format/sample_loader.h"

namespace train_regressor {
namespace {

// The values a numeric setting takes, stated in --help and in every refusal.
struct Range {
  enum class Kind { none, whole, real, seed } kind = Kind::none;
  double low = 0.0;
  double high = 0.0;
  bool low_open = false;  // real: low itself is excluded
};
Range whole(int64_t low, int64_t high) { return {Range::Kind::whole, double(low), double(high), false}; }
Range real(double low, double high) { return {Range::Kind::real, low, high, false}; }
Range real_above(double low, double high) { return {Range::Kind::real, low, high, true}; }
Range any_seed() { return {Range::Kind::seed, 0.0, 0.0, false}; }

// Upper limits of no physical meaning, there to catch typos before they cost a day: a loss weight,
// a learning rate, epochs, schedule periods.
constexpr double kMaxLossWeight = 1000.0;
constexpr double kMaxLearningRate = 10.0;
constexpr int64_t kMaxEpochs = 100000;
// Label maps are 16-bit PNGs: ids 0..65535.
constexpr int64_t kMaxMaterialClasses = 65536;
constexpr int64_t kMaxImageSize = 4096;

struct Setting {
  const char* key;  // the YAML key; the option is --key with dashes
  const char* default_value;
  const char* help;
  Range range = {};
};

// An empty default for the optimiser settings means the paper's choice for the network: AdamW
// 1e-4 with weight decay 1e-2 for Swin-T, Adam 2e-4 for the others.
const std::vector<Setting>& settings_table() {
  static const std::vector<Setting> table = {
      {"dataset_root", "", "dataset folder in the MatPredict layout (<object>/<variant>/{images,albedo,ORM,label})"},
      {"split_file", "", "split YAML with train and val lists (the repository's); none: 80/20 by variant folder"},
      {"model_name", "unet_no_skip",
       "network: unet_no_skip, resnet50_u, swin_t_u, convnext_t_u, repo_resnet50_unet (alias resnet50_unet), "
       "repo_swin_t_unet (alias swin_t_unet)"},
      {"width_divisor", "1", "divide unet_no_skip's channel widths by this (4: a quick 1.5M-parameter network)", whole(1, 32)},
      {"encoder_weights", "", "torchvision weights converted by scripts/convert_torchvision_weights.py, for the trunk"},
      {"output_dir", "train_output", "folder for checkpoints/, log.csv and config.yaml"},
      {"task_mode", "pbr", "pbr (material maps), material (segmentation only) or both"},
      {"outputs", "base_color,roughness:3",
       "predicted maps with channel counts, in order: base_color, roughness[:1|3], metallic[:1|3], normal "
       "(normal reads the dataset's normal_obj maps)"},
      {"albedo_weight", "1", "loss weight of the base colour", real(0, kMaxLossWeight)},
      {"roughness_weight", "1", "loss weight of the roughness", real(0, kMaxLossWeight)},
      {"metallic_weight", "1", "loss weight of the metallic map", real(0, kMaxLossWeight)},
      {"normal_weight", "1", "loss weight of the normal map", real(0, kMaxLossWeight)},
      {"material_num_classes", "8", "segmentation classes (the repository's 8 families, 0 = background)", whole(0, kMaxMaterialClasses)},
      {"material_ce_weight", "1", "loss weight of the segmentation cross-entropy", real(0, kMaxLossWeight)},
      {"loss", "mse", "regression loss: mse (the paper's) or l1 (the repository's)"},
      {"linear_albedo", "false", "supervise the albedo decoded from sRGB to linear values"},
      {"optimizer_name", "", "adam or adamw (default: the paper's for the network)"},
      {"lr", "", "initial learning rate (default: the paper's, 2e-4, or 1e-4 for Swin-T)", real_above(0, kMaxLearningRate)},
      {"weight_decay", "", "weight decay (default: the paper's, 0, or 1e-2 for Swin-T)", real(0, kMaxLearningRate)},
      {"schedule", "step", "learning-rate schedule: step, cosine or plateau"},
      {"step_size", "20", "step schedule: epochs between reductions", whole(1, kMaxEpochs)},
      {"gamma", "0.5", "step and plateau schedules: reduction factor", real_above(0, 1)},
      {"t_max", "50", "cosine schedule: half period in epochs", whole(1, kMaxEpochs)},
      {"patience", "5", "plateau schedule: epochs without improvement before a reduction", whole(0, kMaxEpochs)},
      {"epochs", "50", "epochs to train", whole(1, kMaxEpochs)},
      {"batch_size", "8", "samples per step", whole(1, app_support::kMaxBatchSize)},
      {"image_size", "224", "side the samples are resized to", whole(1, kMaxImageSize)},
      {"threads", "0", "torch and decoding threads (0: all cores, more are capped to them; libtorch alone would use 1)", whole(0, app_support::kMaxThreadRequest)},
      {"seed", "42", "seed of the initial weights, the split and the sample order", any_seed()},
      {"validate_every", "1", "epochs between validations (the last epoch is always validated)", whole(1, kMaxEpochs)},
      {"pretrained_model", "", "checkpoint to continue from (as the repository's option)"},
  };
  return table;
}

// Keys of the repository's training template that have no effect here; accepted so that its
// files load, and named when set.
const std::vector<std::string>& ignored_repository_keys() {
  static const std::vector<std::string> keys = {
      "num_workers", "num_vis_samples", "val_vis_ids_file", "optimizer_momentum", "material_weight",
      "material_map_file", "material_ignore_background", "no_pretrained", "use_wandb", "wandb_project",
      "wandb_run_name", "append_timestamp", "timestamp_format", "log_path"};
  return keys;
}

std::string option_name(const std::string& key) {
  std::string name = key;
  std::replace(name.begin(), name.end(), '_', '-');
  return "--" + name;
}

const Setting& setting_named(const std::string& key) {
  for (const Setting& setting : settings_table())
    if (setting.key == key) return setting;
  throw std::logic_error("no setting " + key);
}

// The range as --help states it: "[1, 100000]", "(0, 10]".
std::string range_text(const Range& r) {
  switch (r.kind) {
    case Range::Kind::none: return "";
    case Range::Kind::whole: return fmt::format("[{:.0f}, {:.0f}]", r.low, r.high);
    case Range::Kind::real: return fmt::format("{}{:g}, {:g}]", r.low_open ? "(" : "[", r.low, r.high);
    case Range::Kind::seed: return "[0, 2^64 - 1]";
  }
  return "";
}

int64_t whole_setting(const std::map<std::string, std::string>& s, const std::string& key) {
  const Range& r = setting_named(key).range;
  const std::string& text = s.at(key);
  if (const auto problem =
          matbase::whole_number_problem(text, static_cast<int64_t>(r.low), static_cast<int64_t>(r.high)))
    throw matbase::InputError(key + ": " + *problem);
  return *matbase::whole_number(text);
}

int int_setting(const std::map<std::string, std::string>& s, const std::string& key) {
  return static_cast<int>(whole_setting(s, key));  // every int setting's range fits an int
}

double number_setting(const std::map<std::string, std::string>& s, const std::string& key) {
  const Range& r = setting_named(key).range;
  const std::string& text = s.at(key);
  if (const auto problem = matbase::number_problem(text, r.low, r.high, r.low_open))
    throw matbase::InputError(key + ": " + *problem);
  return *matbase::finite_number(text);
}

uint64_t seed_setting(const std::map<std::string, std::string>& s, const std::string& key) {
  const std::string& text = s.at(key);
  if (const auto problem = matbase::seed_problem(text)) throw matbase::InputError(key + ": " + *problem);
  return *matbase::unsigned_whole_number(text);
}

bool parse_bool(const std::map<std::string, std::string>& s, const std::string& key) {
  const std::string& text = s.at(key);
  if (text == "true" || text == "1" || text == "yes") return true;
  if (text == "false" || text == "0" || text == "no") return false;
  throw matbase::InputError(key + ": expected true or false, got \"" + text + "\"");
}

std::string network_name(const std::string& name) {
  if (name == "resnet50_unet") return "repo_resnet50_unet";
  if (name == "swin_t_unet") return "repo_swin_t_unet";
  return name;
}

// "base_color,roughness:3,metallic" with the weights of the *_weight keys (the repository's
// albedo_weight for the base colour).
std::vector<matlearn::OutputGroup> output_groups(const std::map<std::string, std::string>& s) {
  std::vector<matlearn::OutputGroup> groups;
  std::istringstream list(s.at("outputs"));
  for (std::string entry; std::getline(list, entry, ',');) {
    const size_t colon = entry.find(':');
    const std::string name = entry.substr(0, colon);
    matlearn::MapKind map;
    try {
      map = matlearn::map_kind_named(name);
    } catch (const std::invalid_argument& e) {
      throw matbase::InputError(std::string("outputs: ") + e.what());
    }
    int64_t channels = matlearn::is_colour_map(map) ? 3 : 1;
    if (colon != std::string::npos) {
      const std::string count = entry.substr(colon + 1);
      if (count != "1" && count != "3") throw matbase::InputError("outputs: \"" + entry + "\": channels must be 1 or 3");
      channels = std::stoi(count);
    }
    const std::string weight_key = map == matlearn::MapKind::base_color ? "albedo_weight" : name + "_weight";
    groups.push_back({map, channels, number_setting(s, weight_key)});
  }
  return groups;
}

}  // namespace

void add_options(CLI::App& app, Options& options) {
  app.add_option("-c,--config", options.config_file, "YAML settings (keys as the options without dashes)")
      ->check(CLI::ExistingFile);
  app.add_flag("--describe", options.describe, "print the networks' parameter counts for these outputs and exit");
  app.add_flag("--resume", options.resume, "continue from <output_dir>/checkpoints/last.pt");
  for (const Setting& setting : settings_table()) {
    const std::string key = setting.key;
    std::string help = setting.help;
    if (setting.range.kind != Range::Kind::none) help += ", in " + range_text(setting.range);
    if (*setting.default_value) help += " [default " + std::string(setting.default_value) + "]";
    const bool integer = setting.range.kind == Range::Kind::whole || setting.range.kind == Range::Kind::seed;
    app.add_option_function<std::string>(
           option_name(key), [&options, key](const std::string& value) { options.command_line[key] = value; }, help)
        ->type_name(integer ? "INT" : setting.range.kind == Range::Kind::real ? "FLOAT" : "TEXT");
  }
}

std::map<std::string, std::string> resolve_settings(const Options& options) {
  std::map<std::string, std::string> settings;
  for (const Setting& setting : settings_table()) settings[setting.key] = setting.default_value;
  if (!options.config_file.empty()) {
    const std::string file = options.config_file.string();
    YAML::Node root;
    try {
      root = YAML::LoadFile(file);
    } catch (const YAML::Exception& e) {
      throw matbase::InputError(file + ": not valid YAML: " + e.what());
    }
    if (!root.IsMap()) throw matbase::InputError(file + ": expected a mapping of settings");
    // Refuses a repeated key, of which yaml-cpp keeps both entries and this loop would take the last.
    const matbase::DocumentValue document = matbase::yaml_document_value(root, file);
    const matbase::DocumentSource source(file, matbase::PathStyle::DottedKeys);
    for (const auto& [key, value] : matbase::DocumentNode(document, source).members()) {
      const bool ignored = std::count(ignored_repository_keys().begin(), ignored_repository_keys().end(), key) > 0;
      if (ignored) continue;
      if (!settings.count(key)) value.fail("unknown key (the settings are train_regressor's options, --help)");
      if (!value.is_null() && !value.is_text()) value.fail_expected("a single value");
      settings[key] = value.is_null() ? "" : value.text();
    }
  }
  for (const auto& [key, value] : options.command_line) settings[key] = value;
  // Paths as absolute ones, relative to the folder the command runs in as given: the config.yaml
  // a run saves then works from any folder, with the resume command it prints.
  for (const char* key : {"dataset_root", "split_file", "encoder_weights", "output_dir", "pretrained_model"})
    if (!settings[key].empty())
      settings[key] = std::filesystem::absolute(settings[key]).lexically_normal().string();
  // The paper's optimiser for the network, where none was chosen.
  const bool swin = network_name(settings["model_name"]) == "swin_t_u";
  if (settings["optimizer_name"].empty()) settings["optimizer_name"] = swin ? "adamw" : "adam";
  if (settings["lr"].empty()) settings["lr"] = swin ? "1e-4" : "2e-4";
  if (settings["weight_decay"].empty()) settings["weight_decay"] = swin ? "1e-2" : "0";
  return settings;
}

matlearn::TrainingConfig training_config(const std::map<std::string, std::string>& s, bool with_dataset) {
  matlearn::TrainingConfig c;
  try {
    c.network = network_name(s.at("model_name"));
    const matlearn::Architecture architecture = matlearn::architecture_named(c.network).architecture;
    c.width_divisor = whole_setting(s, "width_divisor");
    if (const auto problem = matlearn::width_divisor_problem(architecture, c.width_divisor))
      throw matbase::InputError("width_divisor: " + *problem);
    c.encoder_weights = s.at("encoder_weights");
    c.output_dir = s.at("output_dir");
    const std::string task = s.at("task_mode");
    if (task != "pbr" && task != "material" && task != "both")
      throw matbase::InputError("task_mode: expected pbr, material or both, got \"" + task + "\"");
    if (task != "material") c.layout.groups = output_groups(s);
    else c.layout.groups.clear();
    if (task != "pbr") {
      c.layout.material_classes = whole_setting(s, "material_num_classes");
      // A segmentation task needs a background and one class at least; 0 would train nothing.
      if (c.layout.material_classes < 2)
        throw matbase::InputError("material_num_classes: task_mode " + task + " needs at least 2 classes (0 is the background), got " +
                         std::to_string(c.layout.material_classes));
      c.layout.material_weight = number_setting(s, "material_ce_weight");
    }
    matlearn::validate(c.layout);
    const std::string loss = s.at("loss");
    if (loss != "mse" && loss != "l1") throw matbase::InputError("loss: expected mse or l1, got \"" + loss + "\"");
    c.loss = loss == "mse" ? matlearn::RegressionLoss::mse : matlearn::RegressionLoss::l1;
    c.linear_albedo = parse_bool(s, "linear_albedo");
    c.optimizer = matlearn::optimizer_kind_named(s.at("optimizer_name"));
    c.learning_rate = number_setting(s, "lr");
    c.weight_decay = number_setting(s, "weight_decay");
    c.schedule.kind = matlearn::schedule_kind_named(s.at("schedule"));
    c.schedule.step_size = int_setting(s, "step_size");
    c.schedule.gamma = number_setting(s, "gamma");
    c.schedule.t_max = int_setting(s, "t_max");
    c.schedule.patience = int_setting(s, "patience");
    c.epochs = int_setting(s, "epochs");
    c.batch_size = int_setting(s, "batch_size");
    c.image_size = int_setting(s, "image_size");
    c.threads = int_setting(s, "threads");
    c.seed = seed_setting(s, "seed");
    c.validate_every = int_setting(s, "validate_every");
  } catch (const std::invalid_argument& e) {
    throw matbase::InputError(e.what());
  }
  c.config_text = settings_yaml(s);
  if (!with_dataset) return c;
  if (s.at("dataset_root").empty()) throw matbase::InputError("no dataset: give --dataset-root or dataset_root in --config");
  c.dataset_root = s.at("dataset_root");
  try {
    if (!s.at("split_file").empty()) {
      const matdataset::SplitFile split = matdataset::read_split_file(s.at("split_file"));
      c.train_samples = matdataset::split_samples(split, "train", c.dataset_root);
      c.validation_samples = matdataset::split_samples(split, "val", c.dataset_root);
      if (c.train_samples.empty()) throw matbase::InputError(s.at("split_file") + ": its train list is empty");
    } else {
      const std::vector<matdataset::SampleId> all = matdataset::index_dataset(c.dataset_root);
      if (all.empty()) throw matbase::InputError(c.dataset_root.string() + ": no samples in the MatPredict layout");
      const auto parts = matdataset::split_by_variant(all, matdataset::SplitRatios{}, c.seed);
      c.train_samples = parts[0];
      c.validation_samples = parts[1];
    }
  } catch (const std::runtime_error& e) {
    if (dynamic_cast<const matbase::InputError*>(&e)) throw;
    throw matbase::InputError(e.what());
  }
  return c;
}

std::string settings_yaml(const std::map<std::string, std::string>& settings) {
  YAML::Emitter out;
  out << YAML::BeginMap;
  for (const Setting& setting : settings_table()) out << YAML::Key << setting.key << YAML::Value << settings.at(setting.key);
  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

}  // namespace train_regressor
