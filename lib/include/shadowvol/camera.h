// The viewing camera and its matrices (OpenGL conventions, right-handed, looks down -Z of view).
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace shadowvol {

struct Camera {
  glm::dvec3 eye{0.0, 4.0, 10.0};      ///< world
  glm::dvec3 target{0.0, 0.0, 0.0};    ///< world; must differ from eye
  glm::dvec3 up{0.0, 1.0, 0.0};        ///< world; must not be parallel to target - eye
  double fovYDegrees = 45.0;           ///< full vertical field of view
  int width = 640;                     ///< image pixels
  int height = 480;                    ///< image pixels
  double nearPlane = 0.0;              ///< view distance; 0 = fitted to the scene by fitLightAndCamera
  double farPlane = 0.0;               ///< view distance; 0 = fitted to the scene by fitLightAndCamera
};

glm::dmat4 cameraView(const Camera& camera);        ///< world -> camera view
glm::dmat4 cameraProjection(const Camera& camera);  ///< camera view -> camera clip

}  // namespace shadowvol
