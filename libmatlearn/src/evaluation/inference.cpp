#include "matlearn/evaluation/inference.h"

#include "matlearn/training/batch.h"
#include "matlearn/training/loss.h"

namespace matlearn {

PredictedMaps predict_maps(RegressorImpl& model, const CheckpointHeader& header, const matbase::FloatImage& rgb) {
  const InputNormalization normalization = info(architecture_named(header.network).architecture).input_normalization;
  model.eval();
  torch::NoGradGuard no_grad;
  const torch::Tensor input = normalize_input(to_chw(rgb).unsqueeze(0), normalization);
  const torch::Tensor maps = predicted_maps(model.forward(input), header.layout)[0];
  PredictedMaps out;
  for (size_t g = 0; g < header.layout.groups.size(); ++g) {
    const OutputGroup& group = header.layout.groups[g];
    out.names.push_back(map_name(group.map));
    out.maps.push_back(to_hwc(maps.narrow(0, header.layout.first_channel(g), group.channels)));
  }
  return out;
}

}  // namespace matlearn
