// A frame with several lights (renderer.h, frame.h RenderResult::otherLights): each light's
// stencil and shadow test are the ones a frame with that light alone gives, each is consistent
// with Embree's crossing counts and exact shadows, the image is the first light's frame plus every
// further light's diffuse term, and what a several-light frame cannot be is refused.
#include <algorithm>
#include <cstdlib>
#include <memory>

#include <gtest/gtest.h>

#include "shadowvol/embree/embree_depth_oracle.h"
#include "shadowvol/error.h"
#include "shadowvol/gl/renderer.h"
#include "shadowvol/validate/frame_validation.h"
#include "shadowvol/validate/gl_frame.h"
#include "test_util.h"

namespace shadowvol {
namespace {

gl::Renderer& renderer() {
  static std::unique_ptr<gl::Renderer> r = std::make_unique<gl::Renderer>();
  return *r;
}

Scene small(Scene s) {
  s.camera.width = 160;
  s.camera.height = 120;
  return s;
}

// The shipped spot light and lamp.
Scene spotAndPoint() {
  return small(loadScene(test::sourceDir() / "data" / "scenes" / "lights" / "spot-and-point.json").scene);
}

// The same objects under two spot lights from either side (the GPU volume takes no point light).
Scene twoSpots() {
  Scene s = spotAndPoint();
  Light second = s.light;
  second.position = {5.0, 6.0, 3.0};
  second.direction = glm::normalize(glm::dvec3(0.0, 0.0, -0.5) - second.position);
  second.nearPlane = second.farPlane = 0.0;
  s.otherLights = {second};
  forEachLight(s, [&](std::size_t) { fitLightAndCamera(s); });
  return s;
}

gl::RenderResult renderFrame(const Scene& scene, gl::RenderOptions ro) {
  renderer().setScene(scene);
  return renderer().render(validationRenderOptions(ro));
}

FrameValidation validateLight(const Scene& scene, const gl::RenderOptions& ro, const gl::RenderResult& frame,
                              std::size_t k) {
  const gl::RenderResult& r = k == 0 ? frame : frame.otherLights.at(k - 1);
  return validateRender(scene.withOnlyLight(k), validationRenderOptions(ro), r, toRenderedFrame(r, ro.method), {});
}

struct Method {
  const char* name;
  gl::ShadowMethod method;
  gl::VolumeSource volume;
};

// Every method that takes both a spot and a point light.
constexpr Method kMethods[] = {{"hybrid/explicit", gl::ShadowMethod::Hybrid, gl::VolumeSource::Explicit},
                               {"shadowmap", gl::ShadowMethod::ShadowMap, gl::VolumeSource::Gpu},
                               {"pcf3", gl::ShadowMethod::Pcf3, gl::VolumeSource::Gpu},
                               {"silhouette", gl::ShadowMethod::Silhouette, gl::VolumeSource::Gpu},
                               {"none", gl::ShadowMethod::None, gl::VolumeSource::Gpu}};

TEST(SeveralLights, EachLightIsTheFrameOfThatLightAloneAndTheImageTheirSum) {
  const Scene scene = spotAndPoint();
  ASSERT_EQ(scene.lightCount(), 2u);
  for (const Method& m : kMethods) {
    SCOPED_TRACE(m.name);
    gl::RenderOptions ro;
    ro.method = m.method;
    ro.volume = m.volume;
    ro.depthWidth = ro.depthHeight = 128;
    const gl::RenderResult both = renderFrame(scene, ro);
    ASSERT_EQ(both.otherLights.size(), 1u);
    const gl::RenderResult first = renderFrame(scene.withOnlyLight(0), ro);
    gl::RenderOptions added = ro;
    added.ambient = 0.0;  // the second light's diffuse term alone
    const gl::RenderResult second = renderFrame(scene.withOnlyLight(1), added);
    // The same stencil and shadow test per light as alone.
    EXPECT_EQ(both.stencil, first.stencil);
    EXPECT_EQ(both.visibility, first.visibility);
    EXPECT_EQ(both.otherLights[0].stencil, second.stencil);
    EXPECT_EQ(both.otherLights[0].visibility, second.visibility);
    EXPECT_TRUE(both.otherLights[0].rgba.empty()) << "the image is the frame's";
    // The image: the first light's frame plus the second's diffuse term (not its background),
    // within one step of the 8-bit rounding of each term, saturating at 255.
    const std::uint8_t background[3] = {second.rgba[0], second.rgba[1], second.rgba[2]};  // a corner: no object
    std::size_t off = 0, addedPixels = 0;
    for (std::size_t p = 0; p < both.rgba.size() / 4; ++p) {
      const bool secondBackground = std::equal(background, background + 3, &second.rgba[4 * p]);
      for (int c = 0; c < 3; ++c) {
        const int term = secondBackground ? 0 : second.rgba[4 * p + c];
        const int expected = std::min(255, first.rgba[4 * p + c] + term);
        off += std::abs(int(both.rgba[4 * p + c]) - expected) > 1;
      }
      addedPixels += !secondBackground && second.rgba[4 * p] > 0;
    }
    EXPECT_EQ(off, 0u);
    EXPECT_GT(addedPixels, both.rgba.size() / 16) << "the lamp lights much of the image";
    // The passes of the second light carry its suffix.
    EXPECT_TRUE(std::any_of(both.passes.begin(), both.passes.end(),
                            [](const gl::PassTime& p) { return p.name.size() > 2 && p.name.ends_with("#1"); }));
  }
}

// With refinement too: one depth oracle answers for every light, each map carrying its light's
// matrices (depth_oracle.h); the spot light's volume and the lamp's cube volume are refined.
TEST(SeveralLights, EveryLightIsConsistentWithItsCountsAndExactShadows) {
  const Scene scene = spotAndPoint();
  const EmbreeDepthOracle oracle(scene);
  for (CaptureMode mode : {CaptureMode::Back, CaptureMode::Front, CaptureMode::Midpoint})
    for (bool blur : {false, true})
      for (int refine : {0, 4}) {
        gl::RenderOptions ro;
        ro.volume = gl::VolumeSource::Explicit;
        ro.depthWidth = ro.depthHeight = 96;
        ro.capture = mode;
        ro.volumeOptions.blur = blur;
        ro.volumeOptions.refineSteps = refine;
        if (refine > 0) ro.volumeOptions.depthOracle = oracle.oracle();
        SCOPED_TRACE(std::string(toString(mode)) + (blur ? " blur" : "") + (refine > 0 ? " refined" : ""));
        const gl::RenderResult frame = renderFrame(scene, ro);
        for (std::size_t k = 0; k < scene.lightCount(); ++k) {
          const FrameValidation v = validateLight(scene, ro, frame, k);
          ASSERT_TRUE(v.meshCheck && v.meshCheck->valid()) << k << ": " << v.meshCheck->summary();
          EXPECT_GE(v.stencilVsCount.fraction(), kRequiredAgreement) << k;
          EXPECT_TRUE(v.passed) << k << ": " << (v.failures.empty() ? "" : v.failures.front());
          EXPECT_GT(v.exactShadowed, 100u) << k;
        }
      }
}

// The production path, the GPU volume, plain and refined by the walk, under two spot lights.
TEST(SeveralLights, GpuVolumesOfTwoSpotLights) {
  const Scene scene = twoSpots();
  for (int refine : {0, 4}) {
    gl::RenderOptions ro;
    ro.depthWidth = ro.depthHeight = 128;
    ro.volumeOptions.refineSteps = refine;
    SCOPED_TRACE(refine);
    const gl::RenderResult frame = renderFrame(scene, ro);
    ASSERT_EQ(frame.otherLights.size(), 1u);
    EXPECT_NE(frame.stencil, frame.otherLights[0].stencil) << "two lights, two shadows";
    for (std::size_t k = 0; k < 2; ++k) {
      const FrameValidation v = validateLight(scene, ro, frame, k);
      EXPECT_GE(v.stencilVsCount.fraction(), kRequiredAgreement) << k;
      EXPECT_TRUE(v.passed) << k << ": " << (v.failures.empty() ? "" : v.failures.front());
      EXPECT_GT(v.exactShadowed, 100u) << k;
    }
  }
}

// The GPU volumes of a spot light and a point light, plain and refined (the spot light's refined GPU
// volume, the lamp's refined GPU cube volume: six face volumes), back and front capture.
TEST(SeveralLights, GpuVolumesOfASpotAndAPointLight) {
  const Scene scene = spotAndPoint();
  for (CaptureMode mode : {CaptureMode::Back, CaptureMode::Front})
    for (int refine : {0, 4}) {
      gl::RenderOptions ro;
      ro.depthWidth = ro.depthHeight = 64;
      ro.capture = mode;
      ro.volumeOptions.refineSteps = refine;
      SCOPED_TRACE(std::string(toString(mode)) + (refine > 0 ? " refined" : ""));
      const gl::RenderResult frame = renderFrame(scene, ro);
      ASSERT_EQ(frame.otherLights.size(), 1u);
      EXPECT_EQ(frame.otherLights[0].faceVolumes.size(), refine > 0 ? 6u : 0u);
      for (std::size_t k = 0; k < 2; ++k) {
        const FrameValidation v = validateLight(scene, ro, frame, k);
        EXPECT_GE(v.stencilVsCount.fraction(), kRequiredAgreement) << k;
        EXPECT_TRUE(v.passed) << k << ": " << (v.failures.empty() ? "" : v.failures.front());
        EXPECT_GT(v.exactShadowed, 100u) << k;
      }
    }
}

TEST(SeveralLights, RefusesWhatASeveralLightFrameCannotBe) {
  const Scene scene = spotAndPoint();
  renderer().setScene(scene);
  auto expectRefused = [&](const gl::RenderOptions& ro, const std::string& field, const std::string& words) {
    try {
      renderer().render(ro);
      ADD_FAILURE() << "no error for " << field;
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), field) << e.what();
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  gl::RenderOptions quadCap;  // the spot light's GPU volume; the point light's cube has no quad cap
  quadCap.volumeOptions.cap = FarCap::Quad;
  expectRefused(quadCap, "volumeOptions.cap", "light 1 of the scene's 2");
  gl::RenderOptions dpsm;
  dpsm.method = gl::ShadowMethod::Dpsm;  // the spot light has no paraboloid maps
  expectRefused(dpsm, "method", "light 0 of the scene's 2");
  gl::RenderOptions grid;  // the spot light's explicit volume takes the sub-grid, the point light's not
  grid.volume = gl::VolumeSource::Explicit;
  grid.volumeOptions.refineSteps = 4;
  grid.volumeOptions.refineSubdivisions = 4;
  grid.volumeOptions.depthOracle = [](const DepthMap&, std::span<const glm::dvec2>, std::span<float>) {};  // never asked
  expectRefused(grid, "refine subdivisions", "light 1 of the scene's 2");
  gl::RenderOptions zpass;  // the spot light may take z-pass, the point light's cube not (named since a probe)
  zpass.volumeCount = gl::VolumeCount::ZPass;
  expectRefused(zpass, "volumeCount", "light 1 of the scene's 2");
  const Scene spots = twoSpots();
  renderer().setScene(spots);
  try {
    renderer().renderWithVolume(gl::RenderOptions{}, VolumeMesh{});
    ADD_FAILURE() << "a caller-built volume with two lights";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("one light"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace shadowvol
