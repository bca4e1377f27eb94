#include "matrender/atrous_filter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "matbase/image/srgb.h"
#include "matbase/threads.h"
#include "util/finite.h"

namespace matrender {
namespace {

// The B3-spline taps of the a-trous transform (Dammertz et al. 2010, section 3; SVGF's h).
constexpr std::array<float, 5> kTaps = {1.0f / 16.0f, 1.0f / 4.0f, 3.0f / 8.0f, 1.0f / 4.0f, 1.0f / 16.0f};
// Base colours below it divide as it: a black surface keeps its (zero) colour, not a division by 0.
constexpr float kMinAlbedo = 0.01f;

// What the filter knows of each pixel, read once from the frame.
struct Guides {
  int width = 0, height = 0;
  std::vector<uint8_t> filtered;  // a surface pixel whose colour the filter may read and change
  std::vector<glm::vec3> demodulation;  // colour = irradiance x this (base colour, and coverage over a transparent background)
  std::vector<glm::vec3> normal;
  std::vector<float> depth;
  std::vector<glm::vec2> depth_gradient;  // per pixel step in x and y
  std::vector<int32_t> label;

  size_t index(int x, int y) const { return static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x); }
};

void require(bool present, const char* what) {
  if (!present) throw std::invalid_argument(std::string("atrous_filter: the frame has no ") + what + " (kAtrousFilterGuideAovs)");
}

bool finite_non_negative(const glm::vec3& c) { return is_finite(c) && c.x >= 0.0f && c.y >= 0.0f && c.z >= 0.0f; }

Guides read_guides(const FrameBuffers& frame) {
  Guides g;
  g.width = frame.width;
  g.height = frame.height;
  const size_t n = static_cast<size_t>(frame.width) * static_cast<size_t>(frame.height);
  const std::vector<float>& base = frame.parameter(MaterialParameter::BaseColor);
  g.filtered.assign(n, 0);
  g.demodulation.assign(n, glm::vec3(1.0f));
  g.normal.assign(n, glm::vec3(0.0f));
  g.depth.assign(n, 0.0f);
  g.depth_gradient.assign(n, glm::vec2(0.0f));
  g.label = frame.label;
  for (size_t p = 0; p < n; ++p) {
    const float coverage = frame.alpha[p];
    // Over an opaque background a partly covered pixel mixes in the background, which the base
    // colour cannot take out: only whole pixels are filtered then.
    const bool surface = frame.transparent_background ? coverage > 0.0f : coverage >= 1.0f;
    const glm::vec3 colour(frame.color[3 * p], frame.color[3 * p + 1], frame.color[3 * p + 2]);
    const glm::vec3 albedo(base[3 * p], base[3 * p + 1], base[3 * p + 2]);
    const glm::vec3 normal(frame.normal_world[3 * p], frame.normal_world[3 * p + 1], frame.normal_world[3 * p + 2]);
    const float normal_length = glm::length(normal);
    if (!surface || !(normal_length > 0.0f) || !finite_non_negative(colour) || !finite_non_negative(albedo) || !std::isfinite(frame.depth[p]) ||
        !std::isfinite(frame.color_variance[p]) || !is_finite(normal))
      continue;
    g.filtered[p] = 1;
    g.demodulation[p] = glm::max(albedo, glm::vec3(kMinAlbedo)) * (frame.transparent_background ? coverage : 1.0f);
    g.normal[p] = normal / normal_length;
    g.depth[p] = frame.depth[p];
  }
  // The depth gradient by central differences over surface neighbours (one-sided at their edge).
  for (int y = 0; y < g.height; ++y)
    for (int x = 0; x < g.width; ++x) {
      const size_t p = g.index(x, y);
      if (!g.filtered[p]) continue;
      auto slope = [&](int dx, int dy) {
        const int x0 = std::max(0, x - dx), x1 = std::min(g.width - 1, x + dx);
        const int y0 = std::max(0, y - dy), y1 = std::min(g.height - 1, y + dy);
        const size_t a = g.filtered[g.index(x0, y0)] ? g.index(x0, y0) : p;
        const size_t b = g.filtered[g.index(x1, y1)] ? g.index(x1, y1) : p;
        const int steps = (a == p ? 0 : 1) + (b == p ? 0 : 1);
        return steps == 0 ? 0.0f : std::abs(g.depth[b] - g.depth[a]) / static_cast<float>(steps);
      };
      g.depth_gradient[p] = {slope(1, 0), slope(0, 1)};
    }
  return g;
}

// Whether q may contribute to p: both surface pixels of the same material label.
bool joinable(const Guides& g, size_t p, size_t q) { return g.filtered[q] && g.label[q] == g.label[p]; }

// The variance averaged over the joinable pixels within `radius`, weighted by `weight(dx, dy)`.
template <class Weight>
std::vector<float> averaged_variance(const Guides& g, const std::vector<float>& variance, int radius, Weight weight) {
  std::vector<float> out(variance.size(), 0.0f);
  for (int y = 0; y < g.height; ++y)
    for (int x = 0; x < g.width; ++x) {
      const size_t p = g.index(x, y);
      if (!g.filtered[p]) continue;
      float sum = 0.0f, weights = 0.0f;
      for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx) {
          const int qx = x + dx, qy = y + dy;
          if (qx < 0 || qy < 0 || qx >= g.width || qy >= g.height) continue;
          const size_t q = g.index(qx, qy);
          if (!joinable(g, p, q)) continue;
          const float w = weight(dx, dy);
          sum += w * variance[q];
          weights += w;
        }
      out[p] = sum / weights;  // the centre always joins
    }
  return out;
}

