#include "bsdf/lobe_mixture.h"

#include <algorithm>
#include <stdexcept>

namespace matrender {

void LobeMixture::add(const Lobe& lobe) {
  if (count_ == kMaxLobes) throw std::logic_error("LobeMixture: more than kMaxLobes lobes");
  lobes_[count_] = lobe;
  lobe_flags_[count_] = matrender::lobe_flags(lobe);
  sample_weight_[count_] = std::visit([](const auto& l) { return l.sample_weight(); }, lobe);
  ++count_;
}

void LobeMixture::finish() {
  float total = 0.0f;
  for (size_t i = 0; i < count_; ++i) total += sample_weight_[i];
  if (!(total > 0.0f)) {
    count_ = 0;
    flags_ = BxDFFlags::None;
    return;
  }
  float partial = 0.0f;
  flags_ = BxDFFlags::None;
  for (size_t i = 0; i < count_; ++i) {
    partial += sample_weight_[i];
    // The last bound is exactly 1, so every u in [0, 1) picks a lobe.
    cdf_[i] = i + 1 == count_ ? 1.0f : partial / total;
    probability_[i] = cdf_[i] - (i == 0 ? 0.0f : cdf_[i - 1]);
    flags_ |= lobe_flags_[i];
  }
}

glm::vec3 LobeMixture::eval(const glm::vec3& wi, BxDFFlags selected, float* pdf) const {
  glm::vec3 value(0.0f);
  float mixture_pdf = 0.0f;
  for (size_t i = 0; i < count_; ++i) {
    if (!any(lobe_flags_[i] & selected)) continue;
    float lobe_pdf;
    value += std::visit([&](const auto& l) { return l.eval(wi, &lobe_pdf); }, lobes_[i]);
    mixture_pdf += probability_[i] * lobe_pdf;
  }
  *pdf = mixture_pdf;
  return value;
}

size_t LobeMixture::pick(float u_lobe) const {
  for (size_t i = 0; i < count_; ++i)
    if (u_lobe < cdf_[i]) return i;
  return kMaxLobes;
}

bool LobeMixture::sample(glm::vec2 u, BsdfSample* out) const {
  const float u_lobe = u.x;
  const size_t i = pick(u_lobe);
  if (i == kMaxLobes) return false;
  const float lower = i == 0 ? 0.0f : cdf_[i - 1];
  u.x = std::min((u_lobe - lower) / probability_[i], 0x1.fffffep-1f);
  return sample_lobe(i, u, out);
}

bool LobeMixture::sample(float u_lobe, glm::vec2 u, BsdfSample* out) const {
  const size_t i = pick(u_lobe);
  return i != kMaxLobes && sample_lobe(i, u, out);
}

bool LobeMixture::sample_lobe(size_t i, glm::vec2 u, BsdfSample* out) const {
  LobeSample s;
  if (!std::visit([&](const auto& l) { return l.sample(u, &s); }, lobes_[i])) return false;
  const BxDFFlags flags = lobe_flags_[i];
  out->wi = s.wi;
  out->flags = flags;
  if (is_specular(flags)) {
    out->weight = s.specular_weight / probability_[i];
    out->pdf = 0.0f;
    return true;
  }
  float pdf;
  const glm::vec3 value =
      eval(s.wi, is_reflective(flags) ? BxDFFlags::Reflection : BxDFFlags::Transmission, &pdf);
  if (!(pdf > 0.0f)) return false;
  out->weight = value * (1.0f / pdf);
  out->pdf = pdf;
  return true;
}

}  // namespace matrender
