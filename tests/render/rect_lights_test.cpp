// The blocked ray test against rectangular lamps (libmatrender/src/lights/rect_lights)
// against a plain double-precision ray-rectangle intersection, on random rays and lamps.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "uniform_floats.h"
#include "lights/rect_lights.h"

using namespace matrender;

namespace {

// Distance to the lamp's emitting (-Z) side, or -1: the ray meets the plane of the lamp from
// its -Z side inside the rectangle.
double reference_hit(const RectLamp& lamp, const glm::dvec3& o, const glm::dvec3& d, double t_max) {
  const glm::dvec3 c(lamp.light_to_world[3]);
  const glm::dvec3 ax = glm::normalize(glm::dvec3(lamp.light_to_world[0]));
  const glm::dvec3 ay = glm::normalize(glm::dvec3(lamp.light_to_world[1]));
  const glm::dvec3 back = glm::cross(ax, ay);
  if (!(glm::dot(d, back) > 0.0)) return -1.0;
  const double t = glm::dot(c - o, back) / glm::dot(d, back);
  if (!(t > 0.0 && t < t_max)) return -1.0;
  const glm::dvec3 p = o + t * d - c;
  if (std::abs(glm::dot(p, ax)) > 0.5 * lamp.size_x || std::abs(glm::dot(p, ay)) > 0.5 * lamp.size_y) return -1.0;
  return t;
}

}  // namespace

TEST_CASE("Blocked lamp hits equal a plain ray-rectangle test", "[render]") {
  UniformFloats rng(0x5eed0004);
  const auto in_box = [&](float half) {
    return glm::vec3(half * (2.0f * rng.next() - 1.0f), half * (2.0f * rng.next() - 1.0f),
                     half * (2.0f * rng.next() - 1.0f));
  };
  std::vector<RectLamp> lamps;
  for (int i = 0; i < 11; ++i) {  // more than one block
    RectLamp lamp;
    const glm::vec3 axis = glm::normalize(in_box(1.0f) + glm::vec3(0.0f, 0.0f, 1e-3f));
    glm::dmat4 m = glm::translate(glm::dmat4(1.0), glm::dvec3(in_box(2.0f)));
    m = glm::rotate(m, 6.28 * double(rng.next()), glm::dvec3(axis));
    lamp.light_to_world = m;
    lamp.size_x = 0.2 + 1.5 * rng.next();
    lamp.size_y = 0.2 + 1.5 * rng.next();
    lamps.push_back(lamp);
  }
  std::vector<RectLight> prepared(lamps.begin(), lamps.end());
  const RectLights hits(prepared);
  int total_hits = 0, decided = 0;
  for (int r = 0; r < 20000; ++r) {
    const glm::vec3 o = in_box(3.0f);
    const glm::vec3 d = glm::normalize(in_box(1.0f) + glm::vec3(1e-4f));
    const float t_max = r % 3 == 0 ? 2.0f : INFINITY;
    std::vector<double> got(lamps.size(), -1.0);
    hits.for_each_hit(o, d, t_max, [&](size_t k, float t) { got[k] = t; });
    for (size_t k = 0; k < lamps.size(); ++k) {
      const double expected = reference_hit(lamps[k], glm::dvec3(o), glm::dvec3(d), t_max);
      // Rays within float rounding of an edge or of t_max may go either way.
      const bool near_boundary = std::abs(expected - t_max) < 1e-4;
      if ((expected > 0.0) != (got[k] > 0.0)) {
        const double edge_margin = 1e-4;
        RectLamp grown = lamps[k], shrunk = lamps[k];
        grown.size_x += edge_margin, grown.size_y += edge_margin;
        shrunk.size_x -= edge_margin, shrunk.size_y -= edge_margin;
        const bool ambiguous = (reference_hit(grown, glm::dvec3(o), glm::dvec3(d), t_max) > 0.0) !=
                               (reference_hit(shrunk, glm::dvec3(o), glm::dvec3(d), t_max) > 0.0);
        INFO("ray " << r << " lamp " << k << ": expected " << expected << ", got " << got[k]);
        CHECK((ambiguous || near_boundary));
        continue;
      }
      ++decided;
      if (expected > 0.0) {
        ++total_hits;
        CHECK(got[k] == Approx(expected).epsilon(1e-4));
      }
    }
  }
  // The random setup must exercise both outcomes.
  CHECK(total_hits > 500);
  CHECK(decided > 200000);
}

// The bounding-sphere cull must keep every true hit, the farthest from the centre included:
// rays aimed just inside a corner from far and near.
TEST_CASE("Rays aimed just inside a lamp's corners hit it", "[render]") {
  UniformFloats rng(0x5eed0005);
  std::vector<RectLamp> lamps;
  for (int i = 0; i < 6; ++i) {
    RectLamp lamp;
    const glm::dvec3 axis = glm::normalize(glm::dvec3(rng.next() - 0.5, rng.next() - 0.5, rng.next() + 0.1));
    lamp.light_to_world = glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(2.0 * i, 1.0, 3.0)),
                                      6.28 * double(rng.next()), axis);
    lamp.size_x = 0.05 + 2.0 * rng.next();
    lamp.size_y = 0.05 + 2.0 * rng.next();
    lamps.push_back(lamp);
  }
  std::vector<RectLight> prepared(lamps.begin(), lamps.end());
  const RectLights hits(prepared);
  int aimed = 0;
  for (size_t k = 0; k < lamps.size(); ++k) {
    const Rectangle3& r = prepared[k].rectangle();
    for (int corner = 0; corner < 4; ++corner) {
      const float fx = corner & 1 ? 0.999f : 0.001f, fy = corner & 2 ? 0.999f : 0.001f;
      const glm::vec3 target = r.corner + fx * r.length_x * r.x + fy * r.length_y * r.y;
      for (float distance : {0.01f, 1.0f, 100.0f}) {
        // From the emitting side (-z), in a random direction off the normal.
        const glm::vec3 away = glm::normalize(-r.z + 0.9f * (rng.next() - 0.5f) * r.x + 0.9f * (rng.next() - 0.5f) * r.y);
        const glm::vec3 origin = target + distance * away;
        const glm::vec3 dir = glm::normalize(target - origin);
        bool found = false;
        hits.for_each_hit(origin, dir, INFINITY, [&](size_t index, float) { found = found || index == k; });
        INFO("lamp " << k << " corner " << corner << " distance " << distance);
        CHECK(found);
        ++aimed;
      }
    }
  }
  CHECK(aimed == 72);
}
