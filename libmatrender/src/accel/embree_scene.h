#pragma once
// The only place that talks to Embree: builds one BVH over all triangle meshes and answers
// closest-hit and occlusion queries for single rays.
#include <cstdint>
#include <vector>

#include <embree3/rtcore.h>
#include <glm/glm.hpp>
#include <tbb/enumerable_thread_specific.h>

namespace matrender {

struct RayHit {
  float t = 0.0f;
  uint32_t mesh = RTC_INVALID_GEOMETRY_ID;  // index of the mesh as added
  uint32_t triangle = 0;
  float u = 0.0f, v = 0.0f;  // barycentrics of vertices 1 and 2
  bool hit() const { return mesh != RTC_INVALID_GEOMETRY_ID; }
};

// Every query the renderer makes, per thread: lets bench/ replay exactly the path tracer's rays
// through raw Embree. Unused (one null check per ray) unless a benchmark installs one.
struct RayLog {
  struct Entry {
    glm::vec3 origin, dir;
    float t_max;
    bool shadow;
  };
  tbb::enumerable_thread_specific<std::vector<Entry>> per_thread;
};

class EmbreeScene {
 public:
  EmbreeScene();
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // Returns the mesh index (0, 1, ...). Arrays are copied into Embree's buffers.
  uint32_t add_triangle_mesh(const std::vector<glm::vec3>& positions,
                             const std::vector<glm::uvec3>& triangles);
  // Mesh `id`'s geometry replaced (moved), and whether rays see it; commit() rebuilds the BVH.
  void replace_triangle_mesh(uint32_t id, const std::vector<glm::vec3>& positions,
                             const std::vector<glm::uvec3>& triangles);
  void set_enabled(uint32_t id, bool enabled);
  void commit();

  RayHit intersect(const glm::vec3& origin, const glm::vec3& dir, float t_max) const;
  // Closest hits of up to kPacketSize rays from one origin that travel almost together (one
  // pixel's camera rays), traced as one Embree packet: little more work than a single ray.
  // Sixteen: Embree traverses a 16-ray packet at two thirds of the per-ray cost of an 8-ray one
  // on AVX2 machines, and 16 is the usual samples-per-pixel of a dataset render.
  static constexpr int kPacketSize = 16;
  void intersect_coherent(const glm::vec3& origin, const glm::vec3* dirs, int count, RayHit* hits) const;
  bool occluded(const glm::vec3& origin, const glm::vec3& dir, float t_max) const;

  void set_ray_log(RayLog* log) const { ray_log_ = log; }

 private:
  mutable RayLog* ray_log_ = nullptr;
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  uint32_t mesh_count_ = 0;
};

}  // namespace matrender
