#include "shadowvol/light.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "shadowvol/check.h"

namespace shadowvol {

glm::dvec3 lightUp(const Light& light) {
  if (glm::length(light.up) > 0.0) return glm::normalize(light.up);
  const glm::dvec3 d = glm::normalize(light.direction);
  return std::abs(d.y) > 0.999 ? glm::dvec3(0.0, 0.0, -1.0) : glm::dvec3(0.0, 1.0, 0.0);
}

const char* toString(LightType type) { return nameIn(kLightTypeNames, type); }

bool parseLightType(const std::string& text, LightType& type) { return parseIn(kLightTypeNames, text, type); }

glm::dmat4 lightView(const Light& light) {
  if (light.type == LightType::Point) return glm::translate(glm::dmat4(1.0), -light.position);
  const glm::dvec3 d = glm::normalize(light.direction);
  return glm::lookAt(light.position, light.position + d, lightUp(light));
}

glm::dmat4 lightProjection(const Light& light, double aspect) {
  SV_CHECK_GT(light.farPlane, light.nearPlane);
  SV_CHECK_GT(aspect, 0.0);
  SV_CHECK(light.type != LightType::Point);
  if (light.type == LightType::Spot) {
    SV_CHECK_GT(light.nearPlane, 0.0);
    return glm::perspective(glm::radians(light.fovYDegrees), aspect, light.nearPlane, light.farPlane);
  }
  SV_CHECK_GT(light.halfExtent, 0.0);
  const double hx = light.halfExtent * aspect, hy = light.halfExtent;
  return glm::ortho(-hx, hx, -hy, hy, light.nearPlane, light.farPlane);
}

Light guardedLight(const Light& light, int width, int height, int guard) {
  SV_CHECK(light.type != LightType::Point);
  SV_CHECK(width >= 1 && height >= 1 && guard >= 0);
  Light l = light;
  const double widen = double(height + 2 * guard) / double(height);  // the horizontal follows the aspect
  if (light.type == LightType::Spot)
    l.fovYDegrees = 2.0 * glm::degrees(std::atan(std::tan(0.5 * glm::radians(light.fovYDegrees)) * widen));
  else
    l.halfExtent = light.halfExtent * widen;
  return l;
}

}  // namespace shadowvol
