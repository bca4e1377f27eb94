#include "accel/embree_scene.h"

#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

namespace matrender {
namespace {

void throw_on_error(RTCDevice device, const char* what) {
  const RTCError error = rtcGetDeviceError(device);
  if (error != RTC_ERROR_NONE)
    throw std::runtime_error(std::string("Embree: ") + what + " failed with error " + std::to_string(error));
}

RTCRay make_ray(const glm::vec3& origin, const glm::vec3& dir, float t_max) {
  RTCRay ray;
  ray.org_x = origin.x;
  ray.org_y = origin.y;
  ray.org_z = origin.z;
  ray.dir_x = dir.x;
  ray.dir_y = dir.y;
  ray.dir_z = dir.z;
  ray.tnear = 0.0f;
  ray.tfar = t_max;
  ray.time = 0.0f;
  ray.mask = 0xFFFFFFFFu;
  ray.id = 0;
  ray.flags = 0;
  return ray;
}

}  // namespace

EmbreeScene::EmbreeScene() {
  device_ = rtcNewDevice(nullptr);
  if (!device_) throw std::runtime_error("Embree: cannot create a device");
  scene_ = rtcNewScene(device_);
  rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
  // Watertight ray-triangle tests: without them a shadow ray through a shared edge of a closed
  // mesh can slip between its two triangles, and a lamp outside lights the inside (a camera
  // inside a closed 48 x 24 sphere saw it). They cost 4.6 % of the vase's instructions
  // (README, Benchmarks).
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
  throw_on_error(device_, "scene creation");
}

EmbreeScene::~EmbreeScene() {
  if (scene_) rtcReleaseScene(scene_);
  if (device_) rtcReleaseDevice(device_);
}

namespace {

// A committed Embree triangle geometry holding copies of the arrays.
RTCGeometry triangle_geometry(RTCDevice device, const std::vector<glm::vec3>& positions,
                              const std::vector<glm::uvec3>& triangles) {
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  // Embree reads vertices with 16-byte loads; its own buffers carry the padding it needs.
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), positions.size()));
  auto* indices = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), triangles.size()));
  throw_on_error(device, "buffer allocation");
  std::memcpy(vertices, positions.data(), positions.size() * sizeof(glm::vec3));
  std::memcpy(indices, triangles.data(), triangles.size() * sizeof(glm::uvec3));
  rtcCommitGeometry(geometry);
  return geometry;
}

}  // namespace

uint32_t EmbreeScene::add_triangle_mesh(const std::vector<glm::vec3>& positions,
                                        const std::vector<glm::uvec3>& triangles) {
  RTCGeometry geometry = triangle_geometry(device_, positions, triangles);
  const uint32_t id = rtcAttachGeometry(scene_, geometry);
  rtcReleaseGeometry(geometry);
  throw_on_error(device_, "geometry creation");
  if (id != mesh_count_) throw std::logic_error("Embree: unexpected geometry id");
  return mesh_count_++;
}

void EmbreeScene::replace_triangle_mesh(uint32_t id, const std::vector<glm::vec3>& positions,
                                        const std::vector<glm::uvec3>& triangles) {
  rtcDetachGeometry(scene_, id);
  RTCGeometry geometry = triangle_geometry(device_, positions, triangles);
  rtcAttachGeometryByID(scene_, geometry, id);
  rtcReleaseGeometry(geometry);
  throw_on_error(device_, "geometry replacement");
}

void EmbreeScene::set_enabled(uint32_t id, bool enabled) {
  RTCGeometry geometry = rtcGetGeometry(scene_, id);
  if (enabled) rtcEnableGeometry(geometry);
  else rtcDisableGeometry(geometry);
  throw_on_error(device_, "geometry enabling");
}

void EmbreeScene::commit() {
  rtcCommitScene(scene_);
  throw_on_error(device_, "BVH build");
}

RayHit EmbreeScene::intersect(const glm::vec3& origin, const glm::vec3& dir, float t_max) const {
  if (ray_log_) ray_log_->per_thread.local().push_back({origin, dir, t_max, false});
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit query;
  query.ray = make_ray(origin, dir, t_max);
  query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &context, &query);
  RayHit hit;
  if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) return hit;
  hit.t = query.ray.tfar;
  hit.mesh = query.hit.geomID;
  hit.triangle = query.hit.primID;
  hit.u = query.hit.u;
  hit.v = query.hit.v;
  return hit;
}

void EmbreeScene::intersect_coherent(const glm::vec3& origin, const glm::vec3* dirs, int count,
                                     RayHit* hits) const {
  if (count < 1 || count > kPacketSize) throw std::logic_error("Embree: packet of " + std::to_string(count) + " rays");
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  alignas(64) RTCRayHit16 packet;
  alignas(64) int valid[kPacketSize];
  for (int i = 0; i < kPacketSize; ++i) {
    valid[i] = i < count ? -1 : 0;
    const glm::vec3 dir = dirs[i < count ? i : 0];
    if (ray_log_ && i < count)
      ray_log_->per_thread.local().push_back({origin, dir, std::numeric_limits<float>::infinity(), false});
    packet.ray.org_x[i] = origin.x;
    packet.ray.org_y[i] = origin.y;
    packet.ray.org_z[i] = origin.z;
    packet.ray.dir_x[i] = dir.x;
    packet.ray.dir_y[i] = dir.y;
    packet.ray.dir_z[i] = dir.z;
    packet.ray.tnear[i] = 0.0f;
    packet.ray.tfar[i] = std::numeric_limits<float>::infinity();
    packet.ray.time[i] = 0.0f;
    packet.ray.mask[i] = 0xFFFFFFFFu;
    packet.ray.id[i] = 0;
    packet.ray.flags[i] = 0;
    packet.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
    packet.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
  }
  rtcIntersect16(valid, scene_, &context, &packet);
  for (int i = 0; i < count; ++i) {
    RayHit& hit = hits[i];
    hit = RayHit();
    if (packet.hit.geomID[i] == RTC_INVALID_GEOMETRY_ID) continue;
    hit.t = packet.ray.tfar[i];
    hit.mesh = packet.hit.geomID[i];
    hit.triangle = packet.hit.primID[i];
    hit.u = packet.hit.u[i];
    hit.v = packet.hit.v[i];
  }
}

bool EmbreeScene::occluded(const glm::vec3& origin, const glm::vec3& dir, float t_max) const {
  if (ray_log_) ray_log_->per_thread.local().push_back({origin, dir, t_max, true});
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray = make_ray(origin, dir, t_max);
  rtcOccluded1(scene_, &context, &ray);
  return ray.tfar == -std::numeric_limits<float>::infinity();
}

}  // namespace matrender
