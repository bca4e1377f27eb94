// Prints the renderer's figures: path-tracer rays/s beside raw Embree traversal of exactly the
// same rays (replayed from a log, same run, same threads; in the tutorial's setup and with the
// watertight tests the renderer uses), samples/s, BVH build time, peak memory, and error against
// a converged reference versus render time.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <embree3/rtcore.h>
#include <fmt/core.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "accel/embree_scene.h"
#include "bench_scenes.h"
#include "matgeom/builtin/builtin_objects.h"
#include "matgeom/io/mesh_io.h"
#include "matrender/asset.h"
#include "matrender/paper_setup.h"
#include "matrender/render.h"
#include "scene/scene_data.h"

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

struct RawEmbree {
  RTCDevice device;
  RTCScene scene;
  double build_seconds;
};

// The plain Embree-tutorial setup: one triangle geometry, build quality high; `robust` adds the
// watertight triangle tests the renderer's scene needs (RTC_SCENE_FLAG_ROBUST), so that the
// traversal it pays for can be told apart from the rest of its work.
RawEmbree build_raw_embree(const matgeom::TriangleMesh& mesh, bool robust) {
  RawEmbree raw;
  raw.device = rtcNewDevice(nullptr);
  raw.scene = rtcNewScene(raw.device);
  rtcSetSceneBuildQuality(raw.scene, RTC_BUILD_QUALITY_HIGH);
  if (robust) rtcSetSceneFlags(raw.scene, RTC_SCENE_FLAG_ROBUST);
  RTCGeometry geometry = rtcNewGeometry(raw.device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* v = static_cast<glm::vec3*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                            sizeof(glm::vec3), mesh.positions.size()));
  auto* t = static_cast<glm::uvec3*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                             sizeof(glm::uvec3), mesh.triangles.size()));
  std::copy(mesh.positions.begin(), mesh.positions.end(), v);
  std::copy(mesh.triangles.begin(), mesh.triangles.end(), t);
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(raw.scene, geometry);
  rtcReleaseGeometry(geometry);
  const auto start = Clock::now();
  rtcCommitScene(raw.scene);
  raw.build_seconds = seconds_since(start);
  return raw;
}

// Traces every logged ray through raw Embree; returns seconds.
double replay(const RawEmbree& raw, const std::vector<matrender::RayLog::Entry>& rays, int threads) {
  tbb::task_arena arena(threads);
  const auto start = Clock::now();
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), 4096), [&](const tbb::blocked_range<size_t>& r) {
      RTCIntersectContext context;
      rtcInitIntersectContext(&context);
      for (size_t i = r.begin(); i != r.end(); ++i) {
        const auto& e = rays[i];
        RTCRayHit q;
        q.ray.org_x = e.origin.x, q.ray.org_y = e.origin.y, q.ray.org_z = e.origin.z;
        q.ray.dir_x = e.dir.x, q.ray.dir_y = e.dir.y, q.ray.dir_z = e.dir.z;
        q.ray.tnear = 0.0f;
        q.ray.tfar = e.t_max;
        q.ray.time = 0.0f;
        q.ray.mask = 0xFFFFFFFFu;
        q.ray.id = 0;
        q.ray.flags = 0;
        if (e.shadow) {
          rtcOccluded1(raw.scene, &context, &q.ray);
        } else {
          q.hit.geomID = RTC_INVALID_GEOMETRY_ID;
          rtcIntersect1(raw.scene, &context, &q);
        }
      }
    });
  });
  return seconds_since(start);
}


