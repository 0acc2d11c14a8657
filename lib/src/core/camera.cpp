#include "shadowvol/camera.h"

#include <glm/gtc/matrix_transform.hpp>

#include "shadowvol/check.h"

namespace shadowvol {

glm::dmat4 cameraView(const Camera& camera) { return glm::lookAt(camera.eye, camera.target, camera.up); }

glm::dmat4 cameraProjection(const Camera& camera) {
  SV_CHECK_GT(camera.farPlane, camera.nearPlane);
  SV_CHECK_GT(camera.nearPlane, 0.0);
  return glm::perspective(glm::radians(camera.fovYDegrees), double(camera.width) / double(camera.height),
                          camera.nearPlane, camera.farPlane);
}

}  // namespace shadowvol
