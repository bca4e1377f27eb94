#pragma once
// train_regressor's settings: built-in defaults (the paper's protocol), then a YAML file shaped
// like the MatPredict repository's training template, then command-line options, each overriding
// the one before. Errors name the file or option and the key.
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "matbase/input_error.h"
#include "matlearn/training/trainer.h"

namespace train_regressor {

struct Options {
  std::filesystem::path config_file;
  std::map<std::string, std::string> command_line;  // key -> value given on the command line
  bool describe = false;
  bool resume = false;
};

// Registers every setting as --<key with dashes> on `app`, storing into `options`.
void add_options(CLI::App& app, Options& options);

// The settings after defaults, the YAML file and the command line, as key -> text.
std::map<std::string, std::string> resolve_settings(const Options& options);

// The training configuration those settings describe: the output layout, the optimiser and, with
// with_dataset, the dataset indexed and split. Throws matbase::InputError.
matlearn::TrainingConfig training_config(const std::map<std::string, std::string>& settings, bool with_dataset);

// The settings as a YAML document (written beside the outputs as config.yaml).
std::string settings_yaml(const std::map<std::string, std::string>& settings);

}  // namespace train_regressor
