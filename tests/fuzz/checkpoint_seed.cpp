// Writes the checkpoint fuzzer's seed: the smallest network there is (unet_no_skip at 1/32 of its
// widths, one roughness channel), fresh weights and an Adam state after one step.
// Usage: checkpoint_seed OUT.pt
#include <torch/torch.h>

#include "matlearn/training/checkpoint.h"

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  matlearn::CheckpointHeader header;
  header.network = "unet_no_skip";
  header.width_divisor = 32;
  header.layout.groups = {{matlearn::MapKind::roughness, 1, 1.0}};
  header.image_size = 32;
  const auto model = matlearn::make_regressor(matlearn::Architecture::unet_no_skip, 1, 32);
  torch::optim::Adam optimizer(model->parameters());
  model->forward(torch::zeros({1, 3, 32, 32})).sum().backward();
  optimizer.step();
  matlearn::save_checkpoint(argv[1], header, *model, optimizer);
  return 0;
}
