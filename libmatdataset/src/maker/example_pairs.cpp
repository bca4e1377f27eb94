#include "matdataset/maker/example_pairs.h"

#include <string>

#include <fmt/format.h>

#include "matdataset/maker/dataset_config.h"
#include "matdataset/maker/dataset_plan.h"
#include "matdataset/maker/dataset_run.h"

namespace matdataset {

ExamplePairs render_example_pairs(const std::filesystem::path& root, int side, int reference_samples, int noisy_samples,
                                  const std::function<void(const char*, size_t, size_t)>& progress) {
  const std::string yaml = fmt::format(R"(materials:
  all: [wood/raw:1, metal/polished:2]
objects:
  - {{builtin: vase}}
  - {{builtin: chair}}
camera: {{grid: [1, 2], phi_deg: [60, 60]}}
render: {{resolution: {}, hdr_images: true, material_resolution: 64}}
)",
                                       side);
  const ExamplePairs pairs{root / "reference", root / "noisy"};
  const struct {
    const char* name;
    const std::filesystem::path& folder;
    int samples, seed;
  } datasets[] = {{"reference", pairs.reference, reference_samples, 1}, {"noisy", pairs.noisy, noisy_samples, 2}};
  for (const auto& dataset : datasets) {
    const DatasetConfig config =
        parse_config(yaml, "the example pairs", std::filesystem::current_path(),
                     {{"output", "\"" + dataset.folder.string() + "\"", "example pairs"},
                      {"render.samples", std::to_string(dataset.samples), "example pairs"},
                      {"render.seed", std::to_string(dataset.seed), "example pairs"}});
    RunOptions run;
    if (progress)
      run.progress = [&progress, &dataset](size_t done, size_t total, size_t) { progress(dataset.name, done, total); };
    run_dataset(config, plan_dataset(config), run);
  }
  return pairs;
}

}  // namespace matdataset
