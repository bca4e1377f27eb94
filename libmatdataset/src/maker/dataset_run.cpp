#include "matdataset/maker/dataset_run.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <memory>

#include <fmt/format.h>

#include "matbase/cancellation.h"
#include "matbase/file/atomic_file.h"
#include "matbase/file/input_file.h"
#include "matdataset/format/dataset_writer.h"
#include "matdataset/format/decoded_image.h"
#include "matdataset/maker/dataset_checks.h"
#include "matdataset/maker/object_renderer.h"
#include "matdataset/maker/texture_targets.h"

namespace matdataset {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The variant's records; a folder that holds a variant made with other settings is refused
// rather than mixed with this run's frames.
void write_variant_records(const DatasetConfig& config, const DatasetPlan& plan, ObjectRenderer& renderer,
                           size_t object, size_t variant) {
  const fs::path folder = variant_folder(config, plan, object, variant);
  fs::create_directories(folder);
  VariantMetadata metadata;
  metadata.materials = renderer.slot_materials();
  metadata.width = config.render.width;
  metadata.height = config.render.height;
  metadata.samples = config.render.settings.samples_per_pixel;
  metadata.provenance_json = renderer.provenance_json(plan, variant);
  metadata.contents = frame_contents(config, object);
  for (const char* record : {"metadata.json", "transforms.json", "material_segmentation_map.json"})
    matbase::remove_stale_temporaries(folder / record, false);
  const fs::path metadata_file = folder / "metadata.json";
  const std::string text = variant_metadata_text(metadata);
  std::string before;
  const bool existed = fs::exists(metadata_file);
  if (existed)
    if (const std::optional<std::string> problem = matbase::read_whole_file(metadata_file, before))
      throw std::runtime_error(*problem);
  if (existed && before != text)
    throw matbase::InputError(metadata_file.string() +
                     ": this variant was made with other settings (its metadata differs from this run's); "
                     "render into another --output, or delete the folder to render it again");
  matbase::write_file_atomically(metadata_file, text);
  std::vector<FramePose> poses;
  for (const size_t view : plan.object_views[object]) poses.push_back(renderer.view_pose(view, view_stem(plan, view)));
  write_transforms(folder, renderer.intrinsics(), poses, frame_contents(config, object));
  write_segmentation_map_json(folder);
}

// Whether a label map marks any pixel as the object's.
template <class Label>
bool shows_object(const std::vector<Label>& labels) {
  return std::any_of(labels.begin(), labels.end(), [](Label label) { return label > 0; });
}

// "vase/var000/003", as split files name frames.
std::string frame_id(const DatasetConfig& config, const fs::path& variant_folder, const FrameRef& frame,
                     const std::string& stem) {
  return config.objects[frame.object].name + "/" + variant_folder.filename().string() + "/" + stem;
}

}  // namespace

RunSummary run_dataset(const DatasetConfig& config, const DatasetPlan& plan, const RunOptions& options) {
  const Clock::time_point start = Clock::now();
  RunSummary summary;
  for (size_t k = 0; k < plan.frames.size(); ++k) summary.frames += options.shard.owns(k) ? 1 : 0;
  for (const std::string& note : check_before_writing(config))
    if (options.note) options.note(note);
  check_output_matches_plan(config, plan);
  summary.splits = write_dataset_records(config, plan);
  if (config.paper_texture_layout) write_material_references(config);

  size_t done = 0;
  std::unique_ptr<ObjectRenderer> renderer;
  size_t current_object = SIZE_MAX, current_variant = SIZE_MAX;
  for (size_t k = 0; k < plan.frames.size(); ++k) {
    if (!options.shard.owns(k)) continue;
    const FrameRef& frame = plan.frames[k];
    if (frame.object != current_object) {
      renderer.reset();  // one object's scene in memory at a time
      renderer = std::make_unique<ObjectRenderer>(config, frame.object);
      current_object = frame.object;
      current_variant = SIZE_MAX;
    }
    if (frame.variant != current_variant) {
      try {
        renderer->select_variant(frame.variant, plan.variants[frame.object][frame.variant], options.cancel);
      } catch (const matbase::Cancelled&) {
        summary.cancelled = true;
        break;
      }
      write_variant_records(config, plan, *renderer, frame.object, frame.variant);
      current_variant = frame.variant;
    }
    const fs::path folder = variant_folder(config, plan, frame.object, frame.variant);
    const std::string stem = view_stem(plan, frame.view);
    // The paper's layout files the screenshot under the variant's one material.
    const std::string material =
        variant_material_names(config.objects[frame.object], plan.variants[frame.object][frame.variant]).front();
    const fs::path screenshot = texture_target_screenshot_path(
        texture_target_root(config), config.objects[frame.object].name, material, stem);
    if (frame_is_complete(folder, stem, config.render.width, config.render.height, frame_contents(config, frame.object)) &&
        (!config.paper_texture_layout || texture_target_screenshot_is_complete(screenshot))) {
      ++summary.skipped;
      if (!shows_object(decode(folder / "label" / (stem + ".png")).values))
        summary.empty_frames.push_back(frame_id(config, folder, frame, stem));
    } else {
      // Only this shard writes the frame: whatever temporaries of it are there were left by a
      // run of this shard that was killed outright.
      for (const DatasetMapInfo& info : dataset_maps())
        matbase::remove_stale_temporaries(folder / info.folder / (stem + info.extension), true);
      const Clock::time_point frame_start = Clock::now();
      FrameMaps maps;
      if (!renderer->render(frame.view, frame_seed(config.seed, frame, config.render.settings.seed), options.threads, options.cancel, maps)) {
        summary.cancelled = true;
        break;
      }
      write_frame_maps(folder, stem, maps);
      if (!shows_object(maps.label)) summary.empty_frames.push_back(frame_id(config, folder, frame, stem));
      if (renderer->view_lighting(frame.view).unlit) summary.unlit_frames.push_back(frame_id(config, folder, frame, stem));
      const SurroundingsKind kind = config.objects[frame.object].surroundings.kind;
      if (kind == SurroundingsKind::Distractors || kind == SurroundingsKind::Scan) {
        const ObjectRenderer::ViewSurroundings& drawn = renderer->view_surroundings(frame.view);
        if (drawn.tries > 1) ++summary.redrawn_frames;
        if (!drawn.satisfied)
          summary.hidden_frames.push_back(
              kind == SurroundingsKind::Scan
                  ? fmt::format("{} ({:.0f} % visible through the scan)", frame_id(config, folder, frame, stem),
                                100.0 * drawn.visible_fraction)
                  : fmt::format("{} ({:.0f} % visible after {} draws)", frame_id(config, folder, frame, stem),
                                100.0 * drawn.visible_fraction, drawn.tries));
      }
      if (config.paper_texture_layout)
        write_texture_target_screenshot(texture_target_root(config), config.objects[frame.object].name,
                                        material, stem, maps);
      summary.render_seconds += seconds_since(frame_start);
      ++summary.rendered;
    }
    ++done;
    if (options.progress) options.progress(done, summary.frames, summary.rendered);
    if (options.cancel && options.cancel->load()) {
      summary.cancelled = done < summary.frames;
      break;
    }
  }
  summary.seconds = seconds_since(start);
  return summary;
}

uint64_t folder_bytes(const std::string& folder) {
  uint64_t bytes = 0;
  std::error_code error;
  for (fs::recursive_directory_iterator it(folder, error), end; !error && it != end; it.increment(error))
    if (it->is_regular_file(error)) bytes += it->file_size(error);
  return bytes;
}

}  // namespace matdataset
