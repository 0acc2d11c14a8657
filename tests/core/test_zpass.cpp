// zPassSafety (zpass.h): when the camera's near rectangle provably lies outside every depth-map
// volume of the light, and nearer than its far plane.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "shadowvol/zpass.h"

using namespace shadowvol;

namespace {

// A spot light 10 up looking straight down, 40 degrees, near 5, far 12.
Light spotDown() {
  Light l;
  l.position = {0, 10, 0};
  l.direction = {0, -1, 0};
  l.fovYDegrees = 40;
  l.nearPlane = 5;
  l.farPlane = 12;
  return l;
}

Camera cameraAt(glm::dvec3 eye, glm::dvec3 target) {
  Camera c;
  c.eye = eye;
  c.target = target;
  c.fovYDegrees = 45;
  c.width = 64;
  c.height = 48;
  c.nearPlane = 0.1;
  c.farPlane = 100;
  return c;
}

}  // namespace

TEST(ZPass, CameraBesideTheLightsFrustumIsSafe) {
  const ZPassSafety z = zPassSafety(spotDown(), 1.0, cameraAt({20, 3, 0}, {0, 0, 0}), {});
  EXPECT_TRUE(z.safe) << z.reason;
  EXPECT_TRUE(z.reason.empty());
}

TEST(ZPass, CameraNearerToTheLightThanItsNearPlaneIsSafe) {
  // Inside the cone, 2 below the light: nearer than the near plane (5), so before every sheet.
  EXPECT_TRUE(zPassSafety(spotDown(), 1.0, cameraAt({0, 8, 0.3}, {0, 0, 0}), {}).safe);
  // A blur offset that pulls the sheet 3.5 toward the light: no longer provably outside.
  VolumeBuildOptions pulled;
  pulled.blur = true;
  pulled.blurOffset = -3.5;
  EXPECT_FALSE(zPassSafety(spotDown(), 1.0, cameraAt({0, 8, 0.3}, {0, 0, 0}), pulled).safe);
}

TEST(ZPass, CameraInsideTheFrustumBeyondItsNearPlaneIsNot) {
  // 7 below the light, in the cone: it may be under an occluder, inside the volume.
  const ZPassSafety z = zPassSafety(spotDown(), 1.0, cameraAt({0.5, 3, 0.5}, {2, 0, 0}), {});
  EXPECT_FALSE(z.safe);
  EXPECT_NE(z.reason.find("inside the volume"), std::string::npos) << z.reason;
}

TEST(ZPass, NearRectangleBeyondTheFarPlaneIsNot) {
  // Below the far plane (depth 12 = y -2), outside the cone laterally: the segments to the
  // surface could reach the far cap.
  const ZPassSafety z = zPassSafety(spotDown(), 1.0, cameraAt({30, -5, 0}, {0, -6, 0}), {});
  EXPECT_FALSE(z.safe);
  EXPECT_NE(z.reason.find("far plane"), std::string::npos) << z.reason;
}

TEST(ZPass, StraddlingASidePlaneIsNot) {
  // The near rectangle of a camera exactly on the cone's edge, looking across it, has corners on
  // both sides of that plane.
  const double edge = 5.0 * std::tan(20.0 * 3.14159265358979 / 180.0);  // the cone's radius 5 below
  const ZPassSafety z = zPassSafety(spotDown(), 1.0, cameraAt({edge, 5, 0}, {-5, 5, 0}), {});
  EXPECT_FALSE(z.safe) << "the camera's near rectangle crosses the cone's side";
}

TEST(ZPass, DirectionalWindowSidesCount) {
  Light sun;
  sun.type = LightType::Directional;
  sun.position = {0, 10, 0};
  sun.direction = {0, -1, 0};
  sun.halfExtent = 4;
  sun.nearPlane = 1;
  sun.farPlane = 20;
  EXPECT_TRUE(zPassSafety(sun, 1.0, cameraAt({9, 3, 0}, {20, 3, 0}), {}).safe);   // beside the window
  EXPECT_FALSE(zPassSafety(sun, 1.0, cameraAt({1, 3, 0}, {0, 0, 0}), {}).safe);   // under the light
  EXPECT_TRUE(zPassSafety(sun, 1.0, cameraAt({1, 9.5, 0}, {0, 0, 0}), {}).safe);  // before its near plane
}
