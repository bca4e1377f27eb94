// Batches in a seeded order (matdataset/format/sample_loader.h) and the variant-level split.
#include <catch2/catch.hpp>

#include <algorithm>
#include <set>
#include <string>

#include "matdataset/format/sample_loader.h"

using namespace matdataset;

namespace {

std::vector<matdataset::SampleId> fake_samples(int objects, int variants, int frames) {
  std::vector<matdataset::SampleId> samples;
  for (int o = 0; o < objects; ++o)
    for (int v = 0; v < variants; ++v)
      for (int f = 0; f < frames; ++f)
        samples.push_back({"object" + std::to_string(o), "var00" + std::to_string(v), "00" + std::to_string(f)});
  return samples;
}

}  // namespace

TEST_CASE("Seeded permutations are permutations, repeatable, and uniform over positions", "[learn]") {
  const std::vector<size_t> a = matdataset::seeded_permutation(100, 42), b = matdataset::seeded_permutation(100, 42);
  CHECK(a == b);
  CHECK(matdataset::seeded_permutation(100, 43) != a);
  std::vector<size_t> sorted = a;
  std::sort(sorted.begin(), sorted.end());
  for (size_t i = 0; i < sorted.size(); ++i) REQUIRE(sorted[i] == i);
  // Which element lands first, over many seeds: uniform over 8 elements by chi-square (7 degrees
  // of freedom; 24.3 is the 0.999 quantile).
  constexpr int kTrials = 80000;
  std::vector<int> first(8, 0);
  for (int seed = 0; seed < kTrials; ++seed) ++first[matdataset::seeded_permutation(8, static_cast<uint64_t>(seed))[0]];
  double chi2 = 0.0;
  for (int count : first) chi2 += (count - kTrials / 8.0) * (count - kTrials / 8.0) / (kTrials / 8.0);
  INFO("chi^2 = " << chi2);
  CHECK(chi2 < 24.3);
}

TEST_CASE("A loader visits every sample once per epoch, in an order set by seed and epoch", "[learn]") {
  matdataset::LoaderSettings settings;
  settings.batch_size = 4;
  const matdataset::SampleLoader loader("unused", fake_samples(2, 3, 5), settings);  // 30 samples
  CHECK(loader.batch_count() == 8);
  const std::vector<size_t> epoch0 = loader.epoch_order(0), epoch1 = loader.epoch_order(1);
  CHECK(epoch0 != epoch1);
  CHECK(epoch0 == matdataset::SampleLoader("unused", fake_samples(2, 3, 5), settings).epoch_order(0));
  std::set<size_t> seen(epoch0.begin(), epoch0.end());
  CHECK(seen.size() == 30);
  settings.drop_last = true;
  CHECK(matdataset::SampleLoader("unused", fake_samples(2, 3, 5), settings).batch_count() == 7);
  settings.shuffle = false;
  const std::vector<size_t> in_order = matdataset::SampleLoader("unused", fake_samples(2, 3, 5), settings).epoch_order(3);
  CHECK(std::is_sorted(in_order.begin(), in_order.end()));
}

TEST_CASE("The variant-level split keeps every variant folder whole", "[learn]") {
  const std::vector<matdataset::SampleId> samples = fake_samples(4, 5, 3);  // 20 folders of 3 frames
  const auto splits = matdataset::split_by_variant(samples, matdataset::SplitRatios{0.7, 0.2, 0.1}, 42);
  REQUIRE(splits.size() == 3);
  CHECK(splits[1].size() == 4 * 3);  // floor(0.2 * 20) folders
  CHECK(splits[2].size() == 2 * 3);  // floor(0.1 * 20)
  CHECK(splits[0].size() == 14 * 3);
  std::set<std::string> folders[3];
  for (int s = 0; s < 3; ++s)
    for (const matdataset::SampleId& id : splits[static_cast<size_t>(s)]) folders[s].insert(id.object + "/" + id.variant);
  for (const std::string& f : folders[0]) {
    CHECK(folders[1].count(f) == 0);
    CHECK(folders[2].count(f) == 0);
  }
  CHECK(matdataset::split_by_variant(samples, matdataset::SplitRatios{0.7, 0.2, 0.1}, 42)[1] == splits[1]);
  CHECK(matdataset::split_by_variant(samples, matdataset::SplitRatios{0.7, 0.2, 0.1}, 7)[1] != splits[1]);
  CHECK_THROWS_WITH(matdataset::split_by_variant(samples, matdataset::SplitRatios{0.7, 0.2, 0.2}, 42), Catch::Contains("sum to 1"));
}
