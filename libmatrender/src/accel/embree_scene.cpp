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
  throw_on_error(device_, "scene creation");
}

EmbreeScene::~EmbreeScene() {
  if (scene_) rtcReleaseScene(scene_);
  if (device_) rtcReleaseDevice(device_);
}

uint32_t EmbreeScene::add_triangle_mesh(const std::vector<glm::vec3>& positions,
                                        const std::vector<glm::uvec3>& triangles) {
  RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
  // Embree reads vertices with 16-byte loads; its own buffers carry the padding it needs.
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), positions.size()));
  auto* indices = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), triangles.size()));
  throw_on_error(device_, "buffer allocation");
  std::memcpy(vertices, positions.data(), positions.size() * sizeof(glm::vec3));
  std::memcpy(indices, triangles.data(), triangles.size() * sizeof(glm::uvec3));
  rtcCommitGeometry(geometry);
  const uint32_t id = rtcAttachGeometry(scene_, geometry);
  rtcReleaseGeometry(geometry);
  throw_on_error(device_, "geometry creation");
  if (id != mesh_count_) throw std::logic_error("Embree: unexpected geometry id");
  return mesh_count_++;
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

bool EmbreeScene::occluded(const glm::vec3& origin, const glm::vec3& dir, float t_max) const {
  if (ray_log_) ray_log_->per_thread.local().push_back({origin, dir, t_max, true});
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray = make_ray(origin, dir, t_max);
  rtcOccluded1(scene_, &context, &ray);
  return ray.tfar == -std::numeric_limits<float>::infinity();
}

}  // namespace matrender
