// Mesh files without normals reach the pixels shaded as Blender 3.4's importers shade them: the
// cubes of tests/geom/data/mesh_corpus, flat in every format, and smooth where an OBJ puts its
// faces in a smoothing group. The normal AOV shows it: a flat cube's pixels hold one of its six
// face normals (but where a pixel straddles an edge), a smooth one's vary across each face.
#include <cmath>
#include <filesystem>
#include <string>

#include <catch2/catch.hpp>

#include "matgeom/io/mesh_io.h"
#include "matrender/asset.h"
#include "matrender/camera.h"
#include "matrender/render.h"
#include "matrender/scene.h"

namespace {

// The share of the covered pixels whose normal is one of the cube's face normals, (+-1, 0, 0),
// (0, +-1, 0) or (0, 0, +-1), to 1e-3.
double share_on_face_normals(const std::string& file) {
  matrender::Scene scene;
  matrender::add_asset(scene, matgeom::read_object((std::filesystem::path(MATPREDICT_MESH_CORPUS) / file).string()));
  scene.add_lamp(matrender::PointLamp{glm::dvec3(3, -4, 5), 1000.0, glm::dvec3(1.0)});
  // From a corner: three faces in view, each at another angle.
  const matrender::Camera camera = matrender::Camera::look_at({4, -5, 3.5}, {0, 0, 0}, {0, 0, 1}, 0.6, 48, 48);
  matrender::RenderSettings settings;
  settings.samples_per_pixel = 4;
  settings.aovs = matrender::all_aovs();
  matrender::FrameBuffers frame;
  matrender::render(scene, camera, settings, frame);
  size_t covered = 0, on_faces = 0;
  for (size_t i = 0; i < frame.alpha.size(); ++i) {
    if (frame.alpha[i] < 1.0f) continue;
    ++covered;
    const glm::vec3 n(frame.normal_world[3 * i], frame.normal_world[3 * i + 1], frame.normal_world[3 * i + 2]);
    const float largest = std::max({std::abs(n.x), std::abs(n.y), std::abs(n.z)});
    on_faces += std::abs(largest - 1.0f) < 1e-3f ? 1 : 0;
  }
  REQUIRE(covered > 500);
  return static_cast<double>(on_faces) / static_cast<double>(covered);
}

}  // namespace

TEST_CASE("Cubes without normals render flat from every format, and smooth in an OBJ smoothing group", "[render]") {
  for (const char* flat : {"obj/cube_flat_no_normals.obj", "obj/cube_no_s_statement.obj", "ply/cube_no_normals.ply",
                           "gltf/cube_no_normals.gltf"}) {
    INFO(flat);
    // All but the pixels along the three visible edges and the outline.
    CHECK(share_on_face_normals(flat) > 0.85);
  }
  // Smooth, each pixel's normal leans toward the corners: hardly any lies on a face normal.
  CHECK(share_on_face_normals("obj/cube_smooth_groups.obj") < 0.05);
}
