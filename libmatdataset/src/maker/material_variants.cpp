#include "matdataset/maker/material_variants.h"

#include <algorithm>
#include <limits>
#include <set>
#include <stdexcept>

namespace matdataset {
namespace {

// SplitMix64 (Steele, Lea and Flood 2014): a fixed sequence for a seed on every platform, unlike
// the standard library's distributions.
class SplitMix64 {
 public:
  explicit SplitMix64(uint64_t seed) : state_(seed) {}
  uint64_t next() {
    uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  // Uniform in [0, n], n < 2^64 - 1: rejection of the incomplete last block, so no value is favoured.
  uint64_t at_most(uint64_t n) {
    const uint64_t range = n + 1;
    const uint64_t limit = std::numeric_limits<uint64_t>::max() - std::numeric_limits<uint64_t>::max() % range;
    uint64_t x;
    do x = next();
    while (x >= limit);
    return x % range;
  }

 private:
  uint64_t state_;
};

void check_slots(const std::vector<SlotCandidates>& slots) {
  if (slots.empty()) throw std::invalid_argument("material variants: no material slots");
  for (const SlotCandidates& slot : slots)
    if (slot.materials.empty())
      throw std::invalid_argument("material variants: slot \"" + slot.slot + "\" has no candidate materials");
}

// Variant `index` of the full list: mixed-radix digits, the last slot the fastest (cartesian), or
// the index itself in every slot (zip).
MaterialVariant variant_at(const std::vector<SlotCandidates>& slots, VariantCombination combination, uint64_t index) {
  MaterialVariant variant(slots.size());
  if (combination == VariantCombination::Zip) {
    std::fill(variant.begin(), variant.end(), static_cast<size_t>(index));
    return variant;
  }
  for (size_t s = slots.size(); s-- > 0;) {
    const uint64_t radix = slots[s].materials.size();
    variant[s] = static_cast<size_t>(index % radix);
    index /= radix;
  }
  return variant;
}

}  // namespace

uint64_t variant_count(const std::vector<SlotCandidates>& slots, VariantCombination combination) {
  check_slots(slots);
  if (combination == VariantCombination::Zip) {
    size_t shortest = slots.front().materials.size();
    for (const SlotCandidates& slot : slots) shortest = std::min(shortest, slot.materials.size());
    return shortest;
  }
  constexpr uint64_t kLimit = uint64_t{1} << 63;
  uint64_t count = 1;
  for (const SlotCandidates& slot : slots) {
    if (count > kLimit / slot.materials.size())
      throw std::invalid_argument("material variants: the cartesian product has more than 2^63 combinations");
    count *= slot.materials.size();
  }
  return count;
}

std::vector<MaterialVariant> material_variants(const std::vector<SlotCandidates>& slots, VariantCombination combination,
                                               std::optional<uint64_t> max_variants, uint64_t seed) {
  if (max_variants && *max_variants == 0) throw std::invalid_argument("material variants: a cap of 0 variants");
  const uint64_t count = variant_count(slots, combination);
  std::vector<uint64_t> indices;
  if (!max_variants || *max_variants >= count) {
    indices.resize(static_cast<size_t>(count));
    for (uint64_t i = 0; i < count; ++i) indices[static_cast<size_t>(i)] = i;
  } else {
    // Floyd's algorithm (Bentley and Floyd 1987, "A sample of brilliance"): k distinct indices
    // of [0, count), every k-subset equally likely, in k draws whatever count is.
    std::set<uint64_t> chosen;
    SplitMix64 random(seed);
    for (uint64_t j = count - *max_variants; j < count; ++j) {
      const uint64_t t = random.at_most(j);
      chosen.insert(chosen.count(t) ? j : t);
    }
    indices.assign(chosen.begin(), chosen.end());
  }
  std::vector<MaterialVariant> variants;
  variants.reserve(indices.size());
  for (const uint64_t index : indices) variants.push_back(variant_at(slots, combination, index));
  return variants;
}

}  // namespace matdataset
