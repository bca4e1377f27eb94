#pragma once
// The caller-visible result of a render: colour plus pixel-aligned AOVs of the first visible
// surface. Row 0 is the image top; arrays are row-major, channels interleaved.
//
// How AOVs are filtered (docs/conventions.md): colour is the plain mean of all filter-sampled
// camera samples (Cycles' Blackman-Harris of RenderSettings::filter_width, importance sampled,
// weight 1). alpha is the fraction of samples that hit a surface. The material parameters and
// the normals are the mean over the samples that hit (not premultiplied by alpha; each parameter
// clamped to its range in the table, normals renormalised). Depth, label, part and object id come from
// the single hit sample nearest the pixel centre and are never blended. Ambient occlusion is the
// mean over the hit samples of the fraction of their occlusion rays that escape
// (RenderSettings). Pixels no sample hit hold 0 (label 0, part and object id -1, depth 0).
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "matmaterial/material_parameters.h"

namespace matrender {

using matmaterial::MaterialParameter;

// AOV bits: the geometric ones here, then one per material parameter (parameter_aov).
enum Aov : uint32_t {
  AovNormalWorld = 1u << 0,
  AovNormalCamera = 1u << 1,
  AovDepth = 1u << 2,
  AovLabel = 1u << 3,
  AovPartId = 1u << 4,
  AovAlpha = 1u << 5,
  // What the material's tangent-space normal map says at the hit (2 texel - 1, renormalised):
  // (0, 0, 1) where it has none.
  AovNormalTangent = 1u << 6,
  // The fraction of cosine-distributed directions around the shading normal that meet no
  // surface within RenderSettings::ambient_occlusion_distance (Cycles' AO node). Costs rays, so
  // it is never a default AOV.
  AovAmbientOcclusion = 1u << 7,
  // The camera samples each pixel took: RenderSettings::samples_per_pixel everywhere unless
  // adaptive sampling stopped some pixels early.
  AovSampleCount = 1u << 8,
  // The variance of the pixel's colour estimate (of the mean of its samples' Rec.709 luminance):
  // what the denoiser weighs neighbours by.
  AovColorVariance = 1u << 9,
  // Which object of the scene the hit nearest the pixel centre is on: the scene's mesh index
  // (BuiltScene::object_meshes maps described objects to them), -1 for the background. What
  // tells a subject from its surroundings, pixel by pixel.
  AovObjectId = 1u << 10,
};
constexpr uint32_t kFirstParameterAovBit = 11;
static_assert(kFirstParameterAovBit + matmaterial::kMaterialParameterCount <= 32, "AOV bits fit in 32");

// The AOV of a material parameter: its value at the first hit, named as in the table.
constexpr uint32_t parameter_aov(MaterialParameter p) { return 1u << (kFirstParameterAovBit + static_cast<uint32_t>(p)); }

constexpr uint32_t kGeometricAovs =
    AovNormalWorld | AovNormalCamera | AovNormalTangent | AovDepth | AovLabel | AovPartId | AovAlpha;

// Every AOV.
constexpr uint32_t all_aovs() {
  uint32_t mask = kGeometricAovs | AovAmbientOcclusion | AovSampleCount | AovColorVariance | AovObjectId;
  for (const matmaterial::MaterialParameterInfo& info : matmaterial::kMaterialParameters) mask |= parameter_aov(info.id);
  return mask;
}

// The AOVs written unless others are asked for: the geometric ones and the parameters the table
// marks default_aov.
constexpr uint32_t default_aovs() {
  uint32_t mask = kGeometricAovs;
  for (const matmaterial::MaterialParameterInfo& info : matmaterial::kMaterialParameters)
    if (info.default_aov) mask |= parameter_aov(info.id);
  return mask;
}

// An AOV's name (the pass name of its files and of render_object --aovs) and bit, in the order
// files are written.
struct AovName {
  std::string name;
  uint32_t bit;
  std::string description;  // what a pixel holds: units, colour space or frame, the background's value
};
const std::vector<AovName>& aov_names();
// What the colour buffer holds, said as the AOVs' descriptions say it.
constexpr const char* kColorDescription =
    "the image: scene-linear Rec.709 RGB (Blender's \"Linear\"), no exposure applied, the mean of the pixel's "
    "Blackman-Harris filtered camera samples";
std::optional<uint32_t> aov_named(std::string_view name);

struct FrameBuffers {
  int width = 0;
  int height = 0;
  uint32_t aovs = 0;                 // which AOV arrays below are filled
  bool transparent_background = false;  // colour is premultiplied by coverage, 0 where nothing hit
  std::vector<float> color;          // RGB, scene-linear
  std::vector<float> alpha;          // coverage
  // By MaterialParameter: RGB for a colour (linear), one channel for a scalar.
  std::array<std::vector<float>, matmaterial::kMaterialParameterCount> parameters;
  std::vector<float> normal_world;   // XYZ in [-1, 1]
  std::vector<float> normal_camera;  // XYZ, camera frame (+X right, +Y up, +Z toward viewer)
  std::vector<float> normal_tangent;  // XYZ, the normal map's tangent space (+Z along the surface normal)
  std::vector<float> ambient_occlusion;  // in [0, 1]: 1 where nothing is near
  std::vector<float> depth;          // metres along the camera axis
  std::vector<int32_t> label;        // material label id
  std::vector<int32_t> part_id;      // part id, -1 for background
  std::vector<int32_t> object_id;    // the scene's mesh index, -1 for background
  std::vector<int32_t> sample_count;  // camera samples taken
  std::vector<float> color_variance;  // of the mean luminance, from the spread of the samples

  std::vector<float>& parameter(MaterialParameter p) { return parameters[static_cast<size_t>(p)]; }
  const std::vector<float>& parameter(MaterialParameter p) const { return parameters[static_cast<size_t>(p)]; }

  // Sizes every requested array for width x height and zeroes it.
  void resize(int w, int h, uint32_t aov_mask);
  // The bytes resize(w, h, aov_mask) allocates.
  static double bytes_for(int w, int h, uint32_t aov_mask);
};

// One buffer of a frame: the colour's (AOV bit 0) or an AOV's, float or int32, with its channels
// per pixel; the pointer of the other type is null.
struct FrameBufferView {
  std::vector<float>* floats = nullptr;
  std::vector<int32_t>* ints = nullptr;
  int channels = 0;
};
FrameBufferView frame_buffer(FrameBuffers& frame, uint32_t aov_bit);

}  // namespace matrender
