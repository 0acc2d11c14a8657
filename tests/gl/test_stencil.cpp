// Stencil counts of the z-fail volume pass against the volume computed from the texel grid.
// The square-plate scene: a closed plate above a ground under a directional light (orthographic,
// so the sheet is exactly linear in (texel i, texel j, depth) over each triangle). For every pixel
// that sees the ground, the expected count is 1 when the ground point lies behind the sheet (the
// sheet's depth interpolated over the quad's triangles with the same diagonal rule) and 0 else.
// Pixels within one pixel of a change of that answer (or of what the pixel sees) are skipped.
// The same check runs with a camera inside the volume (fails with z-pass counting), a near plane
// cutting the volume, and a far plane cutting it (fails without GL_DEPTH_CLAMP); both failures
// were checked by mutating the renderer.
#include <gtest/gtest.h>

#include <optional>

#include <glm/matrix.hpp>

#include "gl_test_support.h"
#include "shadowvol/sheet_depth.h"
#include "shadowvol/embree/depth_capture.h"
#include "shadowvol/triangulation.h"

using namespace shadowvol;

namespace {

/// The volume of buildVolume phase 1 (no blur), evaluated at world points.
class VolumeOracle {
 public:
  VolumeOracle(const DepthMap& map, double bias, Triangulation tri) : map_(map), tri_(tri), unproject_(map) {
    depth_.resize(map.depth.size());
    const SheetDepthRule rule(map, bias, 0.0);
    for (int j = 0; j < map.height; ++j)
      for (int i = 0; i < map.width; ++i) depth_[map.index(i, j)] = sheetDepthOf(map, i, j, rule, false);
  }

  /// Light-view depth of the sheet at continuous texel coordinates; nullopt outside the grid.
  std::optional<double> sheetDepth(double u, double v) const {
    if (!(u >= 0.0 && v >= 0.0 && u <= map_.width - 1 && v <= map_.height - 1)) return std::nullopt;
    const int i = std::min(int(std::floor(u)), map_.width - 2), j = std::min(int(std::floor(v)), map_.height - 2);
    const double fu = u - i, fv = v - j;
    const double dA = d(i, j), dB = d(i + 1, j), dC = d(i + 1, j + 1), dD = d(i, j + 1);
    const bool flip =
        tri_ == Triangulation::Perfect &&
        flipDiagonal(unproject_.lightViewPoint(i, j, dA), unproject_.lightViewPoint(i + 1, j, dB),
                     unproject_.lightViewPoint(i + 1, j + 1, dC), unproject_.lightViewPoint(i, j + 1, dD));
    if (!flip) {
      if (fu + fv <= 1.0) return dA + fu * (dB - dA) + fv * (dD - dA);
      return dC + (1.0 - fu) * (dD - dC) + (1.0 - fv) * (dB - dC);
    }
    if (fu >= fv) return dA + fu * (dB - dA) + fv * (dC - dB);
    return dA + fv * (dD - dA) + fu * (dC - dD);
  }

  bool inside(const glm::dvec3& world) const {
    const glm::dvec2 uv = map_.texelOf(world);
    const auto s = sheetDepth(uv.x, uv.y);
    const double d = map_.viewDepthOf(world);
    return s && d > *s && d < map_.farPlane;
  }

