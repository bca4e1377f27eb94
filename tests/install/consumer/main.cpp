// Renders a lit square through the installed API and checks the centre pixel is lit.
#include <cstdio>

#include <matrender/camera.h>
#include <matrender/render.h>
#include <matrender/scene.h>

int main() {
  matgeom::TriangleMesh square;
  square.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  square.triangles = {{0, 1, 2}, {0, 2, 3}};
  matrender::Scene scene;
  scene.add_mesh(square, {scene.add_material(matrender::Material{})});
  scene.add_lamp(matrender::PointLamp{glm::dvec3(0, 0, 1), 100.0, glm::dvec3(1.0)});
  const auto camera = matrender::Camera::look_at({0, -1, 2}, {0, 0, 0}, {0, 0, 1}, 0.8, 16, 16);
  matrender::RenderSettings settings;
  settings.samples_per_pixel = 4;
  matrender::FrameBuffers frame;
  matrender::render(scene, camera, settings, frame);
  const float centre = frame.color[3 * (8 * 16 + 8)];
  std::printf("centre pixel %f\n", centre);
  return centre > 0.0f ? 0 : 1;
}
