#pragma once
// make_dataset's lighting (docs/make_dataset.md, "Lighting"): a list of setups, each the paper's
// rig, an environment map, a daylight sky, a ceiling lamp, groups of lamps (suns, spots, points,
// areas) or a mix, with every
// quantity a value or a range drawn for each frame, and the rule by which frames get them. What a
// frame is drawn is frame_lighting.h's.
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "matbase/document/document_node.h"
#include "matdataset/maker/drawn_number.h"

namespace matdataset {

// A lamp's colour: an RGB, or the colour of Blender's Blackbody node at a temperature drawn from
// a range in kelvin.
struct DrawnColor {
  std::optional<glm::dvec3> rgb;  // none: blackbody
  DrawnNumber kelvin;
};

// The paper's rig around the object, normalised to an illuminance at its centre, or at the
// formula's own powers (the paper's 20-200 W per lamp).
struct RigSetup {
  std::optional<DrawnNumber> illuminance_lux = DrawnNumber::value(1000.0, true);  // none: the formula's powers
};

// An equirectangular image, drawn from a list (built-in names, files, folders' images), at a
// strength and a turn about +Z; whether camera rays see it or the images keep a transparent
// background (the map lights the object without being pasted behind it).
struct EnvironmentSetup {
  std::vector<std::string> images;  // built-in names as written, else resolved paths
  DrawnNumber strength = DrawnNumber::value(1.0, true);
  DrawnNumber rotation_deg = DrawnNumber::value(0.0);
  bool visible = false;
};

// A daylight sky and sun (matrender/sky.h) with any of its settings, by the scene file's keys
// ("sun_elevation_deg", "dust", ...), a value or a range; those not given keep Blender's
// defaults. Like an environment, seen by camera rays or not.
struct SkySetup {
  std::map<std::string, DrawnNumber> settings;
  bool sun_disc = true;
  DrawnNumber strength = DrawnNumber::value(1.0, true);
  bool visible = false;
};

enum class LampKind { Sun, Spot, Point, Area };

// `count` lamps of one kind, each placed on a shell about the object's bounding sphere (centre c,
// radius r) at a drawn distance (in r), elevation and azimuth, or at given points (in r from c),
// and aimed at c. A sun has only a direction: the shell's, toward c.
struct LampGroup {
  LampKind kind = LampKind::Spot;
  DrawnNumber count = DrawnNumber::value(1.0);  // whole numbers
  DrawnNumber distance = DrawnNumber::value(3.0);
  DrawnNumber elevation_deg = {10.0, 80.0, false};
  DrawnNumber azimuth_deg = {0.0, 360.0, false};
  std::vector<glm::dvec3> at;  // given positions instead of the shell
  DrawnNumber power_w = DrawnNumber::value(100.0, true);  // spot, point, area (Blender watts)
  DrawnNumber strength = DrawnNumber::value(3.0, true);   // sun (W/m^2)
  DrawnNumber angle_deg = DrawnNumber::value(0.0);        // sun: angular diameter
  DrawnNumber cone_deg = DrawnNumber::value(45.0);        // spot: full cone angle
  DrawnNumber blend = DrawnNumber::value(0.15);           // spot
  DrawnNumber size = DrawnNumber::value(0.5);             // area: the side of a square, in r
  DrawnColor color{glm::dvec3(0.8), {}};                   // the paper's neutral grey-white
};

// A room's ceiling lamp: a square area lamp above the object facing straight down, sideways of
// its centre c by a drawn distance and bearing, at a drawn height (in the bounding radius r), its
// power set for a drawn illuminance on a card at c facing up, in the colours of indoor white
// light. Under a room's ceiling it hangs just below it where the drawn height would put it above.
struct CeilingSetup {
  DrawnNumber illuminance_lux = {300.0, 1000.0, true};
  DrawnNumber height = {3.0, 5.0, false};  // above c, in r
  DrawnNumber offset = {0.0, 1.0, false};  // sideways of c, in r
  DrawnNumber size = DrawnNumber::value(1.5);  // the square's side, in r
  DrawnColor color{std::nullopt, {2700.0, 5000.0, false}};
};

struct LightingSetup {
  std::string name;     // unique; by default its parts, "environment+sun"
  double weight = 1.0;  // the share of frames drawn under it
  std::optional<RigSetup> rig;
  std::optional<EnvironmentSetup> environment;
  std::optional<SkySetup> sky;  // a world of its own: never with an environment
  std::vector<LampGroup> lamps;
  std::optional<CeilingSetup> ceiling;
};

// How frames get their lighting: each view its own draw, each variant one draw for all its
// views, or every setup for every view (the views repeated, setup by setup).
enum class LightingAssignment { PerView, PerVariant, EverySetup };

struct LightingConfig {
  std::vector<LightingSetup> setups = {
      LightingSetup{"rig", 1.0, RigSetup{}, std::nullopt, std::nullopt, {}, std::nullopt}};
  LightingAssignment assignment = LightingAssignment::PerView;
  // The frames each grid view is rendered in: the setups' count under EverySetup, else 1.
  size_t rounds() const { return assignment == LightingAssignment::EverySetup ? setups.size() : 1; }
};

// The configuration's `lights` value: `setups` and `assign`, or the short form of one rig
// (`rig: paper`, `illuminance_lux`). Relative image paths resolve against `base`. Every value is
// checked here: a range whose ends are swapped, an image or folder that is not there (a built-in
// name whose package is not installed), a temperature outside the blackbody's table, a lamp
// inside the object's bounding sphere.
LightingConfig read_lighting(const matbase::DocumentNode& lights, const std::filesystem::path& base);

// Whether every frame gets the same lighting: one setup, the rig alone at a fixed illuminance
// (or the formula's powers).
bool lights_every_frame_alike(const LightingConfig& lighting);
// Whether any setup's environment or sky is seen by camera rays.
bool any_background_visible(const LightingConfig& lighting);

// "sun", "spot", "point", "area".
const char* lamp_kind_name(LampKind kind);

}  // namespace matdataset
