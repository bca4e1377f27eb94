#pragma once
// A frame's lighting as a picture (make_dataset --preview's "lighting" column): a latitude-
// longitude panorama seen from the object's centre, in the environment image's own mapping (+X
// at the centre column, +Y a quarter to its left, straight up along the top edge): the world the
// frame is lit by (its environment, its sky, or black) at the frame's exposure, sRGB, and each
// lamp a dot where it is seen from the centre: suns yellow, spots orange, points white, area
// lamps and the rig's cyan.
#include <array>
#include <filesystem>
#include <vector>

#include <nlohmann/json.hpp>

#include "matgeom/bounding_sphere.h"

namespace matdataset {

// `lighting` is a transforms.json frame's "lighting" record (lights, background, exposure_stops);
// relative paths in it resolve against `folder`. Returns width x height display-encoded RGB,
// rows top to bottom. Throws matbase::InputError for a record the scene file's reader refuses
// (an environment image that is gone).
std::vector<std::array<float, 3>> draw_lighting_panorama(const nlohmann::json& lighting, const matgeom::Sphere& bounds,
                                                         const std::filesystem::path& folder, int width, int height);

}  // namespace matdataset
