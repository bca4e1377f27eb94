// A network through the installed libmatlearn (libtorch): the quarter-width UNet-no-skip of the
// paper's 6 outputs predicts maps the size of its input, each in [0, 1] after the sigmoid.
// Exits non-zero otherwise.
#include <cstdio>

#include <matlearn/models/regressor.h>
#include <matlearn/training/loss.h>

int main() {
  torch::manual_seed(1);
  const auto model = matlearn::make_regressor(matlearn::Architecture::unet_no_skip, 6, 4);
  model->eval();
  torch::NoGradGuard no_grad;
  const torch::Tensor logits = model->forward(torch::rand({1, 3, 64, 64}));
  const torch::Tensor maps = matlearn::predicted_maps(logits, matlearn::OutputLayout::paper());
  std::printf("%lld parameters, maps of %lld x %lld x %lld\n", static_cast<long long>(matlearn::parameter_count(*model)),
              static_cast<long long>(maps.size(1)), static_cast<long long>(maps.size(2)), static_cast<long long>(maps.size(3)));
  const bool in_range = maps.min().item<float>() >= 0.0f && maps.max().item<float>() <= 1.0f;
  return maps.sizes() == torch::IntArrayRef({1, 6, 64, 64}) && in_range ? 0 : 1;
}
