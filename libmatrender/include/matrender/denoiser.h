#pragma once
// A denoiser replaces a finished frame's noisy colour by an estimate of the converged colour,
// guided by AOVs the renderer fills beside it. render() runs the one RenderSettings::denoise
// names: the a-trous filter (matrender/atrous_filter.h), built in, or the learned denoiser, a
// network that lives outside this library (libmatlearn links torch; this library does not) and
// that a program provides with provide_learned_denoiser() before it renders.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "matrender/frame.h"
#include "matrender/render_settings.h"

namespace matrender {

class Denoiser {
 public:
  virtual ~Denoiser() = default;
  // The AOVs denoise() reads beside the colour; render() fills them whenever it runs this one.
  virtual uint32_t guide_aovs() const = 0;
  // Replaces frame.color by the denoised colour: finite and >= 0 everywhere, the same on any
  // thread count (0 = all hardware threads). Throws std::invalid_argument naming what is missing
  // when a guide AOV is not filled.
  virtual void denoise(FrameBuffers& frame, int threads) const = 0;
};

// The learned denoiser render() runs for Denoising::Learned, from now on and on every thread;
// nullptr takes it away. A program built with libmatlearn provides its network here.
void provide_learned_denoiser(std::shared_ptr<const Denoiser> denoiser);
// The learned denoiser provided, or nullptr when this program has none.
std::shared_ptr<const Denoiser> learned_denoiser();

// Why this program cannot denoise as `denoising` says ("\"learned\" needs the learned denoiser,
// and this program was built without it ..."), or nothing: for readers to refuse a setting early.
std::optional<std::string> denoising_problem(Denoising denoising);

// The denoiser `denoising` names: the a-trous filter, the learned denoiser, or nullptr for Off.
// Throws std::invalid_argument ("denoise: " and denoising_problem()) when it cannot.
std::shared_ptr<const Denoiser> denoiser_for(Denoising denoising);

}  // namespace matrender
