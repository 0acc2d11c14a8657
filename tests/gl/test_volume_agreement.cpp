// The GPU-only volume (drawn from the depth texture) against the explicit CPU-built mesh with the
// same options: the stencil counts must agree on at least 99.99 % of pixels (issue 4, pass 3).
#include <gtest/gtest.h>

#include "gl_test_support.h"
#include "shadowvol/embree/depth_capture.h"
#include "shadowvol/volume_builder.h"

using namespace shadowvol;

namespace {

struct Variant {
  Triangulation tri;
  bool blur;
  CaptureMode capture;
  FarCap cap;
};

// Both stencil counts (the scenes' cameras allow z-pass): z-fail draws 2 sheet and 2 cap
// triangles per kept quad, z-pass the sheet alone; GPU and explicit agree in each.
void expectAgreement(const Scene& scene, const Variant& v, int mapSize) {
  const std::vector<char> inside = gltest::insideLightMask(scene);
  for (gl::VolumeCount count : {gl::VolumeCount::ZFail, gl::VolumeCount::ZPass}) {
  SCOPED_TRACE(gl::toString(count));
  gl::Renderer& r = gltest::sharedRenderer();
  r.setScene(scene);
  gl::RenderOptions o;
  o.volumeCount = count;
  const std::size_t perQuad = count == gl::VolumeCount::ZPass ? 2 : 4;
  o.method = gl::ShadowMethod::Hybrid;
  o.depthWidth = o.depthHeight = mapSize;
  o.capture = v.capture;
  o.volumeOptions.triangulation = v.tri;
  o.volumeOptions.blur = v.blur;
  o.volumeOptions.blurOffset = v.blur ? 0.02 : 0.0;
  o.volumeOptions.cap = v.cap;
  o.volume = gl::VolumeSource::Gpu;
  const gl::RenderResult gpu = r.render(o);
  o.volume = gl::VolumeSource::Explicit;
  const gl::RenderResult cpu = r.render(o);
  ASSERT_EQ(gpu.stencil.size(), cpu.stencil.size());
  EXPECT_DOUBLE_EQ(gpu.biasUsed, cpu.biasUsed);
  std::size_t shadowed = 0;
  for (auto s : cpu.stencil) shadowed += s != 0;
  // z-pass: only where the light reaches (elsewhere the GPU's uncapped far-plane triangles of
  // mixed quads, which the explicit mesh drops, may be counted; the lighting ignores them).
  const double share = count == gl::VolumeCount::ZPass ? gltest::agreementWhere(gpu.stencil, cpu.stencil, inside)
                                                       : gltest::agreement(gpu.stencil, cpu.stencil);
  std::printf(
      "%s %s %s %s cap %s: stencil agreement %.5f %% (%zu of %zu differ), %zu shadowed pixels, volume %zu "
      "(gpu) / %zu (explicit) triangles\n",
      scene.source.c_str(), toString(v.tri), v.blur ? "blur" : "no blur", toString(v.capture), toString(v.cap),
      100.0 * share, std::size_t(std::llround((1.0 - share) * double(cpu.stencil.size()))), cpu.stencil.size(),
      shadowed, gpu.volumeTriangles, cpu.volumeTriangles);
  EXPECT_GT(shadowed, cpu.stencil.size() / 50) << "the view must contain shadow";
  const int side = mapSize + 2 * kVolumeGuardTexels;  // the map's guard band (light.h)
  const std::size_t quads = std::size_t(side - 1) * std::size_t(side - 1);
  EXPECT_EQ(gpu.gpuVolumeQuads, quads);
  EXPECT_EQ(gpu.volumeCountUsed, count);
  EXPECT_EQ(cpu.volumeCountUsed, count);
  if (v.cap == FarCap::Quad) {
    // The full sheet, and with z-fail the far rectangle (a fan of one triangle per ring edge, so
    // that it shares the ring's vertices); no quad may be skipped: no compaction.
    EXPECT_EQ(gpu.volumeTriangles, 2 * quads + (perQuad == 4 ? 4 * std::size_t(side - 1) : 0));
    EXPECT_EQ(gpu.gpuVolumeQuadsDrawn, quads);
  } else {
    // only the kept quads were expanded
    EXPECT_TRUE(gltest::gpuVolumeTrianglesFit(gpu.volumeTriangles, gpu.gpuVolumeQuadsDrawn, perQuad == 4,
                                              gpu.gpuVolumeDrawUsed == gl::GpuVolumeDraw::Indexed));
    EXPECT_LT(gpu.gpuVolumeQuadsDrawn, quads);
    EXPECT_GT(gpu.volumeTriangles, 0u);
    EXPECT_LT(gpu.volumeTriangles, perQuad * quads);  // all-far quads are dropped
  }
  EXPECT_GE(share, 0.9999);
  }
}

}  // namespace

