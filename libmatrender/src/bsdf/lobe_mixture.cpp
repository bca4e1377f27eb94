#include "bsdf/lobe_mixture.h"

#include <algorithm>

namespace matrender {

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
  if (!with_lobe(slots_[i].lobe, [&](const auto& l) { return l.sample(u, &s); })) return false;
  const BxDFFlags flags = lobe_flags_[i];
  out->wi = s.wi;
  out->flags = flags;
  if (is_specular(flags)) {
    out->weight = s.specular_weight / probability_[i];
    out->pdf = 0.0f;
    return true;
  }
  float pdf;
  const BxDFFlags side = is_reflective(flags) ? BxDFFlags::Reflection : BxDFFlags::Transmission;
  glm::vec3 value = eval(s.wi, side, &pdf, s.has_value ? i : kMaxLobes);
  if (s.has_value) {
    value += s.value;
    pdf += probability_[i] * s.pdf;
  }
  if (!(pdf > 0.0f)) return false;
  out->weight = value * (1.0f / pdf);
  out->pdf = pdf;
  return true;
}

}  // namespace matrender
