#include "shadowvol/zpass.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include <glm/matrix.hpp>
#include <glm/vec4.hpp>

namespace shadowvol {
namespace {

/// The camera's near rectangle in the light's view space.
std::array<glm::dvec3, 4> nearRectangleInLightView(const Light& light, const Camera& c) {
  const double t = std::tan(0.5 * c.fovYDegrees * std::numbers::pi / 180.0);
  const double h = t * c.nearPlane, w = h * double(c.width) / double(c.height);
  const glm::dmat4 toLight = lightView(light) * glm::inverse(cameraView(c));
  std::array<glm::dvec3, 4> out;
  for (int k = 0; k < 4; ++k)
    out[k] = glm::dvec3(toLight * glm::dvec4(k & 1 ? w : -w, k & 2 ? h : -h, -c.nearPlane, 1.0));
  return out;
}

}  // namespace

ZPassSafety zPassSafety(const Light& light, double lightAspect, const Camera& camera, const VolumeBuildOptions& o) {
  ZPassSafety z;
  const auto q = nearRectangleInLightView(light, camera);
  const double far = light.farPlane;
  if (!std::all_of(q.begin(), q.end(), [&](const glm::dvec3& p) { return -p.z < far * (1.0 - 1e-9); })) {
    z.reason = "the camera's near rectangle reaches the light's far plane";
    return z;
  }
  // The nearest a sheet vertex can be: the near plane, less a pull toward the light.
  const double pull = std::min(0.0, o.bias.value_or(0.0)) + (o.blur ? std::min(0.0, o.blurOffset) : 0.0);
  const double nearest = light.nearPlane + pull;
  if (std::all_of(q.begin(), q.end(), [&](const glm::dvec3& p) { return -p.z < nearest; })) {
    z.safe = true;
    return z;
  }
  // Beyond one side plane (each a half-space whose complement holds the whole frustum).
  const bool spot = light.type == LightType::Spot;
  const double ty = spot ? std::tan(0.5 * light.fovYDegrees * std::numbers::pi / 180.0) : light.halfExtent;
  const double tx = ty * lightAspect;
  for (int plane = 0; plane < 4; ++plane) {
    const bool beyond = std::all_of(q.begin(), q.end(), [&](const glm::dvec3& p) {
      const double reach = (plane < 2 ? tx : ty) * (spot ? -p.z : 1.0);
      const double coordinate = (plane < 2 ? p.x : p.y) * (plane % 2 ? -1.0 : 1.0);
      return coordinate > reach;
    });
    if (beyond) {
      z.safe = true;
      return z;
    }
  }
  z.reason = "the camera's near rectangle may lie inside the volume (it reaches into the light's frustum beyond its "
             "near plane)";
  return z;
}

}  // namespace shadowvol
