#include "matlearn/models/stochastic_depth.h"

#include <vector>

namespace matlearn {

torch::Tensor drop_residual_rows(const torch::Tensor& branch, double drop_probability, bool training) {
  if (!training || drop_probability == 0.0) return branch;
  std::vector<int64_t> shape(static_cast<size_t>(branch.dim()), 1);
  shape[0] = branch.size(0);
  const double survival = 1.0 - drop_probability;
  torch::Tensor keep = torch::empty(shape, branch.options()).bernoulli_(survival);
  if (survival > 0.0) keep.div_(survival);
  return branch * keep;
}

double block_drop_probability(double max_probability, int64_t block, int64_t blocks) {
  return blocks > 1 ? max_probability * static_cast<double>(block) / static_cast<double>(blocks - 1) : 0.0;
}

}  // namespace matlearn