// The 3 x 3 Gaussian of the variance over joinable neighbours (SVGF, equation 5's g_3x3).
std::vector<float> blurred_variance(const Guides& g, const std::vector<float>& variance) {
  constexpr std::array<float, 3> kGauss = {0.25f, 0.5f, 0.25f};
  return averaged_variance(g, variance, 1, [&](int dx, int dy) {
    return kGauss[static_cast<size_t>(dx + 1)] * kGauss[static_cast<size_t>(dy + 1)];
  });
}

}  // namespace

void AtrousFilter::denoise(FrameBuffers& frame, int threads) const {
  AtrousFilterSettings settings;
  settings.threads = threads;
  atrous_filter(frame, settings);
}

void atrous_filter(FrameBuffers& frame, const AtrousFilterSettings& settings) {
  const size_t n = static_cast<size_t>(std::max(frame.width, 0)) * static_cast<size_t>(std::max(frame.height, 0));
  require(frame.color.size() == 3 * n && n > 0, "colour");
  require(frame.alpha.size() == n, "alpha");
  require(frame.color_variance.size() == n, "colour variance");
  require(frame.normal_world.size() == 3 * n, "world normal");
  require(frame.depth.size() == n, "depth");
  require(frame.label.size() == n, "label");
  require(frame.parameter(MaterialParameter::BaseColor).size() == 3 * n, "base colour");
  if (settings.iterations < 0 || settings.iterations > 12)
    throw std::invalid_argument("atrous_filter: iterations must be in [0, 12]");
  if (!(settings.sigma_luminance > 0.0f && settings.sigma_normal >= 0.0f && settings.sigma_depth > 0.0f &&
        std::isfinite(settings.sigma_luminance) && std::isfinite(settings.sigma_normal) && std::isfinite(settings.sigma_depth)))
    throw std::invalid_argument("atrous_filter: sigma_luminance and sigma_depth must be positive, sigma_normal >= 0");
  if (settings.threads < 0) throw std::invalid_argument("atrous_filter: threads must be >= 0");

  const Guides g = read_guides(frame);
  // Irradiance and its variance (section 4.2: the filter works on the colour over the albedo).
  std::vector<glm::vec3> irradiance(n, glm::vec3(0.0f)), next_irradiance(n);
  std::vector<float> variance(n, 0.0f), next_variance(n, 0.0f);
  for (size_t p = 0; p < n; ++p) {
    if (!g.filtered[p]) continue;
    irradiance[p] = glm::vec3(frame.color[3 * p], frame.color[3 * p + 1], frame.color[3 * p + 2]) / g.demodulation[p];
    const float scale = matbase::rec709_luminance(g.demodulation[p]);
    variance[p] = frame.color_variance[p] / (scale * scale);
  }

  // A pixel's own variance comes from few samples and is often 0 in a penumbra whose samples all
  // missed the lamp: it starts as the mean over its 7 x 7 joinable neighbours, as SVGF estimates
  // variance spatially while a pixel's history is short (section 4.3).
  variance = averaged_variance(g, variance, 3, [](int, int) { return 1.0f; });

  tbb::task_arena arena(matbase::worker_threads(settings.threads));
  for (int iteration = 0; iteration < settings.iterations; ++iteration) {
    const int step = 1 << iteration;
    const std::vector<float> blurred = blurred_variance(g, variance);
    arena.execute([&] {
      tbb::parallel_for(tbb::blocked_range<int>(0, g.height), [&](const tbb::blocked_range<int>& rows) {
        for (int y = rows.begin(); y != rows.end(); ++y)
          for (int x = 0; x < g.width; ++x) {
            const size_t p = g.index(x, y);
            if (!g.filtered[p]) {
              next_irradiance[p] = irradiance[p];
              next_variance[p] = variance[p];
              continue;
            }
            const float luminance_p = matbase::rec709_luminance(irradiance[p]);
            glm::vec3 sum(0.0f);
            float weights = 0.0f, variance_sum = 0.0f;
            for (int j = -2; j <= 2; ++j)
              for (int i = -2; i <= 2; ++i) {
                const int qx = x + i * step, qy = y + j * step;
                if (qx < 0 || qy < 0 || qx >= g.width || qy >= g.height) continue;
                const size_t q = g.index(qx, qy);
                if (!joinable(g, p, q)) continue;
                // Equation 3 (depth against the gradient over the tap's offset), 4 (normals), 5
                // (luminance in standard errors).
                const float expected_step = std::abs(g.depth_gradient[p].x * static_cast<float>(i * step)) +
                                            std::abs(g.depth_gradient[p].y * static_cast<float>(j * step));
                const float w_depth = std::exp(-std::abs(g.depth[p] - g.depth[q]) /
                                               (settings.sigma_depth * expected_step + 1e-3f * g.depth[p] + 1e-6f));
                const float w_normal = std::pow(std::clamp(glm::dot(g.normal[p], g.normal[q]), 0.0f, 1.0f), settings.sigma_normal);
                // Equation 5's denominator with the smaller of the two pixels' variances, not p's
                // alone: a highlight (noisy) and its dark surround (quiet) then stay apart in both
                // directions, so highlights are not spread. The epsilon keeps pixels of no measured
                // noise apart from all but equal neighbours without dividing by 0.
                const float luminance_scale = settings.sigma_luminance * std::sqrt(std::min(blurred[p], blurred[q])) + 1e-6f;
                const float w_luminance =
                    std::exp(-std::abs(luminance_p - matbase::rec709_luminance(irradiance[q])) / luminance_scale);
                const float w = kTaps[static_cast<size_t>(i + 2)] * kTaps[static_cast<size_t>(j + 2)] * w_depth * w_normal *
                                w_luminance;
                sum += w * irradiance[q];
                weights += w;
                variance_sum += w * w * variance[q];
              }
            // The centre tap joins with weight (3/8)^2 (every factor 1), so weights > 0.
            next_irradiance[p] = sum / weights;
            next_variance[p] = variance_sum / (weights * weights);
          }
      });
    });
    std::swap(irradiance, next_irradiance);
    std::swap(variance, next_variance);
  }
  for (size_t p = 0; p < n; ++p) {
    if (!g.filtered[p]) continue;
    const glm::vec3 colour = irradiance[p] * g.demodulation[p];
    for (int c = 0; c < 3; ++c) frame.color[3 * p + static_cast<size_t>(c)] = colour[c];
  }
}

}  // namespace matrender
