// Move-only RAII wrappers for Embree 3 (style.md point 7) and a scene built from triangle meshes.
#pragma once

#include <memory>
#include <vector>

#include <embree3/rtcore.h>
#include <glm/vec3.hpp>

#include "shadowvol/triangle_mesh.h"

namespace shadowvol {

/// An Embree device with an error callback that turns Embree errors into messages on stderr and
/// remembers the first one; throwIfError() raises it as std::runtime_error (std::bad_alloc when
/// Embree ran out of memory, as the constructor does when no device can be made for that reason).
class EmbreeDevice {
 public:
  EmbreeDevice();
  RTCDevice get() const { return device_.get(); }
  void throwIfError() const;

 private:
  struct Deleter {
    void operator()(RTCDevice d) const { rtcReleaseDevice(d); }
  };
  std::unique_ptr<RTCDeviceTy, Deleter> device_;
  struct FirstError;  // the first error's code and message (embree_scene.cpp)
  static void onError(void* user, RTCError code, const char* message);
  std::shared_ptr<FirstError> firstError_;
};

/// A ray from `origin` along `direction` (not normalised) over [tnear, tfar], every mask bit set,
/// with an empty hit (geomID invalid). Coordinates are rounded to float.
RTCRayHit makeRayHit(const glm::dvec3& origin, const glm::dvec3& direction, float tnear, float tfar);

/// A committed, robust (watertight) Embree scene of one triangle geometry per mesh; geometry ID k
/// is meshes[k]. Context filter functions are enabled, so a query can bring its own filter.
class EmbreeScene {
 public:
  EmbreeScene(const EmbreeDevice& device, const std::vector<const TriangleMesh*>& meshes);
  RTCScene get() const { return scene_.get(); }
  /// The meshes given, one geometry each: IDs 0 .. geometryCount() - 1 in their order.
  unsigned geometryCount() const { return geometries_; }

 private:
  struct Deleter {
    void operator()(RTCScene s) const { rtcReleaseScene(s); }
  };
  std::unique_ptr<RTCSceneTy, Deleter> scene_;
  unsigned geometries_ = 0;
};

}  // namespace shadowvol