void traversal_table(const std::vector<size_t>& sizes, int resolution, int spp, int rounds) {
  fmt::print("\n## Path tracer against raw Embree on the same rays ({}x{}, {} spp, paper rig)\n\n", resolution,
             resolution, spp);
  fmt::print("| triangles | threads | BVH build ms (ours / raw) | rays | path tracer Mrays/s | raw Embree Mrays/s | ratio "
             "| raw Embree, watertight, Mrays/s | ratio | Msamples/s | peak MiB |\n");
  fmt::print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (size_t target : sizes) {
    bench::reset_peak_rss();
    const matgeom::TriangleMesh mesh = bench::displaced_sphere(target);
    matrender::Scene scene;
    scene.add_mesh(mesh, {scene.add_material(bench::bench_material())});
    matrender::add_rig(scene, matrender::paper_rig(mesh));
    scene.commit();
    RawEmbree raw = build_raw_embree(mesh, false);
    RawEmbree raw_robust = build_raw_embree(mesh, true);
    const matrender::Camera camera = matrender::paper_view(mesh, resolution, resolution);
    for (int threads : {1, 2}) {
      matrender::RenderSettings settings;
      settings.samples_per_pixel = spp;
      settings.threads = threads;
      settings.aovs = 0;
      matrender::FrameBuffers frame;
      // Log the render's rays in an untimed pass (the log costs time); it also warms caches
      // and the thread pool for the timed passes. The two sides then run in turn, `rounds`
      // times, and each keeps its fastest run: on a shared machine slow spells come and go, and
      // the fastest of several runs is each side's speed without them.
      matrender::RayLog log;
      scene.data().accel.set_ray_log(&log);
      matrender::render(scene, camera, settings, frame);
      scene.data().accel.set_ray_log(nullptr);
      std::vector<matrender::RayLog::Entry> rays;
      for (auto& part : log.per_thread) rays.insert(rays.end(), part.begin(), part.end());
      log.per_thread.clear();
      matrender::RenderStats stats;
      double raw_seconds = std::numeric_limits<double>::infinity();
      double robust_seconds = std::numeric_limits<double>::infinity();
      for (int round = 0; round < rounds; ++round) {
        const matrender::RenderStats run = matrender::render(scene, camera, settings, frame);
        if (round == 0 || run.seconds < stats.seconds) stats = run;
        raw_seconds = std::min(raw_seconds, replay(raw, rays, threads));
        robust_seconds = std::min(robust_seconds, replay(raw_robust, rays, threads));
      }
      const double ours = stats.rays / stats.seconds / 1e6;
      const double theirs = rays.size() / raw_seconds / 1e6;
      const double theirs_robust = rays.size() / robust_seconds / 1e6;
      fmt::print("| {} | {} | {:.1f} / {:.1f} | {} | {:.2f} | {:.2f} | {:.2f} | {:.2f} | {:.2f} | {:.2f} | {:.0f} |\n",
                 mesh.triangle_count(), threads, 1e3 * scene.bvh_build_seconds(), 1e3 * raw.build_seconds,
                 stats.rays, ours, theirs, ours / theirs, theirs_robust, ours / theirs_robust,
                 stats.camera_samples / stats.seconds / 1e6, bench::peak_rss_mib());
    }
    for (RawEmbree* r : {&raw, &raw_robust}) {
      rtcReleaseScene(r->scene);
      rtcReleaseDevice(r->device);
    }
  }
}

struct VaseScene {
  matrender::Scene scene;
  matrender::Camera camera;
};

VaseScene textured_vase(int resolution) {
  VaseScene v;
  const matgeom::ObjectAsset vase = matgeom::make_builtin_object("vase", 0);
  matrender::add_asset(v.scene, vase);
  matrender::add_rig(v.scene, matrender::paper_rig(vase.mesh));
  v.camera = matrender::paper_view(vase.mesh, resolution, resolution);
  fmt::print("\n(textured vase: {} triangles, {} lamps)\n", vase.mesh.triangle_count(), v.scene.lamps().size());
  return v;
}

void samples_per_second(VaseScene& v, int spp) {
  fmt::print("\n## Samples/s, textured vase, {}x{}, {} spp\n\n| threads | seconds | Msamples/s | Mrays/s |\n|---:|---:|---:|---:|\n",
             v.camera.width, v.camera.height, spp);
  for (int threads : {1, 2}) {
    matrender::RenderSettings settings;
    settings.samples_per_pixel = spp;
    settings.threads = threads;
    matrender::FrameBuffers frame;
    const auto stats = matrender::render(v.scene, v.camera, settings, frame);
    fmt::print("| {} | {:.2f} | {:.2f} | {:.2f} |\n", threads, stats.seconds, stats.camera_samples / stats.seconds / 1e6,
               stats.rays / stats.seconds / 1e6);
  }
}

