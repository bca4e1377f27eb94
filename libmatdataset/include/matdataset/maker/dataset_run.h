#pragma once
// Rendering a planned dataset (or one shard of it) into its folder, resumably: the dataset's and
// each variant's records first (they follow from the configuration alone, so every shard writes
// the same bytes), then every frame of the shard that is not there whole already, each written
// as a set of files renamed together.
#include <atomic>
#include <cstdint>
#include <functional>
#include <string>

#include "matdataset/maker/dataset_config.h"
#include "matdataset/maker/dataset_plan.h"

namespace matdataset {

struct RunOptions {
  Shard shard;
  int threads = 0;
  const std::atomic<bool>* cancel = nullptr;
  // Called after each frame of the shard, rendered or found complete: (done, total, rendered).
  std::function<void(size_t, size_t, size_t)> progress;
  // Called once for each thing a mesh file holds that its reader does not apply ("<file>: <note>",
  // matgeom::ObjectAsset::notes), before the first frame.
  std::function<void(const std::string&)> note;
};

struct RunSummary {
  size_t frames = 0;    // of this shard
  size_t rendered = 0;  // this run
  size_t skipped = 0;   // found complete
  double seconds = 0.0;
  double render_seconds = 0.0;  // of the frames rendered
  bool cancelled = false;
  std::vector<SplitFile> splits;  // written to config/
  std::vector<std::string> empty_frames;    // rendered this run with the object in no pixel: "vase/var000/003"
  // Rendered this run with distractors: those whose first draw hid too much of the target and was
  // drawn again, and those no draw showed enough of (each kept at its best draw), named.
  size_t redrawn_frames = 0;
  std::vector<std::string> hidden_frames;
  // Rendered this run in surroundings that let none of the frame's light reach the object.
  std::vector<std::string> unlit_frames;
};

// Throws matbase::InputError when an object, a material or the folder's earlier contents do not fit the
// configuration (a variant made with other settings), std::runtime_error when a write fails.
RunSummary run_dataset(const DatasetConfig& config, const DatasetPlan& plan, const RunOptions& options);

// The bytes of every file under `folder`.
uint64_t folder_bytes(const std::string& folder);

}  // namespace matdataset
