#include "lights/environment_light.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "matbase/pi.h"
#include "sampling/warp.h"
#include "util/channel_average.h"

namespace matrender {
namespace {

constexpr float kTwoPiSquared = 2.0f * kPi * kPi;

// d turned about +Z by the angle whose cosine and sine these are.
glm::vec3 turned_about_z(const glm::vec3& d, float cosine, float sine) {
  return {cosine * d.x - sine * d.y, sine * d.x + cosine * d.y, d.z};
}

// Over one texel's cell, the bilinear lookup (texel centres at cell centres) integrates to
// 1/8, 3/4, 1/8 of the previous, own and next texel in each axis. Every texel the lookup blends
// into a cell thus gives it weight, so the density is positive wherever the radiance is.
std::vector<float> cell_integrals(const std::vector<float>& texels, int width, int height) {
  const auto wrap = [](int i, int n) { return (i % n + n) % n; };
  const auto at = [&](const std::vector<float>& grid, int x, int y) {
    return grid[static_cast<size_t>(wrap(y, height)) * width + wrap(x, width)];
  };
  std::vector<float> along_u(texels.size()), both(texels.size());
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      along_u[static_cast<size_t>(y) * width + x] =
          0.125f * at(texels, x - 1, y) + 0.75f * at(texels, x, y) + 0.125f * at(texels, x + 1, y);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      both[static_cast<size_t>(y) * width + x] =
          0.125f * at(along_u, x, y - 1) + 0.75f * at(along_u, x, y) + 0.125f * at(along_u, x, y + 1);
  return both;
}

float sin_polar(float v) { return std::sin(kPi * (1.0f - v)); }

}  // namespace

glm::vec2 equirectangular_uv(const glm::vec3& d) {
  const float u = 0.5f - std::atan2(d.y, d.x) / (2.0f * kPi);
  const float v = 1.0f - std::acos(std::clamp(d.z, -1.0f, 1.0f)) / kPi;
  return {u, v};
}

glm::vec3 equirectangular_direction(glm::vec2 uv) {
  const float phi = kPi * (1.0f - 2.0f * uv.x);
  const float theta = kPi * (1.0f - uv.y);
  const float sin_theta = std::sin(theta);
  return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), std::cos(theta)};
}

EnvironmentLight::EnvironmentLight(const EnvironmentMap& map) : image_(map.image) {
  if (!image_) throw std::invalid_argument("environment map: no image");
  if (!(map.strength >= 0.0 && map.strength <= std::numeric_limits<float>::max()))
    throw std::invalid_argument(image_->name() + ": environment strength " + std::to_string(map.strength) +
                                " must be >= 0 and fit single precision");
  if (!std::isfinite(map.rotation_z))
    throw std::invalid_argument(image_->name() + ": environment rotation must be finite");
  strength_ = static_cast<float>(map.strength);
  cos_rotation_ = static_cast<float>(std::cos(map.rotation_z));
  sin_rotation_ = static_cast<float>(std::sin(map.rotation_z));

  const int width = image_->width();
  const int height = image_->height();
  std::vector<float> means(static_cast<size_t>(width) * height);
  float brightest = 0.0f;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const glm::vec3 texel = image_->sample({(x + 0.5f) / width, (y + 0.5f) / height});
      brightest = std::max(brightest, std::max(texel.x, std::max(texel.y, texel.z)));
      means[static_cast<size_t>(y) * width + x] = std::max(0.0f, channel_average(texel));
    }
  }
  if (static_cast<double>(brightest) * map.strength > std::numeric_limits<float>::max())
    throw std::invalid_argument(image_->name() + ": its brightest texel times the strength " +
                                std::to_string(map.strength) + " exceeds single precision; lower the strength");
  std::vector<float> weights = cell_integrals(means, width, height);
  for (int y = 0; y < height; ++y) {
    const float sine = sin_polar((y + 0.5f) / height);
    for (int x = 0; x < width; ++x) weights[static_cast<size_t>(y) * width + x] *= sine;
  }
  distribution_ = std::make_shared<PiecewiseConstant2D>(weights, width, height);
  // The density's integral over (u, v) is that of L sin(theta), so the mean radiance over the
  // sphere, the integral of L d omega / 4 pi, is 2 pi^2 integral / 4 pi.
  importance_ = static_cast<float>(matbase::kPi * strength_ * 0.5 * matbase::kPi * distribution_->integral());
}

glm::vec3 EnvironmentLight::to_map(const glm::vec3& d) const { return turned_about_z(d, cos_rotation_, sin_rotation_); }

glm::vec3 EnvironmentLight::from_map(const glm::vec3& d) const { return turned_about_z(d, cos_rotation_, -sin_rotation_); }

std::optional<LightSample> EnvironmentLight::sample(const glm::vec3& /*p*/,
                                                            const ReceivingDirections& /*receiving*/,
                                                            glm::vec2 u) const {
  if (black()) return std::nullopt;
  float pdf_uv;
  const glm::vec2 uv = distribution_->sample(u, &pdf_uv);
  const float sine = sin_polar(uv.y);
  // pdf by solid angle: d omega = sin(theta) d theta d phi = 2 pi^2 sin(theta) du dv.
  if (!(pdf_uv > 0.0f) || !(sine > 0.0f)) return std::nullopt;
  LightSample s;
  s.wi = from_map(equirectangular_direction(uv));
  s.distance = std::numeric_limits<float>::infinity();
  s.radiance = strength_ * glm::vec3(image_->sample(uv));
  s.pdf = pdf_uv / (kTwoPiSquared * sine);
  return s;
}

float EnvironmentLight::pdf(const glm::vec3& d) const {
  if (black()) return 0.0f;
  const glm::vec3 m = to_map(d);
  const float sine = std::sqrt(std::max(0.0f, 1.0f - m.z * m.z));
  if (!(sine > 0.0f)) return 0.0f;
  return distribution_->pdf(equirectangular_uv(m)) / (kTwoPiSquared * sine);
}

glm::vec3 EnvironmentLight::radiance(const glm::vec3& d) const {
  return strength_ * glm::vec3(image_->sample(equirectangular_uv(to_map(d))));
}

glm::vec3 background_radiance(const Background& background, const glm::vec3& direction) {
  if (const auto* uniform = std::get_if<glm::vec3>(&background)) return *uniform;
  const auto& map = std::get<EnvironmentMap>(background);
  // Looked up along R_z(rotation) d, as EnvironmentLight::to_map turns it.
  const glm::vec3 turned = turned_about_z(direction, static_cast<float>(std::cos(map.rotation_z)),
                                          static_cast<float>(std::sin(map.rotation_z)));
  return static_cast<float>(map.strength) * glm::vec3(map.image->sample(equirectangular_uv(turned)));
}

}  // namespace matrender
