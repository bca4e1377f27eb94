#pragma once
// A BSDF as a weighted set of lobes in the local shading frame, pbrt-v4's BSDF without the frame
// (bsdf.h adds the frame and the geometric normal). Lobes are picked in proportion to their
// sample weights, as Cycles picks closures (kernel/integrator/shader_eval.h,
// shader_bsdf_pick), and the mixture pdf is what one-sample MIS over the lobes needs.
//
// The set of lobes is open: a new lobe is a class with the methods listed in lobe_sample.h,
// added to `Lobe` below. A material without a lobe pays nothing for it: it is not in the list.
#include <array>
#include <cstddef>
#include <new>
#include <type_traits>
#include <stdexcept>
#include <variant>

#include <glm/glm.hpp>

#include "bsdf/bxdf_flags.h"
#include "bsdf/clearcoat_lobe.h"
#include "bsdf/diffuse_lobe.h"
#include "bsdf/ggx_reflection_lobe.h"
#include "bsdf/ggx_transmission_lobe.h"
#include "bsdf/lobe_sample.h"
#include "bsdf/multiscatter_ggx_lobe.h"
#include "bsdf/sheen_lobe.h"
#include "bsdf/transparent_lobe.h"
#include "bsdf/velvet_lobe.h"

namespace matrender {

using Lobe = std::variant<DiffuseLobe, GgxReflectionLobe, SheenLobe, ClearcoatLobe, GgxTransmissionLobe,
                          TransparentLobe, MultiscatterGgxLobe, VelvetLobe>;

// f(the lobe as its own type). A switch, not std::visit: GCC turns std::visit into a call through
// a table, which keeps the lobes' small methods from being inlined at every path vertex. Forced
// inline: with three lobes GCC stopped inlining it into eval, a call per lobe per vertex (1.2 %
// more instructions on the vase, measured with callgrind).
template <class F>
[[gnu::always_inline]] inline decltype(auto) with_lobe(const Lobe& lobe, F&& f) {
  static_assert(std::variant_size_v<Lobe> == 8, "a new lobe needs its case here");
  switch (lobe.index()) {
    case 0: return f(*std::get_if<0>(&lobe));
    case 1: return f(*std::get_if<1>(&lobe));
    case 2: return f(*std::get_if<2>(&lobe));
    case 3: return f(*std::get_if<3>(&lobe));
    case 4: return f(*std::get_if<4>(&lobe));
    case 5: return f(*std::get_if<5>(&lobe));
    case 6: return f(*std::get_if<6>(&lobe));
    default: return f(*std::get_if<7>(&lobe));
  }
}

struct BsdfSample {
  glm::vec3 wi{0.0f};
  glm::vec3 weight{0.0f};  // f cos / pdf (for a specular lobe: its weight / selection probability)
  float pdf = 0.0f;        // solid-angle pdf of the whole mixture; 0 for a specular lobe
  BxDFFlags flags = BxDFFlags::None;  // of the lobe that made wi
};

class LobeMixture {
 public:
  // Room for every lobe of a material: the Principled BSDF's diffuse, sheen, specular, clearcoat,
  // the glass's reflection and refraction, and transparency, and the velvet beside it (a mixture
  // lives on the stack of every path vertex; the room is left unconstructed, so lobes nobody has
  // cost nothing).
  static constexpr size_t kMaxLobes = 8;

  // Adds a lobe (one of Lobe's alternatives); finish() must follow the last one.
  template <class LobeType>
  void add(const LobeType& lobe);
  // Turns the sample weights into pick probabilities. A mixture whose weights are all zero
  // scatters nothing and has no lobes left.
  void finish();

  BxDFFlags flags() const { return flags_; }

  // Sum of f cos over the lobes whose flags share a bit with `selected` (Reflection for the
  // reflecting lobes, Diffuse for the diffuse ones, ...), and in *pdf the mixture pdf of
  // sampling wi through those lobes.
  // `skip`: a lobe left out of both sums.
  glm::vec3 eval(const glm::vec3& wi, BxDFFlags selected, float* pdf, size_t skip = kMaxLobes) const;
  glm::vec3 eval(const glm::vec3& wi, float* pdf) const {
    return eval(wi, BxDFFlags::Reflection | BxDFFlags::Transmission, pdf);
  }

