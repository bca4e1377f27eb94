// A checkpoint read, its network rebuilt with the weights and an optimiser given the state, as
// evaluate and --resume do.
#include <torch/torch.h>

#include "fuzz_file.h"
#include "matlearn/training/checkpoint.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return fuzz_file(data, size, ".pt", [](const std::string& path) {
    const matlearn::Checkpoint checkpoint = matlearn::read_checkpoint(path);
    const auto model = matlearn::load_model(checkpoint);
    torch::optim::Adam optimizer(model->parameters());
    matlearn::load_optimizer(checkpoint, optimizer);
  });
}
