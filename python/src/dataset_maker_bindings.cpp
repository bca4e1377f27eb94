#include "dataset_maker_bindings.h"

#include <atomic>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/stl.h>

#include "matbase/input_error.h"
#include "matdataset/maker/dataset_config.h"
#include "matdataset/maker/dataset_plan.h"
#include "matdataset/maker/dataset_run.h"
#include "json_text.h"
#include "releasing_gil.h"

namespace matpredict_python {
namespace {

namespace py = pybind11;

// Where a configuration dict's errors point: "the configuration: render.samples: ...".
constexpr const char* kConfigurationSource = "the configuration";

py::dict make_dataset(const py::dict& configuration, const py::object& output, int threads,
                      const std::string& shard_text, const py::object& progress) {
  if (!progress.is_none() && !PyCallable_Check(progress.ptr()))
    throw py::type_error("progress: expected None or a callable taking (frames done, frames in all)");
  if (threads < 0) throw py::value_error("threads: expected 0 (all) or more, got " + std::to_string(threads));
  const std::optional<matdataset::Shard> shard = matdataset::parse_shard(shard_text);
  if (!shard) throw py::value_error("shard: expected K/N with 0 <= K < N, got \"" + shard_text + "\"");
  std::vector<matdataset::Override> overrides;
  if (!output.is_none())
    overrides.push_back({"output", json_text(output, matbase::DocumentSource("output", matbase::PathStyle::DottedKeys)), "output"});
  const matbase::DocumentSource source(kConfigurationSource, matbase::PathStyle::DottedKeys);
  const matdataset::DatasetConfig config =
      matdataset::parse_config(json_text(configuration, source), kConfigurationSource, std::filesystem::current_path(), overrides);
  const matdataset::DatasetPlan plan = matdataset::plan_dataset(config);

  std::atomic<bool> cancel{false};
  std::atomic<size_t> done{0}, total{plan.frames.size()};
  matdataset::RunOptions run;
  run.shard = *shard;
  run.threads = threads;
  run.cancel = &cancel;
  run.progress = [&](size_t frames_done, size_t frames_total, size_t) {
    total.store(frames_total);
    done.store(frames_done);
  };
  matdataset::RunSummary summary;
  size_t reported = static_cast<size_t>(-1);
  run_releasing_gil([&] { summary = matdataset::run_dataset(config, plan, run); }, cancel, [&] {
    if (const size_t d = done.load(); !progress.is_none() && d != reported) {
      reported = d;
      progress(d, total.load());
    }
  });
  // Written, as rendered, but a frame without the object trains to a loss of 0: not a success.
  if (!summary.empty_frames.empty())
    throw std::runtime_error(std::to_string(summary.empty_frames.size()) + " frames show the object in no pixel (the first: " +
                             summary.empty_frames.front() + "); are the cameras too far (camera.radius) or the resolution too low?");
  if (!summary.unlit_frames.empty())
    throw std::runtime_error(std::to_string(summary.unlit_frames.size()) +
                             " frames are black: none of their light reaches the object through its surroundings (the "
                             "first: " + summary.unlit_frames.front() + "); light it from inside (a ceiling lamp, the rig)");
  py::dict splits;
  for (const matdataset::SplitFile& split : summary.splits) {
    py::dict counts;
    counts["train"] = split.train.size();
    counts["val"] = split.val.size();
    counts["test"] = split.test.size();
    splits[split.name.c_str()] = counts;
  }
  py::dict result;
  result["output"] = config.output;
  result["frames"] = summary.frames;
  result["rendered"] = summary.rendered;
  result["skipped"] = summary.skipped;
  result["seconds"] = summary.seconds;
  result["splits"] = splits;
  return result;
}

}  // namespace

void bind_dataset_maker(py::module_& module) {
  module.def("make_dataset", &make_dataset, py::arg("configuration"), py::kw_only(), py::arg("output") = py::none(),
             py::arg("threads") = 0, py::arg("shard") = "0/1", py::arg("progress") = py::none(),
             "make_dataset from Python: renders the dataset a configuration dict describes (the keys of\n"
             "make_dataset's YAML, docs/make_dataset.md; relative paths from the current folder) into\n"
             "`output` (default: its 'output' key), resuming where an earlier run stopped, the same\n"
             "bytes as the command line writes. `progress(done, total)` is called on this thread after\n"
             "each frame; Ctrl-C stops it with KeyboardInterrupt, and a call with the same configuration\n"
             "resumes. Returns {'output', 'frames', 'rendered', 'skipped', 'seconds', 'splits'}. A bad key\n"
             "or value raises matpredict.InputError naming it ('the configuration: render.samples: ...').");
}

}  // namespace matpredict_python
