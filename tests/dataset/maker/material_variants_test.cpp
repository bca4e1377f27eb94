// Material variants (matdataset/maker/material_variants.h): the cartesian order of itertools.product, zip
// up to the shortest list, and a cap that draws every subset of variants equally often.
#include <catch2/catch.hpp>

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "matdataset/maker/material_variants.h"

using matdataset::MaterialVariant;
using matdataset::SlotCandidates;
using matdataset::VariantCombination;

namespace {

const std::vector<SlotCandidates> kTwoSlots = {{"top", {"oak", "pine"}}, {"legs", {"steel", "brass", "chrome"}}};

}  // namespace

TEST_CASE("Cartesian variants come in itertools.product's order, zip ones up to the shortest list", "[geom]") {
  const std::vector<MaterialVariant> all = matdataset::material_variants(kTwoSlots, VariantCombination::Cartesian);
  CHECK(all == std::vector<MaterialVariant>{{0, 0}, {0, 1}, {0, 2}, {1, 0}, {1, 1}, {1, 2}});
  CHECK(matdataset::variant_count(kTwoSlots, VariantCombination::Cartesian) == 6);
  const std::vector<MaterialVariant> zipped = matdataset::material_variants(kTwoSlots, VariantCombination::Zip);
  CHECK(zipped == std::vector<MaterialVariant>{{0, 0}, {1, 1}});
  // A cap at or above the count changes nothing.
  CHECK(matdataset::material_variants(kTwoSlots, VariantCombination::Cartesian, 6, 7) == all);
  CHECK(matdataset::material_variants(kTwoSlots, VariantCombination::Zip, 100, 7) == zipped);
}

TEST_CASE("A cap keeps distinct variants in list order, the same ones for the same seed", "[geom]") {
  const std::vector<MaterialVariant> a = matdataset::material_variants(kTwoSlots, VariantCombination::Cartesian, 3, 42);
  REQUIRE(a.size() == 3);
  CHECK(a == matdataset::material_variants(kTwoSlots, VariantCombination::Cartesian, 3, 42));
  for (size_t k = 1; k < a.size(); ++k) CHECK(a[k - 1] < a[k]);  // list order, no repeats
  // A product far too large to list: the cap still draws k variants at once.
  std::vector<SlotCandidates> many(20, SlotCandidates{"slot", {"a", "b", "c", "d", "e", "f", "g", "h"}});
  const std::vector<MaterialVariant> few = matdataset::material_variants(many, VariantCombination::Cartesian, 5, 1);
  CHECK(few.size() == 5);
  for (const MaterialVariant& v : few) CHECK(v.size() == 20);
}

TEST_CASE("A cap draws every subset of variants equally often (chi-square)", "[geom]") {
  // 2 of the 6 cartesian variants: 15 subsets, each 1/15 of the draws. The repository's cap would
  // always keep the first two, {oak, steel} and {oak, brass}.
  constexpr int kDraws = 30000;
  std::map<std::vector<MaterialVariant>, int> counts;
  for (int seed = 0; seed < kDraws; ++seed)
    ++counts[matdataset::material_variants(kTwoSlots, VariantCombination::Cartesian, 2, static_cast<uint64_t>(seed))];
  REQUIRE(counts.size() == 15);
  const double expected = kDraws / 15.0;
  double statistic = 0.0;
  for (const auto& [subset, n] : counts) statistic += (n - expected) * (n - expected) / expected;
  // The chi-square distribution's 0.999 quantile for 14 degrees of freedom.
  CHECK(statistic < 36.12);
}

TEST_CASE("Variants refuse slots without candidates, a cap of 0 and products beyond 2^63", "[geom]") {
  CHECK_THROWS_AS(matdataset::material_variants({}, VariantCombination::Cartesian), std::invalid_argument);
  CHECK_THROWS_WITH(matdataset::material_variants({{"seat", {}}}, VariantCombination::Zip),
                    Catch::Matchers::Contains("slot \"seat\" has no candidate materials"));
  CHECK_THROWS_WITH(matdataset::material_variants(kTwoSlots, VariantCombination::Cartesian, 0),
                    Catch::Matchers::Contains("a cap of 0"));
  const std::vector<SlotCandidates> huge(64, SlotCandidates{"slot", {"a", "b"}});
  CHECK_THROWS_WITH(matdataset::variant_count(huge, VariantCombination::Cartesian),
                    Catch::Matchers::Contains("more than 2^63"));
}
