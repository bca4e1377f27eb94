#include "bench_scenes.h"

#include <cmath>
#include <fstream>
#include <string>

#include "matbase/pi.h"
#include "matgeom/tangents.h"
#include "matrender/asset.h"
#include "matrender/paper_setup.h"

namespace bench {

matgeom::TriangleMesh displaced_sphere(size_t triangles) {
  const int rings = std::max(4, static_cast<int>(std::sqrt(triangles / 4.0)));
  const int segments = 2 * rings;
  matgeom::TriangleMesh m;
  for (int i = 0; i <= rings; ++i) {
    const double theta = matbase::kPi * i / rings;
    for (int j = 0; j <= segments; ++j) {
      const double phi = 2.0 * matbase::kPi * j / segments;
      const double bump = 1.0 + 0.08 * std::sin(7.0 * theta) * std::sin(5.0 * phi) + 0.03 * std::sin(23.0 * theta + 11.0 * phi);
      const double r = 0.3 * bump;
      m.positions.emplace_back(r * std::sin(theta) * std::cos(phi), r * std::sin(theta) * std::sin(phi),
                               0.35 + r * std::cos(theta));
      m.uvs.emplace_back(static_cast<float>(j) / segments, 1.0f - static_cast<float>(i) / rings);
    }
  }
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const uint32_t a = i * (segments + 1) + j, b = a + segments + 1;
      m.triangles.push_back({a, b, a + 1});
      m.triangles.push_back({a + 1, b, b + 1});
    }
  matgeom::compute_vertex_normals(m);
  return m;
}

matmaterial::MaterialInputs bench_material_inputs() {
  matmaterial::MaterialInputs m("bench");
  m.set(matmaterial::MaterialParameter::BaseColor, glm::dvec3(0.7, 0.5, 0.3));
  m.set(matmaterial::MaterialParameter::Roughness, 0.35);
  m.set(matmaterial::MaterialParameter::Metallic, 0.0);
  return m;
}

matrender::Material bench_material() { return matrender::material_from_desc(bench_material_inputs(), {}); }

namespace {

// A "Vm...:" line of /proc/self/status in MiB.
double status_mib(const std::string& wanted) {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == wanted) {
      double kib;
      status >> kib;
      return kib / 1024.0;
    }
    status.ignore(1 << 20, '\n');
  }
  return 0.0;
}

}  // namespace

double peak_rss_mib() { return status_mib("VmHWM:"); }

double rss_mib() { return status_mib("VmRSS:"); }

void reset_peak_rss() { std::ofstream("/proc/self/clear_refs") << "5"; }

matrender::BuiltScene builtin_in_library_material(const std::string& object, const std::string& spec,
                                                  int material_resolution) {
  matrender::SceneDescription scene;
  matrender::MaterialDescription material;
  material.library = matrender::LibraryMaterialRequest{matmaterial::parse_library_material(spec), material_resolution, {}};
  scene.materials.emplace("material", material);
  matrender::ObjectDescription description;
  description.source = matrender::BuiltinObject{object, 0};
  description.material = "material";
  scene.objects.push_back(description);
  scene.lights = matrender::LightRigDescription{matrender::kPaperTargetIlluminanceLux};
  scene.camera.placement = matrender::MatrixPlacement{};
  return matrender::build_scene(scene);
}

matrender::Camera framed_grid_view(const matrender::BuiltScene& built, int k, int resolution) {
  constexpr double kFieldOfView = 0.6911;  // Blender's 50 mm lens on its 36 mm sensor
  matgeom::CameraGridSpec grid;
  grid.center = built.bounds.center;
  grid.radius = built.bounds.radius / std::sin(0.5 * kFieldOfView) / 0.9;
  grid.n_phi = grid.n_theta = 2;
  return matrender::grid_view(grid, k, k, resolution, resolution, kFieldOfView);
}

}  // namespace bench
