#pragma once
// Incident-light metering (docs/make_dataset.md, "Exposure"): the illuminance a small card at a
// point receives from a scene's lamps and world, nothing blocking it, and the grey-card exposure
// that follows. Lamps are Cycles' (lamp.h), converted with 683 lm/W and the Rec.709 luminance of
// their colour; the world is its uniform radiance or its environment map times strength, turned.
#include <vector>

#include <glm/glm.hpp>

#include "matgeom/camera_grid.h"
#include "matrender/background.h"
#include "matrender/lamp.h"

namespace matrender {

// The illuminance (lux) `lamp` gives a card at `point` with unit normal `normal`. Point and spot
// lamps with a radius are metered as points (the card is far from them next to their size).
double lamp_card_illuminance_lux(const Lamp& lamp, const glm::dvec3& point, const glm::dvec3& normal);

// The illuminance a world gives a card of any orientation: a uniform radiance L gives pi L; an
// environment map is folded once into cells of about 5.6 x 5.6 degrees, each its luminous flux
// per steradian times its solid angle along its flux-weighted mean direction, and a card sums
// flux x cos over the cells it faces (a sun in the map stays one bright cell).
class WorldIlluminance {
 public:
  explicit WorldIlluminance(const Background& background);
  double lux(const glm::dvec3& normal) const;

 private:
  double uniform_lux_ = 0.0;
  std::vector<glm::dvec4> cells_;  // unit direction, and the cell's lux on a card facing it
};

// The grey card's rule: the exposure at which a Lambertian card lit by E lux shows half its
// albedo. Its luminance is albedo E / (683 pi) in Blender's units, so 2^s E / (683 pi) = 1/2
// gives s = log2(683 pi / E) - 1: the stop kept in hand is for surfaces that face a lamp more
// squarely than the card faces the camera (at 0 stops in hand, half of a white vase's pixels
// clip). Clamped to matbase::kMaxExposureStops; 0 when nothing lights the card.
constexpr double kGreyCardHeadroomStops = 1.0;
double grey_card_stops(double lux);

// The grey-card rule for one view: the card at `point` facing `viewer`, lit by `lamps` and
// `background`.
double grey_card_exposure(const std::vector<Lamp>& lamps, const Background& background, const glm::dvec3& point,
                          const glm::dvec3& viewer);

// The grey-card rule for one lighting: the card at the grid's centre facing each of its cameras
// in turn, lit by `lamps` and `background`, its illuminance averaged over the views.
double grey_card_exposure(const std::vector<Lamp>& lamps, const Background& background,
                          const matgeom::CameraGridSpec& grid);

}  // namespace matrender
