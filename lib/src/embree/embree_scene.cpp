#include "shadowvol/embree/embree_scene.h"

#include <cstdio>
#include <cstring>
#include <new>
#include <stdexcept>
#include <string>

#include "shadowvol/check.h"

namespace shadowvol {

RTCRayHit makeRayHit(const glm::dvec3& origin, const glm::dvec3& direction, float tnear, float tfar) {
  RTCRayHit rh{};
  rh.ray.org_x = float(origin.x);
  rh.ray.org_y = float(origin.y);
  rh.ray.org_z = float(origin.z);
  rh.ray.dir_x = float(direction.x);
  rh.ray.dir_y = float(direction.y);
  rh.ray.dir_z = float(direction.z);
  rh.ray.tnear = tnear;
  rh.ray.tfar = tfar;
  rh.ray.mask = 0xFFFFFFFFu;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  return rh;
}

struct EmbreeDevice::FirstError {
  RTCError code = RTC_ERROR_NONE;
  std::string message;
};

void EmbreeDevice::onError(void* user, RTCError code, const char* message) {
  auto* first = static_cast<FirstError*>(user);
  // A first out-of-memory error is said once, plainly, through throwIfError's std::bad_alloc.
  if (code != RTC_ERROR_OUT_OF_MEMORY || first->code != RTC_ERROR_NONE)
    std::fprintf(stderr, "shadowvol: Embree error %d: %s\n", int(code), message ? message : "");
  if (first->code == RTC_ERROR_NONE) {
    first->code = code;
    first->message = "Embree error " + std::to_string(int(code)) + ": " + (message ? message : "");
  }
}

EmbreeDevice::EmbreeDevice() : firstError_(std::make_shared<FirstError>()) {
  device_.reset(rtcNewDevice(nullptr));
  if (!device_) {
    const RTCError code = rtcGetDeviceError(nullptr);
    if (code == RTC_ERROR_OUT_OF_MEMORY) throw std::bad_alloc();
    throw std::runtime_error("cannot create an Embree device (error " + std::to_string(int(code)) + ")");
  }
  rtcSetDeviceErrorFunction(device_.get(), onError, firstError_.get());
}

void EmbreeDevice::throwIfError() const {
  if (firstError_->code == RTC_ERROR_OUT_OF_MEMORY) throw std::bad_alloc();
  if (firstError_->code != RTC_ERROR_NONE) throw std::runtime_error(firstError_->message);
}

EmbreeScene::EmbreeScene(const EmbreeDevice& device, const std::vector<const TriangleMesh*>& meshes) {
  scene_.reset(rtcNewScene(device.get()));
  rtcSetSceneFlags(scene_.get(), RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
  rtcSetSceneBuildQuality(scene_.get(), RTC_BUILD_QUALITY_HIGH);
  for (const TriangleMesh* mesh : meshes) {
    SV_CHECK(mesh != nullptr);
    RTCGeometry geom = rtcNewGeometry(device.get(), RTC_GEOMETRY_TYPE_TRIANGLE);
    // Embree-owned buffers (padded as Embree requires), filled by copy.
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                          3 * sizeof(float), mesh->positions.size()));
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                               3 * sizeof(unsigned), mesh->triangles.size()));
    if (v && !mesh->positions.empty()) std::memcpy(v, mesh->positions.data(), mesh->positions.size() * 12);
    if (idx && !mesh->triangles.empty()) std::memcpy(idx, mesh->triangles.data(), mesh->triangles.size() * 12);
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene_.get(), geom);  // IDs are assigned 0, 1, 2, ... in order
    rtcReleaseGeometry(geom);
  }
  geometries_ = unsigned(meshes.size());
  rtcCommitScene(scene_.get());
  device.throwIfError();
}

}  // namespace shadowvol