// The ways of drawing the GPU volume (gl::GpuVolumeDraw) give the same triangles and the same
// stencil, pixel for pixel; those that skip the quads all on the far plane draw only the kept
// ones. Indexed reads the light pass's window depth itself for back and front capture without
// blur, the resolved depth otherwise (midpoint and entry capture, blur); the rectangular map's
// sides are not multiples of its 8 x 4 blocks. ComputeMesh and Indexed need GL 4.3 (llvmpipe has 4.5); without it the test says so and
// checks the other two.
TEST(GlVolumeAgreement, EveryWayOfDrawingTheGpuVolumeGivesTheSameStencil) {
  gl::Renderer& r = gltest::sharedRenderer();
  r.setScene(defaultScene());
  const bool gl43 = r.info().glMajor > 4 || (r.info().glMajor == 4 && r.info().glMinor >= 3);
  struct Case {
    CaptureMode capture;
    bool blur;
    int w, h;
  };
  for (const Case& c : {Case{CaptureMode::Back, false, 128, 128}, Case{CaptureMode::Front, false, 128, 128},
                        Case{CaptureMode::Back, false, 101, 67}, Case{CaptureMode::Midpoint, false, 101, 67},
                        Case{CaptureMode::Back, true, 101, 67}, Case{CaptureMode::Entry, false, 101, 67}}) {
    SCOPED_TRACE(std::string(toString(c.capture)) + (c.blur ? " blur " : " ") + std::to_string(c.w) + "x" +
                 std::to_string(c.h));
    gl::RenderOptions o;
    o.depthWidth = c.w;
    o.depthHeight = c.h;
    o.capture = c.capture;
    o.volumeOptions.blur = c.blur;
    o.volumeCount = gl::VolumeCount::ZFail;  // 2 sheet + 2 cap triangles per quad (z-pass: test_zpass.cpp)
    o.gpuVolumeDraw = gl::GpuVolumeDraw::AllQuads;
    const gl::RenderResult all = r.render(o);
    EXPECT_EQ(all.gpuVolumeQuadsDrawn, all.gpuVolumeQuads);
    std::vector<gl::GpuVolumeDraw> skipping = {gl::GpuVolumeDraw::KeptQuads};
    if (gl43) skipping.insert(skipping.end(), {gl::GpuVolumeDraw::ComputeMesh, gl::GpuVolumeDraw::Indexed});
    else std::printf("no GL 4.3 context: ComputeMesh and Indexed not checked\n");
    std::size_t keptByFeedback = 0;  // KeptQuads comes first
    for (gl::GpuVolumeDraw how : skipping) {
      SCOPED_TRACE(gl::toString(how));
      o.gpuVolumeDraw = how;
      const gl::RenderResult kept = r.render(o);
      if (how == gl::GpuVolumeDraw::KeptQuads) keptByFeedback = kept.gpuVolumeQuadsDrawn;
      EXPECT_EQ(kept.gpuVolumeDrawUsed, how);
      EXPECT_EQ(kept.stencil, all.stencil);
      const bool indexed = how == gl::GpuVolumeDraw::Indexed;
      // every case here has a block of 8 x 4 kept quads, whose cap the indexed way draws as a fan
      EXPECT_TRUE(gltest::gpuVolumeTrianglesFit(kept.volumeTriangles, kept.gpuVolumeQuadsDrawn, true, indexed, true));
      if (indexed) EXPECT_EQ(kept.gpuVolumeQuadsDrawn, keptByFeedback);
      else EXPECT_EQ(kept.volumeTriangles, all.volumeTriangles);
      if (needsBackFace(c.capture)) {  // no sheet over the lit ground
        EXPECT_LT(kept.gpuVolumeQuadsDrawn, kept.gpuVolumeQuads / 4);
      }
    }
  }
  gl::RenderOptions d;  // the default lists the kept quads as indices (GL 4.3) or by transform feedback
  EXPECT_EQ(r.render(d).gpuVolumeDrawUsed, gl43 ? gl::GpuVolumeDraw::Indexed : gl::GpuVolumeDraw::KeptQuads);
  d.volumeOptions.cap = FarCap::Quad;  // every quad's sheet is needed: nothing is skipped
  EXPECT_EQ(r.render(d).gpuVolumeDrawUsed, gl::GpuVolumeDraw::AllQuads);
}