void error_versus_time(VaseScene& v, int reference_spp, int max_spp) {
  matrender::RenderSettings settings;
  settings.threads = 2;
  settings.aovs = 0;
  settings.samples_per_pixel = reference_spp;
  settings.seed = 1000;  // independent of the test renders
  matrender::FrameBuffers reference;
  const auto ref_stats = matrender::render(v.scene, v.camera, settings, reference);
  fmt::print("\n## Error against a {} spp reference ({:.1f} s), textured vase {}x{}, 2 threads\n\n", reference_spp,
             ref_stats.seconds, v.camera.width, v.camera.height);
  fmt::print("| spp | seconds | RMSE | relative MSE |\n|---:|---:|---:|---:|\n");
  for (int spp = 1; spp <= max_spp; spp *= 2) {
    settings.samples_per_pixel = spp;
    settings.seed = 1;
    matrender::FrameBuffers frame;
    const auto stats = matrender::render(v.scene, v.camera, settings, frame);
    double se = 0.0, rel = 0.0;
    for (size_t i = 0; i < frame.color.size(); ++i) {
      const double d = frame.color[i] - reference.color[i];
      se += d * d;
      // relMSE as in Rousselle et al. 2011: (x - ref)^2 / (ref^2 + 0.01)
      rel += d * d / (double(reference.color[i]) * reference.color[i] + 1e-2);
    }
    fmt::print("| {} | {:.3f} | {:.5f} | {:.6f} |\n", spp, stats.seconds, std::sqrt(se / frame.color.size()),
               rel / frame.color.size());
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"render_bench: libmatrender speed beside raw Embree, and error versus time"};
  std::vector<size_t> sizes{10000, 200000, 1000000};
  int resolution = 256, spp = 16, vase_spp = 64, reference_spp = 2048, max_spp = 256, rounds = 9;
  app.add_option("--triangles", sizes, "Mesh sizes for the traversal table")->capture_default_str();
  app.add_option("--resolution", resolution, "Image side in pixels")->capture_default_str();
  app.add_option("--spp", spp, "Samples per pixel of the traversal table")->capture_default_str();
  app.add_option("--rounds", rounds, "Timed runs of each side of the traversal table (each keeps its fastest)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--vase-spp", vase_spp, "Samples per pixel of the samples/s table")->capture_default_str();
  app.add_option("--reference-spp", reference_spp, "Samples per pixel of the reference image")->capture_default_str();
  app.add_option("--max-spp", max_spp, "Largest spp of the error table")->capture_default_str();
  std::string sphere_file;
  app.add_option("--write-sphere", sphere_file,
                 "Write the traversal table's first sphere (--triangles) in its material as an object file "
                 "(.glb, .ply, .obj) and exit: render_object --mesh renders it under the same rig and view, for "
                 "callgrind's counts (scripts/callgrind.sh)");
  CLI11_PARSE(app, argc, argv);
  if (!sphere_file.empty()) {
    matgeom::ObjectAsset sphere;
    sphere.mesh = bench::displaced_sphere(sizes.front());
    sphere.materials = {bench::bench_material_inputs()};
    try {
      matgeom::write_object(sphere, sphere_file);
    } catch (const std::exception& e) {
      fmt::print(stderr, "render_bench: {}\n", e.what());
      return 1;
    }
    fmt::print("wrote {} ({} triangles)\n", sphere_file, sphere.mesh.triangle_count());
    return 0;
  }

  traversal_table(sizes, resolution, spp, rounds);
  VaseScene vase = textured_vase(resolution);
  samples_per_second(vase, vase_spp);
  error_versus_time(vase, reference_spp, max_spp);
  return 0;
}
