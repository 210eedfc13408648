// Embree 3 scenes from luxel meshes (see rays.hpp for the determinism argument).
#include "luxel/bake/rays.hpp"

#include <embree3/rtcore.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace luxel::bake {

namespace {

const char* error_name(RTCError e) {
  switch (e) {
    case RTC_ERROR_NONE: return "no error";
    case RTC_ERROR_INVALID_ARGUMENT: return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION: return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY: return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU: return "unsupported CPU";
    case RTC_ERROR_CANCELLED: return "cancelled";
    default: return "unknown error";
  }
}

void check(RTCDevice device, const char* what) {
  const RTCError e = rtcGetDeviceError(device);
  if (e != RTC_ERROR_NONE) throw std::runtime_error(std::string("Embree: ") + what + ": " + error_name(e));
}

RTCScene build(RTCDevice device, const scenes::Scene& scene, std::span<const char> include) {
  RTCScene s = rtcNewScene(device);
  rtcSetSceneFlags(s, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(s, RTC_BUILD_QUALITY_HIGH);
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    if (m >= include.size() || !include[m]) continue;
    const scenes::Mesh& mesh = scene.meshes[m];
    const size_t triangles = mesh.triangle_count();
    if (triangles == 0) continue;
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(
        rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.vertex_count()));
    auto* idx = static_cast<uint32_t*>(
        rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), triangles));
    check(device, "geometry buffers");
    for (size_t i = 0; i < mesh.vertex_count(); ++i)
      v[3 * i] = mesh.positions[i].x, v[3 * i + 1] = mesh.positions[i].y, v[3 * i + 2] = mesh.positions[i].z;
    for (size_t i = 0; i < 3 * triangles; ++i) idx[i] = mesh.vertex_of_corner(i);
    rtcCommitGeometry(g);
    rtcAttachGeometryByID(s, g, static_cast<unsigned>(m));  // geomID = mesh index
    rtcReleaseGeometry(g);
    check(device, "attaching a mesh");
  }
  rtcCommitScene(s);
  check(device, "building the BVH");
  return s;
}

}  // namespace

struct RayScene::Impl {
  RTCDevice device = nullptr;
  RTCScene visible = nullptr, occluding = nullptr;
  const scenes::Scene* scene = nullptr;
};

RayScene::RayScene(const scenes::Scene& scene, std::span<const char> visible, std::span<const char> occluding)
    : impl_(std::make_unique<Impl>()) {
  impl_->scene = &scene;
  impl_->device = rtcNewDevice("threads=1");
  if (!impl_->device) throw std::runtime_error(std::string("Embree: cannot create a device: ") + error_name(rtcGetDeviceError(nullptr)));
  impl_->visible = build(impl_->device, scene, visible);
  impl_->occluding = build(impl_->device, scene, occluding);
}

RayScene::~RayScene() {
  if (impl_->visible) rtcReleaseScene(impl_->visible);
  if (impl_->occluding) rtcReleaseScene(impl_->occluding);
  if (impl_->device) rtcReleaseDevice(impl_->device);
}

std::optional<Hit> RayScene::intersect(glm::vec3 o, glm::vec3 d, float tmin, float tmax) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh{};
  rh.ray.org_x = o.x, rh.ray.org_y = o.y, rh.ray.org_z = o.z;
  rh.ray.dir_x = d.x, rh.ray.dir_y = d.y, rh.ray.dir_z = d.z;
  rh.ray.tnear = tmin;
  rh.ray.tfar = tmax;
  rh.ray.mask = 0xFFFFFFFFu;
  rh.ray.flags = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(impl_->visible, &context, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  Hit h;
  h.mesh = static_cast<int>(rh.hit.geomID);
  h.triangle = rh.hit.primID;
  h.u = rh.hit.u, h.v = rh.hit.v, h.t = rh.ray.tfar;
  // The front face is counter-clockwise (scene.hpp); take the winding from our own positions
  // rather than from Embree's Ng, whose orientation convention is Embree's.
  const scenes::Mesh& mesh = impl_->scene->meshes[size_t(h.mesh)];
  const glm::vec3 p0 = mesh.positions[mesh.vertex_of_corner(3 * size_t(h.triangle))];
  const glm::vec3 p1 = mesh.positions[mesh.vertex_of_corner(3 * size_t(h.triangle) + 1)];
  const glm::vec3 p2 = mesh.positions[mesh.vertex_of_corner(3 * size_t(h.triangle) + 2)];
  const glm::vec3 n = glm::cross(p1 - p0, p2 - p0);
  h.front = n.x * d.x + n.y * d.y + n.z * d.z < 0.0f;
  return h;
}

bool RayScene::occluded(glm::vec3 o, glm::vec3 d, float tmin, float tmax) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray{};
  ray.org_x = o.x, ray.org_y = o.y, ray.org_z = o.z;
  ray.dir_x = d.x, ray.dir_y = d.y, ray.dir_z = d.z;
  ray.tnear = tmin;
  ray.tfar = tmax;
  ray.mask = 0xFFFFFFFFu;
  ray.flags = 0;
  rtcOccluded1(impl_->occluding, &context, &ray);
  return ray.tfar == -std::numeric_limits<float>::infinity();
}

}  // namespace luxel::bake
