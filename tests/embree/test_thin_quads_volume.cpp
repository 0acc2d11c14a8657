// The sub-grid's thin quads (volume/thin_quads.h) on a whole volume: a V of two plates 0.02 thick,
// each sloping 30 degrees down to the valley between them, lit from straight above and captured
// with back capture at 32^2 (texels about 0.26 across). The plates' undersides, which the map
// records, fold at the valley by more than the plates are thick between texel centres, so the
// sheet straight across the fold passed in front of the lit top faces along the valley (false
// shadow on 256 pixels of a 320 x 240 frame); the stage puts those quads on the sub-grid (56).
#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <glm/trigonometric.hpp>

#include "mesh_invariants.h"
#include "refined_options.h"
#include "shadowvol/embree/depth_capture.h"
#include "shadowvol/scene.h"
#include "test_util.h"

namespace shadowvol {
namespace {

constexpr double kSlope = 30.0, kThick = 0.02, kValley = 0.8, kOffset = 0.037;

Scene valley() {
  const double a = glm::radians(kSlope), cx = 0.6 * std::cos(a), cy = kValley + 0.6 * std::sin(a);
  auto plate = [&](const char* name, double side) {
    return std::string(R"({"type": "box", "name": ")") + name + R"(", "size": [1.2, )" + std::to_string(kThick) +
           R"(, 1.5], "transform": {"rotate": [0, 0, )" + std::to_string(side * kSlope) + R"(], "translate": [)" +
           std::to_string(kOffset + side * cx) + ", " + std::to_string(cy) + ", 0]}}";
  };
  const std::string json = R"({"objects": [{"type": "plane", "name": "ground", "size": 8}, )" + plate("a", 1.0) +
                           ", " + plate("b", -1.0) +
                           R"(], "light": {"type": "directional", "direction": [0, -1, 0]},
      "camera": {"eye": [0, 4, 5], "target": [0, 0.8, 0], "fov": 50}})";
  return test::fittedScene(json, "valley.json");
}

// How many of 40 x 20 points on the plates' lit top faces within 0.15 of the valley (along the
// slope), 1e-4 above them, lie in the volume.
int litPointsInside(const VolumeMesh& mesh) {
  const double a = glm::radians(kSlope);
  int in = 0;
  for (double side : {1.0, -1.0})
    for (int k = 0; k < 20; ++k)
      for (int m = 0; m < 20; ++m) {
        const double s = 0.15 * (k + 0.5) / 20.0, z = -0.7 + 1.4 * (m + 0.5) / 20.0;
        // Along the top face from the valley: the top lies kThick / cos(a) above the underside's fold.
        const glm::dvec3 dir(side * std::cos(a), std::sin(a), 0.0), up(-side * std::sin(a), std::cos(a), 0.0);
        const glm::dvec3 p = glm::dvec3(kOffset, kValley, z) + s * dir + (kThick + 1e-4) * up;
        in += test::insideVolume(mesh, p - mesh.origin) ? 1 : 0;
      }
  return in;
}

TEST(ThinQuadsVolume, AThinFoldsLitFaceStaysOutOfTheVolume) {
  const VolumeBuildResult r = test::buildOnSubgrid(valley(), 32, CaptureMode::Back);
  EXPECT_GT(r.stats.thinQuads, 0u);
  EXPECT_TRUE(test::closedOrientedManifold(r.mesh));
  // 440 of the 800 without the stage (measured with kThinChordFloor set out of reach), 48 with it:
  // at a fold the sheet's bend shrinks only S times on the sub-grid (0.095 -> about 0.024, the
  // plates' 0.023 along the light), so the points nearest the fold can stay in.
  EXPECT_LE(litPointsInside(r.mesh), 80);
  EXPECT_TRUE(test::insideVolume(r.mesh, glm::dvec3(kOffset, 0.01, 0.0) - r.mesh.origin));  // the valley's shadow
}

}  // namespace
}  // namespace shadowvol
