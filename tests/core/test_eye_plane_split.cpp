// splitAcrossEyePlanes: huge triangles across a view's eye plane are bisected, conformingly,
// until short enough for single-precision clipping (regression: stress configuration
// scene-depth-ground-2e6, a 2-triangle ground of side 2e6 under an eye 3 units up, agreed on
// 99.79 % of pixels only).
#include <cmath>
#include <map>
#include <utility>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "shadowvol/eye_plane_split.h"
#include "shadowvol/primitives.h"
#include "shadowvol/scene.h"

using namespace shadowvol;

namespace {

glm::dvec3 corner(const TriangleMesh& m, std::uint32_t k) { return glm::dvec3(m.positions[k]); }

glm::dvec3 areaVector(const TriangleMesh& m) {
  glm::dvec3 sum(0.0);
  for (const auto& t : m.triangles) sum += 0.5 * glm::cross(corner(m, t[1]) - corner(m, t[0]), corner(m, t[2]) - corner(m, t[0]));
  return sum;
}

double area(const TriangleMesh& m) {
  double sum = 0.0;
  for (const auto& t : m.triangles)
    sum += 0.5 * glm::length(glm::cross(corner(m, t[1]) - corner(m, t[0]), corner(m, t[2]) - corner(m, t[0])));
  return sum;
}

// Every directed edge used once, and its reverse once: closed, consistently oriented, no T-junction.
bool closedAndOriented(const TriangleMesh& m) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) ++uses[{t[k], t[(k + 1) % 3]}];
  for (const auto& [e, n] : uses) {
    if (n != 1) return false;
    const auto back = uses.find({e.second, e.first});
    if (back == uses.end() || back->second != 1) return false;
  }
  return true;
}

// The eye 3 units over a box: its plane (axis tilted 30 degrees off straight down) cuts the box.
EyePlane tiltedEye(double maxEdge) {
  const glm::dvec3 axis = glm::normalize(glm::dvec3(0.0, -std::cos(0.5236), -std::sin(0.5236)));
  return {glm::dvec3(0.0, 3.0, 0.0), axis, 0.5, maxEdge};
}

}  // namespace

TEST(EyePlaneSplit, AClosedBoxStaysClosedOrientedAndTheSameSurface) {
  TriangleMesh box = makeBox(2e4, 10.0, 2e4);
  const glm::dvec3 before = areaVector(box);
  const double beforeArea = area(box);
  const EyePlane eye = tiltedEye(100.0);
  const EyePlaneSplit r = splitAcrossEyePlanes(box, std::span(&eye, 1), 1'000'000);
  EXPECT_TRUE(r.complete);
  EXPECT_GT(r.added, 100u);
  EXPECT_EQ(box.triangles.size(), 12u + r.added);
  EXPECT_TRUE(closedAndOriented(box));
  EXPECT_NEAR(area(box), beforeArea, 1e-6 * beforeArea);
  EXPECT_NEAR(glm::length(areaVector(box) - before), 0.0, 1e-6 * beforeArea);
  // No triangle across the slab [0, near] keeps an edge longer than maxEdge.
  for (const auto& t : box.triangles) {
    double lo = 1e300, hi = -1e300, longest = 0.0;
    for (int k = 0; k < 3; ++k) {
      const double d = glm::dot(corner(box, t[k]) - eye.eye, eye.axis);
      lo = std::min(lo, d), hi = std::max(hi, d);
      longest = std::max(longest, glm::length(corner(box, t[k]) - corner(box, t[(k + 1) % 3])));
    }
    if (lo < eye.nearPlane && hi > 0.0) {
      EXPECT_LE(longest, eye.maxEdge);
    }
  }
}

TEST(EyePlaneSplit, LeavesTrianglesAwayFromTheEyePlaneAndShortOnesAlone) {
  TriangleMesh box = makeBox(2e4, 10.0, 2e4);
  const TriangleMesh copy = box;
  EyePlane far = tiltedEye(100.0);
  far.eye = glm::dvec3(0.0, 1e6, 0.0);  // the plane passes far above the box
  far.axis = glm::dvec3(0.0, -1.0, 0.0);
  EXPECT_EQ(splitAcrossEyePlanes(box, std::span(&far, 1), 1'000'000).added, 0u);
  const EyePlane loose = tiltedEye(1e9);
  EXPECT_EQ(splitAcrossEyePlanes(box, std::span(&loose, 1), 1'000'000).added, 0u);
  EXPECT_EQ(box.triangles, copy.triangles);
  EXPECT_EQ(box.positions, copy.positions);
}

TEST(EyePlaneSplit, StopsAtTheBudgetStillConforming) {
  TriangleMesh box = makeBox(2e6, 10.0, 2e6);
  const EyePlane eye = tiltedEye(1.0);
  const EyePlaneSplit r = splitAcrossEyePlanes(box, std::span(&eye, 1), 5000);
  EXPECT_FALSE(r.complete);
  EXPECT_LE(box.triangles.size(), 5000u);
  EXPECT_TRUE(closedAndOriented(box));
}

TEST(EyePlaneSplit, SceneLoadSplitsAHugeGroundUnderTheEyeAndWarnsPastTheBudget) {
  const char* kScene = R"({"objects":[{"type":"plane","name":"ground","size":SIZE},
      {"type":"sphere","radius":0.2,"transform":{"translate":[0,1,0]}}],
    "light":{"type":"spot","position":[0.3,1.6,0.2],"target":[0,0,0],"fov":120},
    "camera":{"eye":[0,3,4],"target":[0,0,0],"fov":50}})";
  auto withSize = [&](const char* size) {
    std::string s = kScene;
    s.replace(s.find("SIZE"), 4, size);
    return s;
  };
  const SceneLoadResult big = parseScene(withSize("2e6"), "ground.json", ".");
  EXPECT_GT(big.scene.objects[0].mesh.triangles.size(), 2u);
  EXPECT_TRUE(big.warnings.empty()) << big.warnings[0];
  const SceneLoadResult small = parseScene(withSize("20"), "ground.json", ".");
  EXPECT_EQ(small.scene.objects[0].mesh.triangles.size(), 2u);
  const SceneLoadResult over = parseScene(withSize("2e6"), "ground.json", ".", 3000);
  ASSERT_FALSE(over.warnings.empty());
  EXPECT_NE(over.warnings.back().find("eye plane"), std::string::npos) << over.warnings.back();
  EXPECT_LE(over.scene.triangleCount(), 3000u);
}
