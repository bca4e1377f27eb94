// The scene library from outside: a built-in chair under the paper's rig, rendered in two
// material variants from four views of a camera grid, with one BVH. Writes the frames into the
// folder given and checks every one is lit.
#include <cstdio>
#include <string>
#include <vector>

#include <matrender/image_io.h>
#include <matrender/paper_setup.h>
#include <matrender/render.h>
#include <matrender/scene_builder.h>

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  matrender::ObjectDescription chair;
  chair.source = matrender::BuiltinObject{"chair", 7};
  // Or matrender::read_scene_file("scene.json") for a scene file (docs/scene_format.md).
  matrender::BuiltScene built = matrender::build_scene(matrender::paper_object_scene(chair));
  const uint32_t mesh = built.object_meshes[0];

  matrender::Material oak, steel;
  oak.name = "oak";
  oak.set(matrender::MaterialParameter::BaseColor, glm::vec3(0.35f, 0.2f, 0.08f));
  steel.name = "steel";
  steel.set(matrender::MaterialParameter::Metallic, 1.0f).set(matrender::MaterialParameter::Roughness, 0.3f);
  const std::vector<matrender::Material> variants = {oak, steel};

  matgeom::CameraGridSpec grid;  // the paper's grid, 2 x 2 cells of it, around the object
  grid.center = built.bounds.center;
  grid.n_phi = grid.n_theta = 2;
  matrender::RenderSettings settings;
  settings.samples_per_pixel = 4;
  for (const matrender::Material& variant : variants) {
    const uint32_t id = built.scene.add_material(variant);
    built.scene.set_part_materials(mesh, std::vector<uint32_t>(built.scene.part_materials(mesh).size(), id));
    for (const matrender::NamedView& view : matrender::grid_views(grid, 48, 48)) {
      matrender::FrameBuffers frame;
      matrender::render(built.scene, view.camera, settings, frame);
      matrender::write_frame(frame, argv[1], view.name + "_" + variant.name);
      double sum = 0.0;
      for (float v : frame.color) sum += v;
      std::printf("%s %s: mean %g\n", variant.name.c_str(), view.name.c_str(), sum / frame.color.size());
      if (!(sum > 0.0)) return 1;
    }
  }
  return 0;
}
