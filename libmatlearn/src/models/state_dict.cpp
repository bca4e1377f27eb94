#include "matlearn/models/state_dict.h"

#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "matbase/file/atomic_file.h"
#include "matbase/file/input_file.h"
#include "models/torch_error.h"

namespace matlearn {
namespace {

std::map<std::string, torch::Tensor> named_state(const torch::nn::Module& module) {
  std::map<std::string, torch::Tensor> state;
  for (const auto& p : module.named_parameters()) state[p.key()] = p.value();
  for (const auto& b : module.named_buffers()) state[b.key()] = b.value();
  return state;
}

std::string shape_of(const torch::Tensor& t) {
  std::ostringstream s;
  s << t.sizes();
  return s.str();
}

}  // namespace

std::map<std::string, torch::Tensor> read_state_dict(const std::filesystem::path& path) {
  matbase::require_input_file(path.string());
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open " + path.string());
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  torch::IValue value;
  try {
    value = torch::pickle_load(bytes);
  } catch (const std::exception& e) {
    throw std::runtime_error(path.string() + " is not a file torch.save wrote: " + torch_error_text(e));
  }
  if (!value.isGenericDict()) throw std::runtime_error(path.string() + " does not hold a dict of tensors");
  std::map<std::string, torch::Tensor> loaded;
  for (const auto& entry : value.toGenericDict()) {
    if (!entry.key().isString() || !entry.value().isTensor())
      throw std::runtime_error(path.string() + " holds an entry that is not name -> tensor");
    loaded[entry.key().toStringRef()] = entry.value().toTensor();
  }
  return loaded;
}

void load_state_dict(torch::nn::Module& module, const std::map<std::string, torch::Tensor>& loaded, const std::string& source) {
  std::map<std::string, torch::Tensor> state = named_state(module);
  std::vector<std::string> problems;
  for (const auto& [name, tensor] : state) {
    const auto it = loaded.find(name);
    if (it == loaded.end())
      problems.push_back("missing " + name);
    else if (it->second.sizes() != tensor.sizes())
      problems.push_back(name + " is " + shape_of(it->second) + " in the file, " + shape_of(tensor) + " in the model");
  }
  for (const auto& entry : loaded)
    if (state.find(entry.first) == state.end()) problems.push_back("unexpected " + entry.first);
  if (!problems.empty()) {
    std::string message = source + " does not fit the model:";
    for (size_t i = 0; i < problems.size() && i < 10; ++i) message += "\n  " + problems[i];
    if (problems.size() > 10) message += "\n  ... and " + std::to_string(problems.size() - 10) + " more";
    throw std::runtime_error(message);
  }
  torch::NoGradGuard no_grad;
  for (auto& [name, tensor] : state) tensor.copy_(loaded.at(name));
}

void load_state_dict(torch::nn::Module& module, const std::filesystem::path& path) {
  load_state_dict(module, read_state_dict(path), path.string());
}

void save_state_dict(const torch::nn::Module& module, const std::filesystem::path& path) {
  c10::Dict<std::string, torch::Tensor> dict;
  for (const auto& [name, tensor] : named_state(module)) dict.insert(name, tensor.detach().contiguous());
  const std::vector<char> bytes = torch::pickle_save(dict);
  matbase::write_file_atomically(path, std::string_view(bytes.data(), bytes.size()));
}

}  // namespace matlearn
