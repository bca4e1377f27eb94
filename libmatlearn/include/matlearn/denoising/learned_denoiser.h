#pragma once
// The learned denoiser as libmatrender runs it (matrender::Denoiser): the denoising U-Net
// (denoising_unet.h) on a frame's colour, albedo and normal (denoiser_input.h). Deterministic:
// the same frame gives the same image on any thread count.
#include <filesystem>
#include <memory>
#include <mutex>
#include <vector>

#include "matlearn/denoising/denoiser_input.h"
#include "matlearn/denoising/denoising_unet.h"
#include "matrender/denoiser.h"

namespace matlearn {

class LearnedDenoiser final : public matrender::Denoiser {
 public:
  // A network with its weights (it is put in inference mode, not copied).
  explicit LearnedDenoiser(DenoisingUNet network);
  // Weights from a file save_state_dict wrote; std::runtime_error naming the file when they do
  // not fit the network or hold a NaN or an infinity.
  explicit LearnedDenoiser(const std::filesystem::path& weights);

  // The base colour, the world normal and the coverage.
  uint32_t guide_aovs() const override;
  void denoise(matrender::FrameBuffers& frame, int threads) const override;
  // The same on plain arrays: the denoised colour, interleaved RGB.
  std::vector<float> denoised_colour(const DenoiserFrame& frame, int threads) const;

 private:
  mutable std::mutex mutex_;  // one inference at a time: the network and torch's thread count are shared
  mutable DenoisingUNet network_;
};

}  // namespace matlearn
