// render_object: renders one view of an object or of a scene file, with the pixel-aligned AOVs.
// This file only parses the command line, calls the parts that do the work and reports.
#include <algorithm>
#include <atomic>
#include <cstdio>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "common/command_line.h"
#include "common/exit_codes.h"
#include "common/interrupt.h"
#include "matbase/cancellation.h"
#include "matbase/file/output_folder.h"
#include "matbase/memory_limit.h"
#include "matgeom/builtin/builtin_objects.h"
#include "matmaterial/library/material_library.h"
#include "matmaterial/material_classes.h"
#include "matmaterial/material_parameters.h"
#include "matrender/image_io.h"
#include "matrender/light_meter.h"
#include "matrender/render.h"
#include "matrender/texture_cache.h"
#include "options.h"
#include "common/progress_bar.h"
#include "matrender/scene_builder.h"

using render_object::Options;
using matrender::BuiltScene;
using matbase::InputError;
using matrender::SceneDescription;

namespace {

using app_support::kInputError;
using app_support::kRuntimeFailure;

int report_error(const std::string& message, int exit_code) {
  return app_support::report_error("render_object", message, exit_code);
}

void report_files(const std::vector<std::string>& files, const std::string& folder) {
  fmt::print("wrote {} files to {}:\n", files.size(), folder);
  for (const std::string& file : files) fmt::print("  {}\n", file);
}

void report_rig(const BuiltScene& built) {
  if (!built.rig) return;
  const matgeom::LightRig& rig = *built.rig;
  fmt::print("light rig: {} ring + {} accent lamps around a sphere of radius {:.3f} m; "
             "illuminance at its centre {:.0f} lx{}\n",
             rig.ring_count, rig.lights.size() - static_cast<size_t>(rig.ring_count), built.bounds.radius,
             rig.illuminance_lux,
             rig.power_scale == 1.0 ? "" : fmt::format(" (powers scaled by {:.3g})", rig.power_scale));
}

void report_summary(const matrender::RenderStats& stats, const BuiltScene& built, const matrender::RenderSettings& settings) {
  const double seconds = std::max(stats.seconds, 1e-9);
  const double pixels = static_cast<double>(built.camera.width) * static_cast<double>(built.camera.height);
  const double mean_samples = static_cast<double>(stats.camera_samples) / pixels;
  const std::string adaptive =
      settings.target_error > 0.0
          ? fmt::format(" (to a target error of {:.3g} %: {:.3g} % predicted, {:.1f} samples a pixel on average)",
                        100.0 * settings.target_error, 100.0 * stats.predicted_error, mean_samples)
      : settings.noise_threshold > 0.0 ? fmt::format(" (adaptive: {:.1f} a pixel on average)", mean_samples)
                                       : "";
  fmt::print("rendered {}x{} at {} spp{} in {:.2f} s: {:.1f} M samples/s, {:.1f} M rays/s, {} discarded samples, "
             "BVH {:.0f} ms\n",
             built.camera.width, built.camera.height, settings.samples_per_pixel, adaptive, stats.seconds,
             stats.camera_samples / seconds * 1e-6, stats.rays / seconds * 1e-6, stats.discarded_samples,
             built.scene.bvh_build_seconds() * 1e3);
}

// Only scenes with image textures have texels to report.
void report_textures() {
  const matrender::TextureCacheStats cache = matrender::texture_cache_stats();
  if (cache.peak_bytes == 0) return;
  fmt::print("textures: at most {} of texels in memory (limit {}), {} mip levels dropped, {} made again\n",
             matbase::byte_size_text(static_cast<double>(cache.peak_bytes)),
             matbase::byte_size_text(static_cast<double>(cache.limit_bytes)), cache.evictions, cache.reloads);
}

int render_and_write(const Options& options) {
  if (const std::optional<std::string> problem = matbase::output_folder_problem(options.output_folder))
    throw matbase::InputError("--output: " + *problem);
  const std::atomic<bool>* cancel = app_support::cancel_on_interrupt();
  matrender::set_texture_memory_limit(options.texture_memory_mib << 20);
  const SceneDescription description = render_object::describe_scene(options);
  BuiltScene built;
  try {
    built = matrender::build_scene(description, cancel);
  } catch (const matbase::Cancelled&) {
    return report_error("interrupted; nothing written", app_support::interrupted_exit_code());
  }
  for (const std::string& note : built.notes) fmt::print(stderr, "render_object: note: {}\n", note);

  matrender::RenderSettings settings = description.settings;
  app_support::ProgressBar progress("render");
  settings.progress = [&progress](double fraction) { progress.update(fraction); };
  settings.cancel = cancel;
  matrender::FrameBuffers frame;
  const matrender::RenderStats stats = matrender::render(built.scene, built.camera, settings, frame);
  progress.finish();
  if (stats.cancelled) return report_error("interrupted; nothing written", app_support::interrupted_exit_code());

  double exposure_stops = description.exposure_stops;
  if (options.exposure_auto) {
    exposure_stops = matrender::grey_card_exposure(built.scene.lamps(), built.scene.background(), built.bounds.center,
                                                   glm::dvec3(built.camera.camera_to_world[3]));
    fmt::print("exposure: {:+.2f} stops by the grey-card rule at the objects' centre\n", exposure_stops);
  }
  const std::vector<std::string> files =
      matrender::write_frame(frame, options.output_folder, built.frame_stem, exposure_stops);
  report_files(files, options.output_folder);
  report_rig(built);
  report_summary(stats, built, settings);
  report_textures();
  // A signal that came while the files were written let them finish: they are complete, and the
  // exit code still says the run was asked to stop.
  if (cancel->load()) return report_error("interrupted while writing; the files above are complete",
                                          app_support::interrupted_exit_code());
  return 0;
}

void list_objects() {
  for (const std::string& name : matgeom::builtin_object_names()) fmt::print("{}\n", name);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Renders one view of an object (built-in, glTF) or of a JSON scene file with matpredict's path "
               "tracer, writing colour (EXR + PNG) and pixel-aligned AOVs. With no arguments it renders the "
               "built-in vase under the paper's light rig into ./render_out/.",
               "render_object"};
  app.footer("Command-line camera and render options override the scene file's values. Exit codes: 0 done, "
             "1 render or write failure, 2 bad option or input, 130 or 143 interrupted by Ctrl-C or SIGTERM (nothing is written).");
  Options options;
  add_options(app, options);
  if (const std::optional<int> exit_code = app_support::parse_command_line(app, argc, argv, "render_object")) return *exit_code;

  try {
    if (options.list_objects) {
      list_objects();
      return 0;
    }
    if (options.list_parameters) {
      fmt::print("{}", matmaterial::material_parameters_markdown());
      return 0;
    }
    if (options.list_settings) {
      fmt::print("{}", matrender::render_settings_markdown());
      return 0;
    }
    if (options.list_materials) {
      fmt::print("{}\n{}\n{}", matmaterial::material_classes_markdown(), matmaterial::library_styles_markdown(),
                 matmaterial::library_ranges_markdown());
      return 0;
    }
    return render_and_write(options);
  } catch (const matbase::InputError& e) {
    return report_error(e.what(), kInputError);
  } catch (const std::exception& e) {
    return report_error(e.what(), kRuntimeFailure);
  }
}
