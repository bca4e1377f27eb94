#include "matlearn/training/loss.h"

#include <stdexcept>
#include <string>

namespace matlearn {

torch::Tensor predicted_maps(const torch::Tensor& output, const OutputLayout& layout) {
  return torch::sigmoid(output.narrow(1, 0, layout.regression_channels()));
}

LossTerms training_loss(const torch::Tensor& output, const Batch& batch, const OutputLayout& layout,
                        RegressionLoss loss) {
  LossTerms terms;
  terms.total = torch::zeros({}, output.options());
  const torch::Tensor maps = predicted_maps(output, layout);
  // An empty mask leaves every map term 0 rather than 0 / 0.
  const torch::Tensor object_pixels = batch.mask.sum().clamp_min(1.0);
  for (size_t g = 0; g < layout.groups.size(); ++g) {
    const OutputGroup& group = layout.groups[g];
    const int64_t first = layout.first_channel(g);
    const torch::Tensor difference = maps.narrow(1, first, group.channels) - batch.target.narrow(1, first, group.channels);
    const torch::Tensor error = loss == RegressionLoss::mse ? difference.square() : difference.abs();
    const torch::Tensor term = (error * batch.mask).sum() / (object_pixels * static_cast<double>(group.channels));
    terms.group_terms.push_back(term.item<double>());
    terms.total = terms.total + group.weight * term;
  }
  if (layout.material_classes > 0) {
    const torch::Tensor logits = output.narrow(1, layout.regression_channels(), layout.material_classes);
    const bool any_label = (batch.labels != kIgnoredLabel).any().item<bool>();
    if (any_label) {
      const int64_t largest = batch.labels.max().item<int64_t>();
      if (largest >= layout.material_classes)
        throw std::runtime_error("a label holds material id " + std::to_string(largest) + " but the network has " +
                                 std::to_string(layout.material_classes) + " classes");
      const torch::Tensor term = torch::nn::functional::cross_entropy(
          logits, batch.labels, torch::nn::functional::CrossEntropyFuncOptions().ignore_index(kIgnoredLabel));
      terms.material_term = term.item<double>();
      terms.total = terms.total + layout.material_weight * term;
    }
  }
  return terms;
}

}  // namespace matlearn