TEST(GlVolumeAgreement, FixedNoBlur) {
  expectAgreement(gltest::clutterScene(), {Triangulation::Fixed, false, CaptureMode::Back, FarCap::Exact}, 96);
}
TEST(GlVolumeAgreement, PerfectNoBlur) {
  expectAgreement(gltest::clutterScene(), {Triangulation::Perfect, false, CaptureMode::Back, FarCap::Exact}, 96);
}
TEST(GlVolumeAgreement, FixedBlur) {
  expectAgreement(gltest::clutterScene(), {Triangulation::Fixed, true, CaptureMode::Front, FarCap::Exact}, 96);
}
TEST(GlVolumeAgreement, PerfectBlur) {
  expectAgreement(gltest::clutterScene(), {Triangulation::Perfect, true, CaptureMode::Front, FarCap::Exact}, 96);
}
TEST(GlVolumeAgreement, PerfectEntry) {
  expectAgreement(gltest::clutterScene(), {Triangulation::Perfect, false, CaptureMode::Entry, FarCap::Exact}, 96);
}
TEST(GlVolumeAgreement, PerfectQuadCapMidpoint) {
  expectAgreement(gltest::clutterScene(), {Triangulation::Perfect, false, CaptureMode::Midpoint, FarCap::Quad}, 64);
}
TEST(GlVolumeAgreement, DefaultScenePerfect) {
  expectAgreement(defaultScene(), {Triangulation::Perfect, false, CaptureMode::Back, FarCap::Exact}, 128);
}

// renderWithVolume draws a caller's mesh: the volume built from the Embree capture of the same
// light must give the stencil of the GPU volume (the GL and Embree depth maps agree, see
// test_light_pass.cpp).
TEST(GlVolumeAgreement, CallerBuiltVolumeFromEmbreeCapture) {
  const Scene scene = gltest::clutterScene();
  gl::Renderer& r = gltest::sharedRenderer();
  r.setScene(scene);
  gl::RenderOptions o;
  o.depthWidth = o.depthHeight = 96;
  o.volumeCount = gl::VolumeCount::ZFail;  // renderWithVolume counts z-fail: compare like with like
  const gl::RenderResult gpu = r.render(o);
  const VolumeBuildResult built = buildVolume(captureDepthEmbree(scene, 96, 96, CaptureMode::Back), o.volumeOptions);
  const gl::RenderResult given = r.renderWithVolume(o, built.mesh);
  EXPECT_EQ(given.volumeTriangles, built.mesh.triangleCount());
  const double share = gltest::agreement(gpu.stencil, given.stencil);
  std::printf("gpu volume vs buildVolume(Embree capture) drawn by renderWithVolume: %.5f %% agree\n", 100.0 * share);
  EXPECT_GE(share, 0.9999);
}
