#pragma once
// Encoders against torchvision (tests/learn/torchvision_encoder.py run by Debian's
// python3-torchvision): the same parameter and buffer names, shapes and count, and with the same
// weights, converted by scripts/convert_torchvision_weights.py as a user would, the same stage
// outputs. Include after catch.hpp with CATCH_CONFIG_PREFIX_ALL (torch tests).
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <torch/torch.h>

#include "matlearn/models/state_dict.h"

namespace torchvision_reference {

inline void run(const std::string& command) {
  if (std::system(command.c_str()) != 0) throw std::runtime_error(command + " failed (needs Debian's python3-torchvision)");
}

// The folder holding names.txt, torchvision.pth, io.pt and the converted weights.pt of
// torchvision's `model`; made once per test run.
inline std::filesystem::path folder(const std::string& model) {
  static std::map<std::string, std::filesystem::path> made;
  if (made.count(model)) return made[model];
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("matpredict_" + model + "_reference");
  std::filesystem::create_directories(dir);
  const std::string python = MATPREDICT_DEBIAN_PYTHON;
  run(python + " " + MATPREDICT_ENCODER_SCRIPT + " " + model + " " + dir.string());
  run(python + " " + MATPREDICT_CONVERT_SCRIPT + " " + model + " " + (dir / "torchvision.pth").string() + " " +
      (dir / "weights.pt").string() + " > /dev/null");
  return made[model] = dir;
}

// "(64,3,7,7)", "()" for a scalar: the format of names.txt.
inline std::string shape_text(const torch::Tensor& t) {
  std::string s = "(";
  for (int64_t i = 0; i < t.dim(); ++i) s += (i ? "," : "") + std::to_string(t.size(i));
  return s + ")";
}

inline std::map<std::string, torch::Tensor> tensors_in(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::map<std::string, torch::Tensor> tensors;
  for (const auto& e : torch::pickle_load(bytes).toGenericDict()) tensors[e.key().toStringRef()] = e.value().toTensor();
  return tensors;
}

inline void check_names_and_count(const torch::nn::Module& encoder, const std::string& model, size_t expected_tensors,
                                  int64_t expected_parameters) {
  std::map<std::string, std::string> reference;
  std::ifstream names(folder(model) / "names.txt");
  std::string name, shape;
  while (names >> name >> shape) reference[name] = shape;
  CATCH_REQUIRE(reference.size() == expected_tensors);
  std::map<std::string, std::string> ours;
  int64_t parameters = 0;
  for (const auto& p : encoder.named_parameters()) {
    ours[p.key()] = shape_text(p.value());
    parameters += p.value().numel();
  }
  for (const auto& b : encoder.named_buffers()) ours[b.key()] = shape_text(b.value());
  CATCH_CHECK(ours == reference);
  CATCH_CHECK(parameters == expected_parameters);
}

// Loads the converted torchvision weights into `encoder` and compares `stages` (name -> our
// output for io.pt's input, computed by `run_encoder`) with torchvision's within 1e-4 of the
// larger of 1 and the largest magnitude.
template <class Encoder, class RunEncoder>
void check_stage_outputs(Encoder& encoder, const std::string& model, RunEncoder run_encoder) {
  const std::filesystem::path dir = folder(model);
  matlearn::load_state_dict(*encoder, dir / "weights.pt");
  encoder->eval();
  std::map<std::string, torch::Tensor> io = tensors_in(dir / "io.pt");
  torch::NoGradGuard no_grad;
  const std::vector<std::pair<std::string, torch::Tensor>> stages = run_encoder(io.at("input"));
  CATCH_REQUIRE(stages.size() + 1 == io.size());
  for (const auto& [stage, ours] : stages) {
    const torch::Tensor& theirs = io.at(stage);
    CATCH_REQUIRE(ours.sizes() == theirs.sizes());
    const double scale = std::max(1.0, theirs.abs().max().item<double>());
    const double difference = (ours - theirs).abs().max().template item<double>();
    CATCH_INFO(model << " " << stage << ": largest difference " << difference << " for values up to " << scale);
    CATCH_CHECK(difference <= 1e-4 * scale);
  }
}

}  // namespace torchvision_reference
