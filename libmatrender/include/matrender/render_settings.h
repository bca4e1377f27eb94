#pragma once
// What a render is asked to do. Every setting's name, range and one line of documentation are
// declared once, in matrender/render_setting_declarations.h; the defaults are the initialisers
// below (Cycles 3.4's where Cycles has the setting).
#include <atomic>
#include <cstdint>
#include <functional>

#include "matrender/frame.h"

namespace matrender {

// How next-event estimation picks one light per shading point: in proportion to a bound on the
// irradiance each light can give there (0 where it can give none), or uniformly as Cycles 3.4
// does. Only the noise differs.
enum class LightSelection { Importance, Uniform };

// What denoises the finished colour (matrender/denoiser.h): nothing, the a-trous filter
// (matrender/atrous_filter.h), or the learned denoiser the program provides.
enum class Denoising { Off, Filter, Learned };

struct RenderSettings {
  int samples_per_pixel = 64;
  double filter_width = 1.5;  // pixels, Blender's Film > Pixel Filter > Width
  // Adaptive sampling as Cycles 3.4 (docs/conventions.md): 0 = off.
  double noise_threshold = 0.0;
  int min_samples = 0;  // 0 = Cycles' automatic rule (16 with a target error)
  // Rendering to an error (docs/conventions.md, "Rendering to an error"): the relative RMSE over
  // the covered pixels the frame may have, samples_per_pixel the most a pixel takes; 0 = off.
  double target_error = 0.0;
  uint32_t seed = 0;
  int threads = 0;  // 0 = all hardware threads; the image does not depend on this
  int max_bounces = 12;
  int max_diffuse_bounces = 4;
  int max_glossy_bounces = 4;
  int max_transmission_bounces = 12;
  int max_transparent_bounces = 8;
  bool transparent_background = false;
  bool cycles_parity = false;
  LightSelection light_selection = LightSelection::Importance;
  // A denoiser fills the guide AOVs it reads too (Denoiser::guide_aovs).
  Denoising denoise = Denoising::Off;
  bool mipmaps = true;
  uint32_t aovs = default_aovs();
  // Ambient occlusion (AovAmbientOcclusion): with an error > 0 each pixel traces as many rays as
  // its own trials show it needs (ambient_occlusion.h), and ambient_occlusion_rays is not used.
  double ambient_occlusion_distance = 1.0;
  double ambient_occlusion_error = 0.0;
  int ambient_occlusion_rays = 4;
  // Called with the finished fraction of all samples in [0, 1], from a render thread, every 65,536
  // samples a thread takes and when a tile ends; calls are serialised and the fraction increases.
  std::function<void(double)> progress;
  // Checked at every packet of 16 samples; when it becomes true the render stops within
  // milliseconds and reports cancelled (the frame is then incomplete).
  const std::atomic<bool>* cancel = nullptr;
};

}  // namespace matrender
