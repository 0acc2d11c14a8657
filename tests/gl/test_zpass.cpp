// Z-pass without the far cap where zPassSafety allows (renderer.h VolumeCount): the same frame as
// z-fail, pixel for pixel, with the sheet's triangles alone; refused where it is not safe.
#include <memory>

#include <gtest/gtest.h>

#include "gl_test_support.h"
#include "shadowvol/embree/embree_depth_oracle.h"
#include "shadowvol/error.h"

using namespace shadowvol;

namespace {

struct Way {
  const char* name;
  gl::VolumeSource volume;
  gl::GpuVolumeDraw draw;
  FarCap cap;
  int refine;
};

}  // namespace

// Every way of drawing the hybrid volume: Auto takes z-pass on the default scene's camera, draws
// half the GPU triangles (no cap copies) or the explicit mesh less its cap, and gives the same
// image, and the same stencil wherever the light reaches.
TEST(GlZPass, SameFrameAsZFailWithoutTheCap) {
  gl::Renderer& r = gltest::sharedRenderer();
  Scene scene = defaultScene();
  scene.camera.width = 160;
  scene.camera.height = 120;
  r.setScene(scene);
  const std::vector<char> inside = gltest::insideLightMask(scene);
  const EmbreeDepthOracle rays(scene);
  const bool compute = r.info().glMajor > 4 || (r.info().glMajor == 4 && r.info().glMinor >= 3);
  std::vector<Way> ways = {{"kept quads", gl::VolumeSource::Gpu, gl::GpuVolumeDraw::KeptQuads, FarCap::Exact, 0},
                           {"all quads", gl::VolumeSource::Gpu, gl::GpuVolumeDraw::AllQuads, FarCap::Exact, 0},
                           {"quad cap", gl::VolumeSource::Gpu, gl::GpuVolumeDraw::Auto, FarCap::Quad, 0},
                           {"explicit", gl::VolumeSource::Explicit, gl::GpuVolumeDraw::Auto, FarCap::Exact, 0},
                           {"explicit refined", gl::VolumeSource::Explicit, gl::GpuVolumeDraw::Auto, FarCap::Exact, 6},
                           {"explicit quad cap", gl::VolumeSource::Explicit, gl::GpuVolumeDraw::Auto, FarCap::Quad, 0}};
  if (compute) {
    ways.push_back({"compute mesh", gl::VolumeSource::Gpu, gl::GpuVolumeDraw::ComputeMesh, FarCap::Exact, 0});
    ways.push_back({"indexed", gl::VolumeSource::Gpu, gl::GpuVolumeDraw::Indexed, FarCap::Exact, 0});
  }
  for (const Way& w : ways) {
    SCOPED_TRACE(w.name);
    gl::RenderOptions o;
    o.depthWidth = o.depthHeight = 128;
    o.volume = w.volume;
    o.gpuVolumeDraw = w.draw;
    o.volumeOptions.cap = w.cap;
    o.volumeOptions.refineSteps = w.refine;
    if (w.refine) o.volumeOptions.depthOracle = rays.oracle();
    o.volumeCount = gl::VolumeCount::ZFail;
    const gl::RenderResult zfail = r.render(o);
    o.volumeCount = gl::VolumeCount::Auto;
    const gl::RenderResult zpass = r.render(o);
    EXPECT_EQ(zfail.volumeCountUsed, gl::VolumeCount::ZFail);
    EXPECT_EQ(zpass.volumeCountUsed, gl::VolumeCount::ZPass);
    EXPECT_TRUE(zpass.zPassRefused.empty()) << zpass.zPassRefused;
    EXPECT_EQ(zpass.rgba, zfail.rgba);
    EXPECT_EQ(gltest::agreementWhere(zpass.stencil, zfail.stencil, inside), 1.0);
    std::size_t shadowed = 0;
    for (std::size_t k = 0; k < inside.size(); ++k) shadowed += inside[k] && zfail.stencil[k] != 0;
    EXPECT_GT(shadowed, 100u);
    if (w.volume == gl::VolumeSource::Gpu && w.cap == FarCap::Exact) {
      EXPECT_EQ(zpass.gpuVolumeQuadsDrawn, zfail.gpuVolumeQuadsDrawn);
      if (zfail.gpuVolumeDrawUsed == gl::GpuVolumeDraw::Indexed) {  // the cap of full blocks as fans
        EXPECT_TRUE(gltest::gpuVolumeTrianglesFit(zpass.volumeTriangles, zpass.gpuVolumeQuadsDrawn, false, true));
        EXPECT_TRUE(gltest::gpuVolumeTrianglesFit(zfail.volumeTriangles, zfail.gpuVolumeQuadsDrawn, true, true, true));
      } else {
        EXPECT_EQ(2 * zpass.volumeTriangles, zfail.volumeTriangles);
      }
    }
    if (w.volume == gl::VolumeSource::Explicit) {
      EXPECT_EQ(zpass.volumeTriangles + zpass.volumeStats->capTrianglesAfter, zfail.volumeTriangles);
    }
  }
}

// A camera under the sphere, inside the light's frustum beyond its near plane: Auto keeps z-fail
// and says why; asking for z-pass there is an error.
TEST(GlZPass, RefusedWhereTheCameraMayBeInsideTheVolume) {
  gl::Renderer& r = gltest::sharedRenderer();
  Scene scene = defaultScene();
  scene.camera.eye = {-0.2, 0.4, -0.1};
  scene.camera.target = {2.0, 0.0, 1.0};
  scene.camera.width = 96;
  scene.camera.height = 72;
  r.setScene(scene);
  gl::RenderOptions o;
  o.depthWidth = o.depthHeight = 64;
  const gl::RenderResult result = r.render(o);
  EXPECT_EQ(result.volumeCountUsed, gl::VolumeCount::ZFail);
  EXPECT_NE(result.zPassRefused.find("inside the volume"), std::string::npos) << result.zPassRefused;
  o.volumeCount = gl::VolumeCount::ZPass;
  try {
    r.render(o);
    ADD_FAILURE() << "z-pass was drawn where it is not safe";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not safe"), std::string::npos) << e.what();
  }
  // Silhouette volumes always count z-fail.
  o.method = gl::ShadowMethod::Silhouette;
  o.volumeCount = gl::VolumeCount::Auto;
  r.setScene(defaultScene());
  EXPECT_EQ(r.render(o).volumeCountUsed, gl::VolumeCount::ZFail);
}
