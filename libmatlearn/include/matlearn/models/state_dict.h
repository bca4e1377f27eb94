#pragma once
// Parameters and buffers by name, in and out of files that PyTorch's torch.save writes (a dict
// of name -> tensor), so weights move between this library and PyTorch/torchvision.
#include <filesystem>
#include <map>
#include <string>

#include <torch/torch.h>

namespace matlearn {

// Copies every tensor of the dict saved at `path` into the module's parameter or buffer of the
// same name. Strict: a name missing on either side, or a shape that differs, is an error naming
// the file and the tensors (std::runtime_error); nothing is copied then.
void load_state_dict(torch::nn::Module& module, const std::filesystem::path& path);

// The two halves of it: the dict in the file (std::runtime_error naming the file when it is
// unreadable or holds anything but name -> tensor), and copying a dict read from `source` into
// the module, as strictly.
std::map<std::string, torch::Tensor> read_state_dict(const std::filesystem::path& path);
void load_state_dict(torch::nn::Module& module, const std::map<std::string, torch::Tensor>& tensors, const std::string& source);

// Writes the module's parameters and buffers as such a dict.
void save_state_dict(const torch::nn::Module& module, const std::filesystem::path& path);

}  // namespace matlearn
