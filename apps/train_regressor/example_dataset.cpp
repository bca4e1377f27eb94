#include "example_dataset.h"

#include <fmt/format.h>

#include "matdataset/maker/dataset_config.h"
#include "matdataset/maker/dataset_plan.h"
#include "matdataset/maker/dataset_run.h"

namespace train_regressor {

int render_example_dataset(const std::filesystem::path& root, const ExampleDatasetSize& size,
                           const std::function<void(int, int)>& progress) {
  // One material per class the repository labels most (wood, metal, plastic, fabric).
  const std::string yaml = fmt::format(R"(materials:
  all: [wood/raw:1, metal/polished:2, plastic:3, fabric/plain_weave:4]
objects:
  - {{name: vase, builtin: vase}}
  - {{name: chair, builtin: chair}}
camera:
  grid: [1, {}]
  phi_deg: [60, 60]
  theta_deg: [-180, 180]
render: {{resolution: {}, samples: {}, material_resolution: 64}}
)",
                                       size.views, size.resolution, size.samples);
  const matdataset::DatasetConfig config =
      matdataset::parse_config(yaml, "train_regressor's example dataset", std::filesystem::current_path(),
                               {{"output", "\"" + root.string() + "\"", "train_regressor"}});
  const matdataset::DatasetPlan plan = matdataset::plan_dataset(config);
  matdataset::RunOptions run;
  run.progress = [&progress](size_t done, size_t total, size_t) {
    if (progress) progress(static_cast<int>(done), static_cast<int>(total));
  };
  matdataset::run_dataset(config, plan, run);
  return static_cast<int>(plan.frames.size());
}

}  // namespace train_regressor
