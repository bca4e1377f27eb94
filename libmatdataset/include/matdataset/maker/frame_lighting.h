#pragma once
// What lights one frame: its setup drawn by the configuration's rule (lighting_setups.h), then
// every quantity the setup leaves open drawn from the frame's lighting seed, so that any shard,
// run or resumed run gives a frame the same light. The result is written as a scene file writes
// lights (docs/scene_format.md): transforms.json records it, the maker reads it back to render,
// and render_object renders the frame again from it.
#include <cstdint>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "matdataset/maker/dataset_plan.h"
#include "matdataset/maker/lighting_setups.h"
#include "matgeom/bounding_sphere.h"

namespace matdataset {

// The part of a frame's lighting that follows from the configuration alone (the split files are
// written before any object is loaded): its setup and, for an environment, its image.
struct LightingChoice {
  size_t setup = 0;
  std::optional<size_t> image;  // among the setup's environment images
};
LightingChoice choose_lighting(const LightingConfig& lighting, uint64_t seed, const FrameRef& frame,
                               size_t grid_views);
// What the lighting split groups frames by: the environment image's name ("forest", "hdri_04"),
// whichever setup shows it, or else the setup's name ("spot+area"), so that no image and no
// lamp-lit setup is in two splits.
std::string lighting_key(const LightingConfig& lighting, const LightingChoice& choice);

struct FrameLighting {
  std::string setup;
  // A scene file's "lights" and "background" values.
  nlohmann::ordered_json lights;
  nlohmann::ordered_json background;
  // Camera rays see the environment; otherwise the images' background stays transparent.
  bool background_visible = false;
};

// The frame's lighting in full around the object's bounding sphere `bounds`, in a room whose
// ceiling (when it has one) is at height `ceiling_z`.
FrameLighting draw_frame_lighting(const LightingConfig& lighting, uint64_t seed, const FrameRef& frame,
                                  size_t grid_views, const matgeom::Sphere& bounds,
                                  std::optional<double> ceiling_z = std::nullopt);

// The scene file's {"lights": ..., "background": ...} of a frame's lighting.
nlohmann::ordered_json scene_lighting_json(const FrameLighting& lighting);

}  // namespace matdataset
