// The geometry steps of the README, through the installed libmatgeom: a mesh with parts goes to a
// file and back, is split into its parts, gets the paper's UV pass and is written as GLB.
// Usage: prepare_mesh OUTPUT_DIR. Exits non-zero if a step does not give what it should.
#include <cstdio>
#include <string>

#include <matgeom/builtin/builtin_objects.h>
#include <matgeom/io/mesh_io.h>
#include <matgeom/mesh_parts.h>
#include <matgeom/uv/uv_pass.h>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: prepare_mesh OUTPUT_DIR\n");
    return 2;
  }
  const std::string dir = argv[1];

  // Any PLY, OBJ or glTF/GLB in metres with +Z up; here a built-in chair saved as PLY.
  matgeom::write_object(matgeom::make_builtin_object("chair", 7), dir + "/chair.ply");
  matgeom::ObjectAsset chair = matgeom::read_object(dir + "/chair.ply");

  for (const matgeom::MeshPart& part : matgeom::split_parts(chair.mesh)) {
    std::printf("part %u %s: %zu triangles\n", part.id, part.name.c_str(), part.mesh.triangles.size());
  }

  matgeom::UvPassOptions options;
  options.texel_density_scale = 0.5;  // the paper's s: half the texels per metre
  const matgeom::UvPassResult uv = matgeom::uv_pass(chair.mesh, options);
  for (const matgeom::UvPartReport& report : uv.parts) {
    std::printf("%s: %u charts, packing %.2f, %.1f px/m\n", report.part.c_str(), report.charts,
                report.packing_efficiency, report.achieved_density);
    if (report.achieved_density < 0.99 * report.target_density) return 1;
  }
  chair.mesh = uv.mesh;
  matgeom::write_object(chair, dir + "/chair.glb");
  return matgeom::read_object(dir + "/chair.glb").mesh.triangles.size() == chair.mesh.triangles.size() ? 0 : 1;
}
