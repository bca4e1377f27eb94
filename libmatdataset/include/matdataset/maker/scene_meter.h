#pragma once
// The grey card measured in a scene with surroundings (docs/make_dataset.md, "Exposure"): a small
// white Lambertian card at the grid's centre, the object and its distractors hidden, rendered
// from just in front as it faces each of a few of the grid's cameras. Its radiance is what the
// frame's light gives it after everything the room blocks and bounces, which the analytic meter
// (matrender/light_meter.h, nothing in the way) cannot know: a closed room under a sky, a lamp
// behind a wall.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "matgeom/camera_grid.h"
#include "matrender/render_settings.h"
#include "matrender/scene.h"
#include "matrender/scene_description.h"

namespace matdataset {

// The card's material's name among a scene's materials, and the material: white, Lambertian, no
// specular layer.
inline constexpr const char* kMeterCardMaterial = "matpredict_meter_card";
matrender::MaterialDescription meter_card_material();

// The card as a scene object: a square of side 2 about the origin facing +Z, in the card's
// material, around the subject (surroundings), to be placed by meter_card_lux.
matrender::ObjectDescription meter_card_object();

// The illuminance (lux) the card receives at the grid's centre, averaged over up to `directions`
// of the grid's cameras (spread over its cells, those not above `floor_z` left out) as it faces
// each: the card, mesh `card` of `scene`, is shown, placed with half-side 1 % of the grid's radius,
// and rendered 4 x 4 pixels from twice that in front; `hidden` meshes are hidden meanwhile. Every
// mesh is as it was afterwards. `settings` gives the bounces; the samples, seed and outputs are
// the meter's own, so the reading depends on the scene and the lighting alone.
double meter_card_lux(matrender::Scene& scene, uint32_t card, const std::vector<uint32_t>& hidden,
                      const matgeom::CameraGridSpec& grid, double floor_z, const matrender::RenderSettings& settings,
                      int directions = 8);

}  // namespace matdataset