  // Picks a lobe with u_lobe and a direction in it with u; the value and pdf are the mixture's
  // over the lobes on the picked lobe's side. False when no direction could be made.
  bool sample(float u_lobe, glm::vec2 u, BsdfSample* out) const;
  // The same with the lobe picked by u.x, which is then rescaled within the picked lobe's
  // interval and reused for the direction, so each lobe's directions keep u's 2-D
  // stratification (Cycles 3.4, shader_bsdf_pick: "rescale to reuse for direction sample").
  bool sample(glm::vec2 u, BsdfSample* out) const;

 private:
  // The lobe u_lobe falls in, or kMaxLobes when there is none.
  size_t pick(float u_lobe) const;
  bool sample_lobe(size_t i, glm::vec2 u, BsdfSample* out) const;

  // Room for a lobe, left unconstructed until add() puts one there: a mixture is made at every
  // path vertex, and default-constructing lobes nobody uses costs stores. Lobes are trivially
  // destructible, so nothing needs to end their lifetime.
  union LobeSlot {
    LobeSlot() {}
    Lobe lobe;
  };
  static_assert(std::is_trivially_destructible_v<Lobe> && std::is_trivially_copyable_v<Lobe>);
  // Entries from count_ on are unused.
  std::array<LobeSlot, kMaxLobes> slots_;
  std::array<BxDFFlags, kMaxLobes> lobe_flags_;
  // Until finish(): the sum of the sample weights of lobes 0..i. After: the probability of
  // picking one of lobes 0..i.
  std::array<float, kMaxLobes> cdf_;
  std::array<float, kMaxLobes> probability_;  // cdf_[i] - cdf_[i - 1]
  size_t count_ = 0;
  BxDFFlags flags_ = BxDFFlags::None;
};

// Small and called at every path vertex: defined here so the integrator inlines them.
template <class LobeType>
void LobeMixture::add(const LobeType& lobe) {
  if (count_ == kMaxLobes) throw std::logic_error("LobeMixture: more than kMaxLobes lobes");
  new (&slots_[count_].lobe) Lobe(std::in_place_type<LobeType>, lobe);
  lobe_flags_[count_] = lobe.flags();
  cdf_[count_] = (count_ == 0 ? 0.0f : cdf_[count_ - 1]) + lobe.sample_weight();
  flags_ |= lobe_flags_[count_];
  ++count_;
}

inline void LobeMixture::finish() {
  const float total = count_ == 0 ? 0.0f : cdf_[count_ - 1];
  if (!(total > 0.0f)) {
    count_ = 0;
    flags_ = BxDFFlags::None;
    return;
  }
  for (size_t i = 0; i < count_; ++i) {
    // The last bound is exactly 1, so every u in [0, 1) picks a lobe.
    cdf_[i] = i + 1 == count_ ? 1.0f : cdf_[i] / total;
    probability_[i] = cdf_[i] - (i == 0 ? 0.0f : cdf_[i - 1]);
  }
}

[[gnu::always_inline]] inline glm::vec3 LobeMixture::eval(const glm::vec3& wi, BxDFFlags selected, float* pdf,
                                                          size_t skip) const {
  glm::vec3 value(0.0f);
  float mixture_pdf = 0.0f;
  for (size_t i = 0; i < count_; ++i) {
    if (i == skip || !any(lobe_flags_[i] & selected)) continue;
    float lobe_pdf;
    value += with_lobe(slots_[i].lobe, [&](const auto& l) { return l.eval(wi, &lobe_pdf); });
    mixture_pdf += probability_[i] * lobe_pdf;
  }
  *pdf = mixture_pdf;
  return value;
}

inline size_t LobeMixture::pick(float u_lobe) const {
  for (size_t i = 0; i < count_; ++i)
    if (u_lobe < cdf_[i]) return i;
  return kMaxLobes;
}

}  // namespace matrender
