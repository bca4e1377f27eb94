// Judges the denoisers on held-out frames (docs/denoising.md, "Judging it"): every frame of a
// reference dataset (configs/denoiser_test.yaml at 1024 samples, with render.hdr_images) is
// rendered again from its records at a few sample counts, and the error of the raw image, of the
// a-trous filter and of the learned denoiser against the reference is printed per material class:
// the relative RMSE over the object's pixels (label > 0), in %, the mean over the class's
// frames, with the seconds each took (render, then render and denoiser). One render per count:
// both denoisers run on a copy of the same raw frame.
#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "image_error.h"
#include "matdataset/format/dataset_index.h"
#include "matdataset/format/decoded_image.h"
#include "matdataset/maker/frame_scene.h"
#include "matlearn/denoising/learned_denoiser.h"
#include "matrender/atrous_filter.h"
#include "matrender/render.h"
#include "matrender/scene_builder.h"
#include "matrender/scene_file.h"

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct Tally {
  double error = 0.0, seconds = 0.0;
  int frames = 0;
};

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"denoiser_judge: raw, filter and learned denoiser against held-out references, per material class"};
  std::string reference, weights;
  std::vector<int> spps{4, 8, 16, 32, 64, 128};
  int threads = 2, most_frames = 0;
  app.add_option("--reference", reference, "the held-out frames at many samples (make_dataset, render.hdr_images)")
      ->required();
  app.add_option("--weights", weights, "the learned denoiser's weights")->required();
  app.add_option("--spp", spps, "sample counts")->capture_default_str();
  app.add_option("--threads", threads, "render and denoiser threads")->capture_default_str();
  app.add_option("--frames", most_frames, "at most this many frames (0: all)")->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  const matlearn::LearnedDenoiser learned{fs::path(weights)};
  const matrender::AtrousFilter filter;
  // class -> spp -> mode -> tally
  std::map<std::string, std::map<int, std::array<Tally, 3>>> tallies;
  std::vector<matdataset::SampleId> frames = matdataset::index_dataset(reference);
  if (most_frames > 0 && frames.size() > static_cast<size_t>(most_frames)) frames.resize(static_cast<size_t>(most_frames));
  for (const matdataset::SampleId& id : frames) {
    const fs::path variant = fs::path(reference) / id.object / id.variant;
    const nlohmann::json metadata = nlohmann::json::parse(std::ifstream(variant / "metadata.json"));
    const std::string material_class = metadata.at("used_materials").begin()->at("material_family").get<std::string>();
    const matdataset::FrameScene frame_scene = matdataset::dataset_frame_scene(variant / id.stem);
    const matrender::SceneDescription description = matrender::read_scene_text(frame_scene.json, id.str(), frame_scene.folder);
    matrender::BuiltScene built = matrender::build_scene(description);
    const matbase::FloatImage truth = matdataset::decode_finite(variant / "images_hdr" / (id.stem + ".exr"));
    const matdataset::DecodedIds label = matdataset::decode_ids(variant / "label" / (id.stem + ".png"));
    std::vector<float> truth_rgb;
    for (size_t p = 0; p < label.ids.size(); ++p)
      for (size_t c = 0; c < 3; ++c) truth_rgb.push_back(truth.values[4 * p + c]);
    const double mean = bench::masked_mean(truth_rgb, label.ids, 3);
    if (mean <= 0.0) continue;  // a black frame says nothing about noise
    for (const int spp : spps) {
      matrender::RenderSettings settings = description.settings;
      settings.samples_per_pixel = spp;
      settings.seed = description.settings.seed + 7919u * static_cast<uint32_t>(spp);  // not the reference's noise
      settings.threads = threads;
      settings.aovs = filter.guide_aovs() | learned.guide_aovs();
      matrender::FrameBuffers raw;
      const auto start = Clock::now();
      matrender::render(built.scene, built.camera, settings, raw);
      const double render_seconds = seconds_since(start);
      for (int mode = 0; mode < 3; ++mode) {
        matrender::FrameBuffers frame = raw;
        const auto denoise_start = Clock::now();
        if (mode == 1) filter.denoise(frame, threads);
        if (mode == 2) learned.denoise(frame, threads);
        Tally& tally = tallies[material_class][spp][static_cast<size_t>(mode)];
        tally.error += bench::masked_rmse(frame.color, truth_rgb, label.ids, 3) / mean;
        tally.seconds += render_seconds + (mode == 0 ? 0.0 : seconds_since(denoise_start));
        ++tally.frames;
      }
    }
    fmt::print(stderr, "{} ({})\n", id.str(), material_class);
  }

  fmt::print("## Held-out frames: relative RMSE over the object, % (raw / filter / learned), mean over the class's "
             "frames; reference {}\n\n| class | frames |",
             reference);
  for (const int spp : spps) fmt::print(" {} spp |", spp);
  fmt::print("\n|---|---:|");
  for (size_t k = 0; k < spps.size(); ++k) fmt::print("---|");
  fmt::print("\n");
  std::map<int, std::array<Tally, 3>> all;
  for (const auto& [material_class, by_spp] : tallies) {
    fmt::print("| {} | {} |", material_class, by_spp.begin()->second[0].frames);
    for (const int spp : spps) {
      const std::array<Tally, 3>& t = by_spp.at(spp);
      fmt::print(" {:.2f} / {:.2f} / {:.2f} |", 100.0 * t[0].error / t[0].frames, 100.0 * t[1].error / t[1].frames,
                 100.0 * t[2].error / t[2].frames);
      for (size_t m = 0; m < 3; ++m) {
        all[spp][m].error += t[m].error;
        all[spp][m].seconds += t[m].seconds;
        all[spp][m].frames += t[m].frames;
      }
    }
    fmt::print("\n");
  }
  fmt::print("| all | {} |", all.begin()->second[0].frames);
  for (const int spp : spps)
    fmt::print(" {:.2f} / {:.2f} / {:.2f} |", 100.0 * all[spp][0].error / all[spp][0].frames,
               100.0 * all[spp][1].error / all[spp][1].frames, 100.0 * all[spp][2].error / all[spp][2].frames);
  fmt::print("\n| seconds a frame | |");
  for (const int spp : spps)
    fmt::print(" {:.2f} / {:.2f} / {:.2f} |", all[spp][0].seconds / all[spp][0].frames,
               all[spp][1].seconds / all[spp][1].frames, all[spp][2].seconds / all[spp][2].frames);
  fmt::print("\n");
  return 0;
}
