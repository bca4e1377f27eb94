#pragma once
// Phase congruency (Kovesi 1999, "Image Features from Phase Congruency", Videre 1(3)), computed
// as his phasecong3 does: log-Gabor filters at several scales and orientations; per orientation
// the energy along the mean phase, less a noise threshold estimated from the smallest scale's
// amplitudes, over the summed amplitudes, weighted by a sigmoid of the frequency spread. The
// result is dimensionless and invariant to the image's brightness and contrast.
#include <vector>

namespace matlearn {

struct PhaseCongruencySettings {
  int scales = 4;
  int orientations = 6;
  double min_wavelength = 3.0;  // pixels, of the smallest-scale filter
  double scale_factor = 2.1;    // ratio of successive filter wavelengths (Kovesi's "mult")
  double sigma_on_f = 0.55;     // log-Gabor bandwidth: sigma over centre frequency
  double noise_k = 2.0;         // noise threshold: mean noise energy plus k standard deviations
  double cut_off = 0.5;         // frequency spread below which congruency is penalised
  double spread_gain = 10.0;    // sharpness of that penalty (Kovesi's "g")
};

struct PhaseCongruency {
  std::vector<std::vector<double>> per_orientation;  // each in [0, 1], one value per pixel
  // Over all orientations: summed weighted energy over summed amplitude (phasecong2's PC).
  std::vector<double> overall;
};

// `image`: height rows of width values. Pixels with no amplitude at all (a flat image) get 0.
PhaseCongruency phase_congruency(const std::vector<double>& image, int width, int height,
                                 const PhaseCongruencySettings& settings);

}  // namespace matlearn
