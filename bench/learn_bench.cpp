// learn_bench: training step time (batch 8, 2 threads by default) and inference images/s of each
// regressor, ours (libtorch) beside the same architecture in PyTorch 1.13 (Debian's
// python3-torch, bench/pytorch_regressors.py) measured in the same run, each network on each side
// in its own process so that the peak memory is its own. Prints a markdown table.
#include <sys/resource.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "matlearn/models/regressor.h"
#include "matlearn/training/batch.h"
#include "matlearn/training/loss.h"
#include "matlearn/training/tensor_memory_cache.h"

namespace {

constexpr int64_t kBatch = 8;

// As Python's statistics.median: the mean of the middle two of an even count.
double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t half = v.size() / 2;
  return v.size() % 2 ? v[half] : 0.5 * (v[half - 1] + v[half]);
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Measures one network in this process and prints the JSON line pytorch_regressors.py prints.
void measure(const std::string& name, int threads, int warm_up, int steps, int size, bool system_allocator) {
  if (!system_allocator) matlearn::use_tensor_memory_cache();  // as train_regressor and evaluate do
  torch::set_num_threads(threads);
  torch::manual_seed(0);
  const matlearn::OutputLayout layout = matlearn::OutputLayout::paper();
  const auto model = matlearn::make_regressor(matlearn::architecture_named(name).architecture, layout.output_channels());
  torch::optim::Adam optimizer(model->parameters(), torch::optim::AdamOptions(2e-4));
  matlearn::Batch batch;
  batch.input = torch::rand({kBatch, 3, size, size});
  batch.target = torch::rand({kBatch, layout.output_channels(), size, size});
  batch.mask = torch::ones({kBatch, 1, size, size});
  batch.labels = torch::full({kBatch, size, size}, matlearn::kIgnoredLabel, torch::kLong);
  model->train();
  std::vector<double> step_times, forward_times;
  for (int step = 0; step < warm_up + steps; ++step) {
    const auto start = std::chrono::steady_clock::now();
    optimizer.zero_grad();
    matlearn::training_loss(model->forward(batch.input), batch, layout, matlearn::RegressionLoss::mse).total.backward();
    optimizer.step();
    if (step >= warm_up) step_times.push_back(seconds_since(start));
  }
  model->eval();
  {
    torch::NoGradGuard no_grad;
    for (int step = 0; step < warm_up + steps; ++step) {
      const auto start = std::chrono::steady_clock::now();
      model->forward(batch.input);
      if (step >= warm_up) forward_times.push_back(seconds_since(start));
    }
  }
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const nlohmann::json line = {{"network", name},
                               {"parameters", matlearn::parameter_count(*model)},
                               {"step_s", median(step_times)},
                               {"images_per_s", static_cast<double>(kBatch) / median(forward_times)},
                               {"peak_mib", static_cast<double>(usage.ru_maxrss) / 1024.0}};
  fmt::print("{}\n", line.dump());
}

nlohmann::json run_child(const std::string& command) {
  std::unique_ptr<FILE, decltype(&pclose)> pipe(popen(command.c_str(), "r"), pclose);
  if (!pipe) throw std::runtime_error("cannot run " + command);
  std::string output;
  std::array<char, 4096> buffer{};
  while (fgets(buffer.data(), buffer.size(), pipe.get())) output += buffer.data();
  const size_t brace = output.rfind('{');
  if (brace == std::string::npos) throw std::runtime_error(command + " printed no result:\n" + output);
  return nlohmann::json::parse(output.substr(brace));
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Training step and inference speed of libmatlearn's regressors beside PyTorch 1.13's, same run."};
  std::string single;
  std::vector<std::string> networks;
  int threads = 2, warm_up = 2, steps = 3, size = 224;
  bool system_allocator = false;
  app.add_option("--networks", networks, "networks to measure (default: all six)");
  app.add_option("--threads", threads, "torch threads on both sides")->capture_default_str();
  app.add_option("--warm-up", warm_up, "untimed steps first (both sides take two to settle)")->capture_default_str();
  app.add_option("--steps", steps, "timed steps after the warm-up (the median is kept)")->capture_default_str();
  app.add_flag("--system-allocator", system_allocator,
               "our side allocates tensors through glibc, as PyTorch does, instead of matlearn's memory cache");
  app.add_option("--size", size, "image side")->capture_default_str();
  app.add_option("--single", single, "measure one network in this process (used by the driver)");
  CLI11_PARSE(app, argc, argv);
  if (!single.empty()) {
    measure(single, threads, warm_up, steps, size, system_allocator);
    return 0;
  }
  if (networks.empty())
    for (const matlearn::ArchitectureInfo& a : matlearn::architectures()) networks.push_back(a.name);
  const std::string self = "/proc/self/exe";
  const std::string ours_command =
      fmt::format("{} --threads {} --warm-up {} --steps {} --size {}{} --single ", std::filesystem::read_symlink(self).string(),
                  threads, warm_up, steps, size, system_allocator ? " --system-allocator" : "");
  const std::string theirs_command = fmt::format("/usr/bin/python3 {} ", MATPREDICT_PYTORCH_SCRIPT);
  fmt::print("Batch {} at {}x{}, {} threads, median of {} steps after {} warm-up steps; Adam, masked MSE on sigmoid "
             "maps; our tensors through {}.\n\n",
             kBatch, size, size, threads, steps, warm_up, system_allocator ? "glibc" : "matlearn's memory cache");
  fmt::print("| network | parameters (ours / PyTorch) | train step s, ours | PyTorch | ratio | inference img/s, ours | "
             "PyTorch | peak MiB, ours | PyTorch |\n|---|---|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const std::string& name : networks) {
    const nlohmann::json ours = run_child(ours_command + name);
    const nlohmann::json theirs =
        run_child(theirs_command + fmt::format("{} {} {} {} {} 2>/dev/null", name, threads, warm_up, steps, size));
    fmt::print("| {} | {} / {} | {:.2f} | {:.2f} | {:.2f} | {:.1f} | {:.1f} | {:.0f} | {:.0f} |\n", name,
               ours["parameters"].get<int64_t>(), theirs["parameters"].get<int64_t>(), ours["step_s"].get<double>(),
               theirs["step_s"].get<double>(), ours["step_s"].get<double>() / theirs["step_s"].get<double>(),
               ours["images_per_s"].get<double>(), theirs["images_per_s"].get<double>(), ours["peak_mib"].get<double>(),
               theirs["peak_mib"].get<double>());
    std::fflush(stdout);
  }
  return 0;
}
