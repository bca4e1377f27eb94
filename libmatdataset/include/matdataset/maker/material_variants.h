#pragma once
// Material variants of an object: per material slot a list of candidate materials, combined
// slot by slot (every combination, or the k-th candidates together), and capped to at most
// `max_variants` combinations drawn uniformly at random without repetition. The MatPredict
// repository's cap keeps the first combinations instead, which for the cartesian product are the
// ones whose first slots keep their first candidates: a biased subset (docs/matpredict_repository.md).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace matdataset {

enum class VariantCombination {
  Cartesian,  // every combination; the last slot varies fastest, as itertools.product
  Zip,        // the k-th candidate of every slot together, up to the shortest list
};

struct SlotCandidates {
  std::string slot;
  std::vector<std::string> materials;  // at least one
};

// One variant: for each slot, in the order given, the index of its candidate; for an object with
// several UV scales (ObjectConfig::uv_scales), then the index of its scale.
using MaterialVariant = std::vector<size_t>;

// The variants, in the order of the full list; with a cap below its size, a uniformly random
// subset of `max_variants` of them (seeded: the same seed gives the same subset), still in that
// order. Throws std::invalid_argument for no slots, a slot without candidates, a cap of 0, or a
// cartesian product beyond 2^63 combinations.
std::vector<MaterialVariant> material_variants(const std::vector<SlotCandidates>& slots, VariantCombination combination,
                                               std::optional<uint64_t> max_variants = std::nullopt, uint64_t seed = 0);

// How many variants the full list has.
uint64_t variant_count(const std::vector<SlotCandidates>& slots, VariantCombination combination);

}  // namespace matdataset
