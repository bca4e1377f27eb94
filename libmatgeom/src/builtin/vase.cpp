#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "builtin/object_builder.h"
#include "builtin/objects.h"
#include "builtin/procedural_textures.h"
#include "builtin/shapes.h"
#include "matbase/image/srgb.h"
#include "matbase/smoothstep.h"
#include "matbase/uniform_source.h"
#include "matmaterial/material_classes.h"

// The vase keeps UVs of its own rather than the UV pass's: u around, v along the profile, so
// that its glaze pools in rings and its band follows the wall.

namespace matgeom::builtin {
namespace {

double lerp(double a, double b, double t) { return a + (b - a) * t; }

// ---------------------------------------------------------------------------------------------
// Vase shape: a closed profile in the (r, z) half-plane revolved about the z axis.

// The outer silhouette passes through four control heights (foot, belly, neck, rim); smoothstep
// between them gives zero slope at each, so the belly and neck are true extrema and the wall is
// vertical at the foot and the rim, where the fillet and the rounded lip join it smoothly.
struct VaseShape {
  double height = 0.3;  // top of the lip
  double foot_radius = 0.05;
  double belly_height = 0.1;
  double belly_radius = 0.08;
  double neck_height = 0.23;
  double neck_radius = 0.04;
  double rim_radius = 0.05;
  double wall = 0.006;    // horizontal wall thickness; the lip is a half circle of this width
  double floor = 0.01;    // thickness of the bottom
  double fillet = 0.008;  // radius of the rounded foot and of the inside corner
  double rim_height() const { return height - 0.5 * wall; }
};

VaseShape random_vase_shape(matbase::UniformSource& random) {
  VaseShape shape;
  shape.height = random.between(0.27, 0.33);
  shape.foot_radius = random.between(0.045, 0.06);
  shape.belly_height = shape.height * random.between(0.30, 0.45);
  shape.belly_radius = random.between(0.07, 0.09);
  shape.neck_height = shape.height * random.between(0.70, 0.82);
  shape.neck_radius = random.between(0.03, 0.045);
  shape.rim_radius = shape.neck_radius + random.between(0.005, 0.02);
  return shape;
}

double outer_radius(const VaseShape& shape, double z) {
  const double heights[4] = {shape.fillet, shape.belly_height, shape.neck_height,
                             shape.rim_height()};
  const double radii[4] = {shape.foot_radius, shape.belly_radius, shape.neck_radius,
                           shape.rim_radius};
  for (int k = 0; k < 3; ++k) {
    if (z <= heights[k + 1] || k == 2) {
      return lerp(radii[k], radii[k + 1],
                  matbase::smoothstep((z - heights[k]) / (heights[k + 1] - heights[k])));
    }
  }
  return radii[3];
}

// The profile's points and which of its segments (segment i joins points i and i + 1) run up
// the outside wall.
struct Profile {
  std::vector<ProfilePoint> points;
  size_t first_outer_wall_segment = 0;
  size_t last_outer_wall_segment = 0;
};

// Samples per profile segment, chosen so that the vase has about 6k triangles with quads of
// similar size along and around the surface.
constexpr int kAroundSegments = 56;
constexpr int kFootDiskSamples = 4;
constexpr int kFilletSamples = 4;
constexpr int kOuterWallSamples = 20;
constexpr int kLipSamples = 6;
constexpr int kInnerWallSamples = 14;
constexpr int kInnerFilletSamples = 3;
constexpr int kInnerFloorSamples = 2;

void append_arc(std::vector<ProfilePoint>& profile, ProfilePoint centre, double radius,
                double from_angle, double to_angle, int samples) {
  for (int k = 1; k <= samples; ++k) {
    const double angle = lerp(from_angle, to_angle, static_cast<double>(k) / samples);
    profile.push_back({centre.r + radius * std::cos(angle), centre.z + radius * std::sin(angle)});
  }
}

// The closed profile, walked so that the material lies on its left: from the bottom centre out
// along the base, up the outside, over the lip, down the inside and in to the inner floor's
// centre. Both ends lie on the axis, so the revolved surface is closed (a topological sphere).
Profile vase_profile(const VaseShape& shape) {
  Profile result;
  std::vector<ProfilePoint>& profile = result.points;
  profile.push_back({0.0, 0.0});
  const double disk_edge = shape.foot_radius - shape.fillet;
  for (int k = 1; k <= kFootDiskSamples; ++k) {
    profile.push_back({disk_edge * k / kFootDiskSamples, 0.0});
  }
  append_arc(profile, {disk_edge, shape.fillet}, shape.fillet, -0.5 * kPi, 0.0, kFilletSamples);

  const double rim = shape.rim_height();
  result.first_outer_wall_segment = profile.size() - 1;
  for (int k = 1; k <= kOuterWallSamples; ++k) {
    const double z = lerp(shape.fillet, rim, static_cast<double>(k) / kOuterWallSamples);
    profile.push_back({outer_radius(shape, z), z});
  }
  result.last_outer_wall_segment = profile.size() - 2;
  append_arc(profile, {shape.rim_radius - 0.5 * shape.wall, rim}, 0.5 * shape.wall, 0.0, kPi,
             kLipSamples);

  const double inner_corner = shape.floor + shape.fillet;
  for (int k = 1; k <= kInnerWallSamples; ++k) {
    const double z = lerp(rim, inner_corner, static_cast<double>(k) / kInnerWallSamples);
    profile.push_back({outer_radius(shape, z) - shape.wall, z});
  }
  const double fillet_centre = outer_radius(shape, inner_corner) - shape.wall - shape.fillet;
  append_arc(profile, {fillet_centre, inner_corner}, shape.fillet, 0.0, -0.5 * kPi,
             kInnerFilletSamples);
  for (int k = 1; k <= kInnerFloorSamples; ++k) {
    profile.push_back(
        {fillet_centre * (1.0 - static_cast<double>(k) / (kInnerFloorSamples + 1)), shape.floor});
  }
  profile.push_back({0.0, shape.floor});
  return result;
}

// Outward normal of the revolved surface at each profile point, as (radial, z). With the
// material on the left of the walking direction d = (dr, dz), outside is on the right: (dz, -dr).
// The direction averages the two adjacent segments so that shading is smooth across samples.
std::vector<ProfilePoint> profile_normals(const std::vector<ProfilePoint>& profile) {
  auto unit_step = [&](size_t from, size_t to) {
    const double dr = profile[to].r - profile[from].r;
    const double dz = profile[to].z - profile[from].z;
    const double length = std::hypot(dr, dz);
    return ProfilePoint{dr / length, dz / length};
  };
  std::vector<ProfilePoint> normals(profile.size());
  normals.front() = {0.0, -1.0};
  normals.back() = {0.0, 1.0};
  for (size_t i = 1; i + 1 < profile.size(); ++i) {
    const ProfilePoint in = unit_step(i - 1, i);
    const ProfilePoint out = unit_step(i, i + 1);
    const double dr = in.r + out.r;
    const double dz = in.z + out.z;
    const double length = std::hypot(dr, dz);
    normals[i] = {dz / length, -dr / length};
  }
  return normals;
}

// Cumulative arc length along the profile.
std::vector<double> profile_arc_length(const std::vector<ProfilePoint>& profile) {
  std::vector<double> s(profile.size(), 0.0);
  for (size_t i = 1; i < profile.size(); ++i) {
    s[i] = s[i - 1] + std::hypot(profile[i].r - profile[i - 1].r, profile[i].z - profile[i - 1].z);
  }
  return s;
}

// Revolves the profile. Rings get kAroundSegments + 1 vertices: the seam column is duplicated
// (same position, u = 0 and u = 1). The two axis points get one vertex per segment so that each
// fan triangle has its own u; their positions coincide, so the surface stays closed.
// u runs around, v along the profile's arc length, both in metres divided by the circumference
// at the belly, so texels are square there. Triangles wind counter-clockwise seen from outside:
// the surface normal is d(phi) x d(s) for the profile walked with the material on its left.
TriangleMesh revolve_profile(const std::vector<ProfilePoint>& profile, double texture_length,
                             const std::function<uint32_t(size_t)>& part_of_segment) {
  const std::vector<ProfilePoint> normals = profile_normals(profile);
  const std::vector<double> arc_length = profile_arc_length(profile);
  const size_t last = profile.size() - 1;
  auto on_axis = [&](size_t i) { return i == 0 || i == last; };

  TriangleMesh mesh;
  std::vector<uint32_t> ring_start(profile.size());
  for (size_t i = 0; i < profile.size(); ++i) {
    ring_start[i] = static_cast<uint32_t>(mesh.vertex_count());
    const int columns = on_axis(i) ? kAroundSegments : kAroundSegments + 1;
    const float v = static_cast<float>(arc_length[i] / texture_length);
    for (int j = 0; j < columns; ++j) {
      // (j % segments) makes the seam column's position bitwise equal to the first column's.
      const double phi = 2.0 * kPi * (j % kAroundSegments) / kAroundSegments;
      const double c = std::cos(phi);
      const double s = std::sin(phi);
      mesh.positions.emplace_back(profile[i].r * c, profile[i].r * s, profile[i].z);
      mesh.normals.emplace_back(normals[i].r * c, normals[i].r * s, normals[i].z);
      const double u =
          on_axis(i) ? (j + 0.5) / kAroundSegments : static_cast<double>(j) / kAroundSegments;
      mesh.uvs.emplace_back(static_cast<float>(u), v);
    }
  }

  for (size_t i = 0; i < last; ++i) {
    const uint32_t part = part_of_segment(i);
    for (uint32_t j = 0; j < static_cast<uint32_t>(kAroundSegments); ++j) {
      const uint32_t a = ring_start[i] + j;
      const uint32_t b = ring_start[i] + j + 1;
      const uint32_t c = ring_start[i + 1] + j + 1;
      const uint32_t d = ring_start[i + 1] + j;
      if (i == 0) {
        mesh.triangles.emplace_back(a, c, d);  // fan around the bottom centre
      } else if (i + 1 == last) {
        mesh.triangles.emplace_back(a, b, d);  // fan around the inner floor's centre
      } else {
        mesh.triangles.emplace_back(a, b, c);
        mesh.triangles.emplace_back(a, c, d);
      }
      const size_t added = (i == 0 || i + 1 == last) ? 1 : 2;
      mesh.triangle_parts.insert(mesh.triangle_parts.end(), added, part);
    }
  }
  return mesh;
}

// ---------------------------------------------------------------------------------------------
// Procedural textures (tileable in u and v, so that neither the seam nor v > 1 shows).

constexpr int kTextureSize = 256;

struct GlazePalette {
  glm::dvec3 light;  // sRGB-encoded, [0, 1]
  glm::dvec3 dark;
  glm::dvec3 band;  // the glaze band's colour
};

GlazePalette random_palette(matbase::UniformSource& random) {
  static const GlazePalette palettes[] = {
      {{0.78, 0.85, 0.76}, {0.45, 0.60, 0.50}, {0.20, 0.32, 0.55}},  // celadon, cobalt band
      {{0.93, 0.90, 0.82}, {0.70, 0.62, 0.50}, {0.55, 0.25, 0.12}},  // cream, iron-red band
      {{0.60, 0.72, 0.85}, {0.25, 0.38, 0.60}, {0.90, 0.88, 0.80}},  // blue, white band
  };
  GlazePalette palette = palettes[random.bits() % 3];
  const double tint = random.between(-0.04, 0.04);
  palette.light = glm::clamp(palette.light + glm::dvec3(tint, 0.0, -tint), 0.0, 1.0);
  return palette;
}

// Glaze thickness across the texture: horizontal bands (whole periods per tile, so v tiles)
// wobbled by noise, as glaze pools in rings when a thrown pot is dipped.
double glaze_pooling(double u, double v, uint32_t salt) {
  const double wobble = 0.08 * (fractal_noise(u, v, 4, salt) - 0.5);
  return 0.5 + 0.5 * std::sin(2.0 * kPi * (3.0 * v + wobble));
}

matbase::ImagePixels glaze_base_color(const GlazePalette& palette, uint32_t salt) {
  return rgb_image("vase#base_color", kTextureSize, [&](double u, double v) {
    const double pooling = glaze_pooling(u, v, salt);
    const double mottling = fractal_noise(u, v, 8, salt + 1u);
    glm::dvec3 colour = glm::mix(palette.light, palette.dark, 0.55 * pooling + 0.45 * mottling);
    // Sparse iron speckles: a few texels darkened by a hash threshold.
    const uint32_t texel =
        static_cast<uint32_t>(u * kTextureSize) * 7919u + static_cast<uint32_t>(v * kTextureSize);
    if (hash_to_unit(texel ^ salt) > 0.996) colour *= 0.45;
    return colour;
  });
}

// glTF channel layout, as Blender's importer reads it: G = roughness, B = metallic (R, ambient
// occlusion in glTF, is unused and left white). Pooled glaze is glossier.
matbase::ImagePixels glaze_metallic_roughness(uint32_t salt) {
  return rgb_image("vase#metallic_roughness", kTextureSize, [&](double u, double v) {
    const double pooling = glaze_pooling(u, v, salt);
    const double variation = fractal_noise(u, v, 8, salt + 2u);
    const double roughness = 0.2 + 0.3 * (0.6 * (1.0 - pooling) + 0.4 * variation);
    return glm::dvec3(1.0, roughness, 0.0);
  });
}

// Tangent-space normal map of small glaze bumps, noise in [0, 1] over texels a quarter apart:
// about 5 degrees of tilt at the steepest.
matbase::ImagePixels glaze_normal_map(uint32_t salt) {
  return normal_map_image("vase#normal", kTextureSize, [&](double u, double v) { return fractal_noise(u, v, 16, salt + 3u); },
                          0.25);
}

}  // namespace

ObjectAsset make_vase(uint32_t seed) {
  ObjectBuilder builder(seed);
  matbase::UniformSource& random = builder.random();
  const VaseShape shape = random_vase_shape(random);
  const GlazePalette palette = random_palette(random);
  const uint32_t texture_salt = random.bits();

  const int glaze_color = builder.add_image(glaze_base_color(palette, texture_salt));
  const int glaze_metallic_roughness_image = builder.add_image(glaze_metallic_roughness(texture_salt));
  const int glaze_normals = builder.add_image(glaze_normal_map(texture_salt));

  using P = matmaterial::MaterialParameter;
  matmaterial::MaterialInputs body("body");
  body.set(P::BaseColor, 1.0).set_image(P::BaseColor, glaze_color);  // factor x texture, as in glTF
  body.set(P::Roughness, 1.0);  // factor x texture.G in [0.2, 0.5]
  body.set(P::Metallic, 0.0);   // factor x texture.B, both 0
  body.set_metallic_roughness_image(glaze_metallic_roughness_image);
  body.normal_image = glaze_normals;
  body.normal_strength = 1.0;
  body.label_id = matmaterial::label_id(matmaterial::MaterialClass::Ceramic);
  const uint32_t body_part = builder.add_part("body", body);

  matmaterial::MaterialInputs band("glaze_band");
  band.set(P::BaseColor, glm::dvec3(matbase::srgb_to_linear(palette.band.r), matbase::srgb_to_linear(palette.band.g),
                                    matbase::srgb_to_linear(palette.band.b)));
  band.set(P::Metallic, 0.0).set(P::Roughness, 0.12);
  band.normal_image = glaze_normals;
  band.normal_strength = 0.5;
  band.label_id = matmaterial::label_id(matmaterial::MaterialClass::Ceramic);
  const uint32_t band_part = builder.add_part("glaze_band", band);

  const Profile profile = vase_profile(shape);
  // The glaze band covers the outer wall segments within 3 cm of midway between belly and neck.
  const double band_centre = 0.5 * (shape.belly_height + shape.neck_height);
  auto part_of_segment = [&](size_t i) -> uint32_t {
    if (i < profile.first_outer_wall_segment || i > profile.last_outer_wall_segment) return body_part;
    const double mid_z = 0.5 * (profile.points[i].z + profile.points[i + 1].z);
    return std::abs(mid_z - band_centre) < 0.03 ? band_part : body_part;
  };
  // The vase keeps the UVs of its surface of revolution, which the glaze band follows.
  builder.add_uv_mapped(revolve_profile(profile.points, 2.0 * kPi * shape.belly_radius, part_of_segment));
  return builder.finish();
}

}  // namespace matgeom::builtin