 private:
  double d(int i, int j) const { return depth_[map_.index(i, j)]; }
  const DepthMap& map_;
  Triangulation tri_;
  TexelUnprojector unproject_;
  std::vector<double> depth_;
};


struct Expectation {
  std::size_t tested = 0, inside = 0, outside = 0, wrong = 0;
  std::string firstWrong;  // the first few wrong pixels: window position, expected and stencil
};

/// Compares the stencil (rows top first) with the oracle for the ground pixels of the camera.
Expectation checkStencil(const Scene& scene, const VolumeOracle& oracle, const std::vector<std::uint8_t>& stencil) {
  const Camera& cam = scene.camera;
  const int w = cam.width, h = cam.height;
  // -1: not the ground (or clipped), 0: ground outside the volume, 1: ground inside.
  auto classify = [&](double wx, double wy) {  // window coordinates (pixels, y up)
    const auto hit = gltest::visibleGround(cam, wx, wy);
    return hit ? (oracle.inside(hit->ground) ? 1 : 0) : -1;
  };
  Expectation e;
  gltest::forEachPixelAwayFromBorders(w, h, classify, [&](std::size_t pixel, int c) {
    ++e.tested;
    (c ? e.inside : e.outside) += 1;
    if (stencil[pixel] != std::uint8_t(c) && ++e.wrong <= 8)
      e.firstWrong += " (" + std::to_string(pixel % std::size_t(w)) + ", " + std::to_string(pixel / std::size_t(w)) +
                      "): expected " + std::to_string(c) + ", stencil " + std::to_string(int(stencil[pixel])) + ";";
  });
  return e;
}

struct Case {
  const char* name;
  gl::VolumeSource source;
  FarCap cap;
  Triangulation tri;
};

void runPlate(Scene scene, std::size_t minInside, std::size_t minOutside) {
  gl::Renderer& r = gltest::sharedRenderer();
  r.setScene(scene);
  const DepthMap map = captureDepthEmbree(scene, 64, 64, CaptureMode::Back);
  for (const Case& c :
       {Case{"gpu exact perfect", gl::VolumeSource::Gpu, FarCap::Exact, Triangulation::Perfect},
        Case{"gpu quad fixed", gl::VolumeSource::Gpu, FarCap::Quad, Triangulation::Fixed},
        Case{"explicit exact perfect", gl::VolumeSource::Explicit, FarCap::Exact, Triangulation::Perfect}}) {
    gl::RenderOptions o;
    o.method = gl::ShadowMethod::Hybrid;
    o.volume = c.source;
    o.depthWidth = o.depthHeight = 64;
    o.capture = CaptureMode::Back;
    o.volumeOptions.cap = c.cap;
    o.volumeOptions.triangulation = c.tri;
    const gl::RenderResult res = r.render(o);
    ASSERT_EQ(res.stencil.size(), std::size_t(scene.camera.width) * scene.camera.height);
    const VolumeOracle oracle(map, res.biasUsed, c.tri);
    const Expectation e = checkStencil(scene, oracle, res.stencil);
    std::printf("%s, %s: %zu ground pixels tested (%zu inside, %zu outside), %zu wrong\n", scene.source.c_str(), c.name,
                e.tested, e.inside, e.outside, e.wrong);
    EXPECT_GE(e.inside, minInside) << c.name;
    EXPECT_GE(e.outside, minOutside) << c.name;
    EXPECT_EQ(e.wrong, 0u) << c.name << ", rows top first:" << e.firstWrong;
  }
}

}  // namespace

TEST(GlStencil, SquarePlateFootprintIsExactlyOne) {
  runPlate(gltest::plateScene(), 300, 3000);
}

TEST(GlStencil, CameraInsideTheVolume) {
  Scene s = gltest::plateScene();
  s.source = "plate, camera inside the volume";
  s.camera.eye = {0.1, 1.0, -0.1};
  s.camera.target = {0.6, 0.0, 1.8};
  s.camera.fovYDegrees = 70.0;
  s.camera.nearPlane = 0.05;
  s.camera.farPlane = 30.0;
  ASSERT_TRUE(
      VolumeOracle(captureDepthEmbree(s, 64, 64, CaptureMode::Back), 0.0, Triangulation::Perfect).inside(s.camera.eye));
  runPlate(s, 1000, 1000);
}

TEST(GlStencil, NearPlaneCutsTheVolume) {
  Scene s = gltest::plateScene();
  s.source = "plate, near plane through the volume";
  s.camera.eye = {0.0, 4.0, 5.0};
  s.camera.target = {0.0, 0.0, 0.0};
  s.camera.nearPlane = 5.6;  // between the plate (about 5.4 away) and the ground below it (about 6.4)
  s.camera.farPlane = 30.0;
  runPlate(s, 300, 1000);
}

// The volume reaches far beyond the camera's far plane (the light's far plane is pushed out):
// without GL_DEPTH_CLAMP the far parts would be clipped and the z-fail counts broken.
TEST(GlStencil, FarPlaneCutsTheVolume) {
  Scene s = gltest::plateScene();
  s.source = "plate, camera far plane through the volume";
  s.light.farPlane = 60.0;
  s.camera.nearPlane = 0.5;
  s.camera.farPlane = 16.0;
  runPlate(s, 300, 3000);
}
