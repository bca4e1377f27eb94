#pragma once
// Small scenes the render tests share.
#include <cmath>
#include <vector>

#include <glm/glm.hpp>

#include "matbase/pi.h"
#include "matgeom/mesh.h"
#include "matrender/camera.h"
#include "matrender/frame.h"
#include "matrender/lamp.h"
#include "matrender/material.h"
#include "matrender/render.h"
#include "matrender/scene.h"

namespace test_scenes {

// Square of side `size` in the plane z = height, centred on the origin, normal +Z.
inline matgeom::TriangleMesh horizontal_square(double size, double height = 0.0) {
  const float h = static_cast<float>(0.5 * size);
  const float z = static_cast<float>(height);
  matgeom::TriangleMesh m;
  m.positions = {{-h, -h, z}, {h, -h, z}, {h, h, z}, {-h, h, z}};
  m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

// Sphere of `radius` around `center`, `rings` rings of 2 rings segments, wound outward (front
// faces outside), with smooth vertex normals.
inline matgeom::TriangleMesh uv_sphere(double radius, int rings, const glm::dvec3& center = glm::dvec3(0.0)) {
  matgeom::TriangleMesh m;
  const int segments = 2 * rings;
  for (int i = 0; i <= rings; ++i)
    for (int j = 0; j <= segments; ++j) {
      const double theta = matbase::kPi * i / rings, phi = 2.0 * matbase::kPi * j / segments;
      const glm::dvec3 n(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
      m.positions.emplace_back(center + radius * n);
      m.normals.emplace_back(n);
    }
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const uint32_t a = static_cast<uint32_t>(i * (segments + 1) + j), b = a + static_cast<uint32_t>(segments) + 1;
      if (i > 0) m.triangles.push_back({a, b, a + 1});
      if (i + 1 < rings) m.triangles.push_back({a + 1, b, b + 1});
    }
  return m;
}

// A ball of radius 0.4 on a 6 m floor of albedo 0.6, under a square area lamp of side
// `lamp_size` and 150 W, 2 m up and to the side, and the camera that sees them at 40 x 32.
inline void add_ball_on_floor(matrender::Scene& scene, const matrender::Material& ball, double lamp_size);
inline matrender::Camera ball_on_floor_camera() {
  return matrender::Camera::look_at({0.0, -2.2, 1.2}, {0, 0, 0.35}, {0, 0, 1}, 0.6, 40, 32);
}

inline matrender::Material lambert(float albedo) {
  matrender::Material m;
  m.diffuse_model = matrender::DiffuseModel::Lambert;
  m.set(matrender::MaterialParameter::BaseColor, glm::vec3(albedo));
  m.set(matrender::MaterialParameter::Specular, 0.0f);
  m.set(matrender::MaterialParameter::Metallic, 0.0f);
  return m;
}

struct PixelStatistics {
  double mean = 0.0;
  double standard_error = 0.0;  // of the mean, from the spread between pixels
};

// Mean and standard error over all pixels of one colour channel.
inline PixelStatistics channel_statistics(const matrender::FrameBuffers& frame, int channel) {
  const size_t n = static_cast<size_t>(frame.width) * frame.height;
  double sum = 0.0, sum2 = 0.0;
  for (size_t i = 0; i < n; ++i) {
    const double v = frame.color[3 * i + channel];
    sum += v;
    sum2 += v * v;
  }
  PixelStatistics s;
  s.mean = sum / n;
  const double variance = std::max(0.0, (sum2 / n - s.mean * s.mean) * n / (n - 1.0));
  s.standard_error = std::sqrt(variance / n);
  return s;
}

// Mean and standard error of the per-pixel difference a - b (channels summed) over RGB pixels
// [first, last) of two renders of one image: pixels are independent, so two estimators of the
// same image have a mean difference within a few standard errors of 0.
inline PixelStatistics difference_statistics(const std::vector<float>& a, const std::vector<float>& b, size_t first,
                                             size_t last) {
  double sum = 0.0, sum2 = 0.0;
  for (size_t p = first; p < last; ++p) {
    const double d = (double(a[3 * p]) + a[3 * p + 1] + a[3 * p + 2]) - (double(b[3 * p]) + b[3 * p + 1] + b[3 * p + 2]);
    sum += d;
    sum2 += d * d;
  }
  const double n = static_cast<double>(last - first);
  PixelStatistics s;
  s.mean = sum / n;
  s.standard_error = std::sqrt(std::max(0.0, sum2 / n - s.mean * s.mean) / (n - 1.0));
  return s;
}

inline double mean_of(const std::vector<float>& values) {
  double sum = 0.0;
  for (const float v : values) sum += v;
  return sum / static_cast<double>(values.size());
}

inline bool all_finite(const std::vector<float>& values) {
  for (float v : values)
    if (!std::isfinite(v)) return false;
  return true;
}

inline void add_ball_on_floor(matrender::Scene& scene, const matrender::Material& ball, double lamp_size) {
  scene.add_mesh(horizontal_square(6.0), {scene.add_material(lambert(0.6f))});
  scene.add_mesh(uv_sphere(0.4, 32, {0.0, 0.0, 0.4}), {scene.add_material(ball)});
  matrender::RectLamp lamp;
  lamp.light_to_world[3] = glm::dvec4(0.5, -0.5, 2.0, 1.0);
  lamp.size_x = lamp.size_y = lamp_size;
  lamp.power = 150.0;
  scene.add_lamp(lamp);
}

// Renders and tells whether every pixel came out finite with no sample discarded.
inline bool renders_finite(matrender::Scene& scene, const matrender::Camera& camera,
                           const matrender::RenderSettings& settings) {
  matrender::FrameBuffers frame;
  const matrender::RenderStats stats = matrender::render(scene, camera, settings, frame);
  return all_finite(frame.color) && stats.discarded_samples == 0;
}

}  // namespace test_scenes
