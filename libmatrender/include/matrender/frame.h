#pragma once
// The caller-visible result of a render: colour plus pixel-aligned AOVs of the first visible
// surface. Row 0 is the image top; arrays are row-major, channels interleaved.
//
// How AOVs are filtered (docs/conventions.md): colour is the plain mean of all filter-sampled
// camera samples (Cycles' Blackman-Harris 1.5 px, importance sampled, weight 1). alpha is the
// fraction of samples that hit a surface. base colour, roughness, metallic and the normals are
// the mean over the samples that hit (not premultiplied by alpha; normals renormalised). Depth,
// label and part id come from the single hit sample nearest the pixel centre and are never
// blended. Pixels no sample hit hold 0 (label 0, part id -1, depth 0).
#include <cstdint>
#include <vector>

namespace matrender {

enum Aov : uint32_t {
  AovBaseColor = 1u << 0,
  AovRoughness = 1u << 1,
  AovMetallic = 1u << 2,
  AovNormalWorld = 1u << 3,
  AovNormalCamera = 1u << 4,
  AovDepth = 1u << 5,
  AovLabel = 1u << 6,
  AovPartId = 1u << 7,
  AovAlpha = 1u << 8,
  AovAll = (1u << 9) - 1,
};

struct FrameBuffers {
  int width = 0;
  int height = 0;
  uint32_t aovs = 0;                 // which AOV arrays below are filled
  bool transparent_background = false;  // colour is premultiplied by coverage, 0 where nothing hit
  std::vector<float> color;          // RGB, scene-linear
  std::vector<float> alpha;          // coverage
  std::vector<float> base_color;     // RGB, linear
  std::vector<float> roughness;
  std::vector<float> metallic;
  std::vector<float> normal_world;   // XYZ in [-1, 1]
  std::vector<float> normal_camera;  // XYZ, camera frame (+X right, +Y up, +Z toward viewer)
  std::vector<float> depth;          // metres along the camera axis
  std::vector<int32_t> label;        // material label id
  std::vector<int32_t> part_id;      // part id, -1 for background

  // Sizes every requested array for width x height and zeroes it.
  void resize(int w, int h, uint32_t aov_mask);
};

}  // namespace matrender
