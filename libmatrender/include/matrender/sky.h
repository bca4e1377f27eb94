#pragma once
// A procedural daylight sky with no image file: Blender 3.4's Sky Texture of type Nishita on the
// World's Background (docs/conventions.md, "Sky"). Its atmosphere is precomputed into a table of
// 512 x 128 directions of the upper hemisphere, read as Cycles reads it; the ground below the
// horizon fades to black by 0.4 down. The renderer lights with it as an environment map baked
// from that table plus a sun lamp of the same angle carrying the sun disc's irradiance, so light
// sampling finds the sun however small it is. Camera rays see the sky but not the disc (lamps are
// invisible to them, lamp.h); reflections and lighting see both.
#include <optional>
#include <string>
#include <vector>

#include "matbase/pi.h"
#include "matrender/background.h"
#include "matrender/lamp.h"

namespace matrender {

// The Sky Texture's settings (Blender's names and defaults; angles in radians, altitude in metres).
struct NishitaSky {
  double sun_elevation = 15.0 * matbase::kPi / 180.0;  // above the horizon
  // About +Z, clockwise seen from above: 0 puts the sun towards +Y, 90 degrees towards +X.
  double sun_rotation = 0.0;
  double sun_size = 0.545 * matbase::kPi / 180.0;  // the disc's angular diameter
  double sun_intensity = 1.0;                      // the disc's radiance multiplier
  bool sun_disc = true;
  double altitude = 0.0;  // Cycles evaluates at 1 m at least
  double air_density = 1.0;
  double dust_density = 1.0;
  double ozone_density = 1.0;
  double strength = 1.0;  // the Background node's Strength, on sky and disc alike
};

// The sky's numeric settings as scene files, render_object --sky and make_dataset's sky setups
// name them, in the key's unit, with the range each accepts (Blender's, except that the sun
// stays above the horizon: below it the sky is a twilight no grey card meters): declared once.
// sun_disc (true or false) and the Background's strength are read beside them.
struct SkySetting {
  const char* key;  // "sun_elevation_deg"
  double NishitaSky::*field;
  double unit;  // the field's value per unit of the key (pi / 180 for degrees)
  double low, high;
  bool low_open;  // (low, high] instead of [low, high]
  const char* meaning;
};
const std::vector<SkySetting>& sky_settings();

// The first setting outside its range, or a strength that is not a finite number >= 0, as
// "sun_elevation_deg -5 is not in [0, 90] (...)"; or nothing.
std::optional<std::string> sky_problem(const NishitaSky& sky);

// The sky as the renderer takes it: an environment map (rows of `map_width` / 2 texels, scene-
// linear Rec.709, the sky already turned) and, for a disc above the horizon, the sun lamp whose
// irradiance and colour are the disc's integrated radiance (its limb darkening included).
// Throws std::invalid_argument for a sky sky_problem refuses.
struct SkyLighting {
  EnvironmentMap map;
  std::optional<SunLamp> sun;
};
SkyLighting sky_lighting(const NishitaSky& sky, int map_width = 1024);

}  // namespace matrender
