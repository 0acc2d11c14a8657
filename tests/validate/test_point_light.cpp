// Point lights (cube_map.h, cube_volume.h) through the renderer: the explicit cube volume's
// stencil against Embree's crossing counts in every option combination, on the shipped room and
// on a lamp above objects (far texels on every face); the GPU cube volume (cube_gpu_volume.h) the
// same way, through its CPU mirror, and its shadow against the explicit volume's; the GPU's cube
// capture against Embree's; the explicit volume refined by rays;
// the refined GPU cube volume (six face volumes) against its faces' meshes and the unrefined one;
// silhouette volumes extruded from the point; cube shadow maps; what a point light's frame cannot be.
#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "shadowvol/embree/depth_capture.h"
#include "shadowvol/embree/embree_depth_oracle.h"
#include "shadowvol/error.h"
#include "shadowvol/gl/renderer.h"
#include "shadowvol/primitives.h"
#include "shadowvol/validate/frame_validation.h"
#include "test_util.h"

namespace shadowvol {
namespace {

gl::Renderer& renderer() {
  static std::unique_ptr<gl::Renderer> r = std::make_unique<gl::Renderer>();
  return *r;
}

Scene room() {
  Scene s = loadScene(test::sourceDir() / "data" / "scenes" / "point" / "room.json").scene;
  s.camera.width = 160;
  s.camera.height = 120;
  return s;
}

// The default scene's sphere and ground under a point light where its spot light was: most
// texels of five faces see nothing (far), the sphere and the ground fill the -y face.
Scene lampOverSphere() {
  Scene s = defaultScene();
  s.light = Light{};
  s.light.type = LightType::Point;
  s.light.position = {0.8, 5.0, 0.6};
  fitLightAndCamera(s);
  s.camera.width = 160;
  s.camera.height = 120;
  return s;
}

FrameValidation renderAndValidate(const Scene& scene, gl::RenderOptions ro) {
  ro.readStencil = ro.readDepthMap = ro.readVisibility = ro.keepVolume = true;
  renderer().setScene(scene);
  const gl::RenderResult r = renderer().render(ro);
  RenderedFrame frame;
  frame.width = r.width;
  frame.height = r.height;
  frame.stencil = r.stencil;
  frame.hybrid = ro.method == gl::ShadowMethod::Hybrid;
  for (auto vis : r.visibility) frame.shadowed.push_back(vis < 128);
  frame.volume = r.volume;
  frame.stencilBits = r.stencilBits;
  frame.faceVolumes = r.faceVolumes;
  frame.faceGpuVolumes = r.faceGpuVolumes;
  EXPECT_FALSE(r.depthMap.has_value()) << "a point light's frame has six maps, not one";
  EXPECT_EQ(r.volumeCountUsed, gl::VolumeCount::ZFail);
  return validateFrame(scene, DepthMap{}, ro.volumeOptions, frame);
}

// Every capture mode, triangulation and blur at two face sizes, of the volume `source`: the
// stencil against the crossing counts of the explicit cube volume of the same faces (for the GPU
// volume, its CPU mirror: RenderOptions::keepVolume).
// With `refineSteps`, the explicit volume refined by the scene's rays (cube_volume.h), or the
// refined GPU cube volume (its six face volumes, each checked and counted: back, front and entry
// capture).
void expectCubeVolumeMatchesCrossingCounts(gl::VolumeSource source, std::initializer_list<int> sizes,
                                           gl::GpuVolumeDraw draw = gl::GpuVolumeDraw::Auto, int refineSteps = 0) {
  const bool faces = source == gl::VolumeSource::Gpu && refineSteps > 0;
  const std::vector<CaptureMode> modes = faces ? std::vector{CaptureMode::Back, CaptureMode::Front, CaptureMode::Entry}
                                               : std::vector{CaptureMode::Back, CaptureMode::Front, CaptureMode::Midpoint};
  int frames = 0;
  for (const Scene& scene : {room(), lampOverSphere()}) {
    const EmbreeDepthOracle oracle(scene);
    for (int n : sizes)
      for (CaptureMode mode : modes)
        for (Triangulation t : {Triangulation::Fixed, Triangulation::Perfect})
          for (bool blur : {false, true}) {
            gl::RenderOptions ro;
            ro.volume = source;
            ro.gpuVolumeDraw = draw;
            ro.depthWidth = ro.depthHeight = n;
            ro.capture = mode;
            ro.volumeOptions.triangulation = t;
            ro.volumeOptions.blur = blur;
            ro.volumeOptions.refineSteps = refineSteps;
            if (refineSteps > 0 && !faces) ro.volumeOptions.depthOracle = oracle.oracle();
            SCOPED_TRACE(scene.source + " " + std::to_string(n) + " " + toString(mode) + " " + toString(t) +
                         (blur ? " blur" : "") + (refineSteps > 0 ? " refined" : ""));
            const FrameValidation v = renderAndValidate(scene, ro);
            ASSERT_TRUE(v.meshCheck && v.meshCheck->valid()) << v.meshCheck->summary();
            if (faces) {
              ASSERT_TRUE(v.gpuMeshCheck && v.gpuMeshCheck->valid()) << "the GPU's own face volumes";
              EXPECT_GT(v.gpuMeshCheck->triangles, 0u);
            }
            EXPECT_GE(v.stencilVsCount.fraction(), kRequiredAgreement)
                << v.stencilVsCount.pixels - v.stencilVsCount.agree << " of " << v.stencilVsCount.pixels;
            EXPECT_TRUE(v.consistent) << (v.failures.empty() ? "" : v.failures.front());
            EXPECT_GT(v.exactShadowed, 0u) << "the scene casts shadows";
            EXPECT_EQ(v.outsideLight, 0u) << "the far cube holds the whole scene";
            ++frames;
          }
  }
  EXPECT_EQ(frames, 2 * int(sizes.size()) * int(modes.size()) * 2 * 2);
}

TEST(PointLight, CubeVolumeMatchesCrossingCountsInEveryCombination) {
  expectCubeVolumeMatchesCrossingCounts(gl::VolumeSource::Explicit, {24, 64});
}

// Refined by rays (cube_refinement.h), at an even and an odd face size.
TEST(PointLight, RefinedCubeVolumeMatchesCrossingCountsInEveryCombination) {
  expectCubeVolumeMatchesCrossingCounts(gl::VolumeSource::Explicit, {24, 37}, gl::GpuVolumeDraw::Auto, 3);
}

// A point light's explicit cube volume from six ray-cast faces (ExplicitDepth::Rays, each face
// the oracle at its texel centres): consistent with the crossing counts, refined and not.
TEST(PointLight, RayCastCubeFacesMatchCrossingCounts) {
  int frames = 0;
  for (const Scene& scene : {room(), lampOverSphere()}) {
    const EmbreeDepthOracle oracle(scene);
    for (CaptureMode mode : {CaptureMode::Back, CaptureMode::Midpoint})
      for (int steps : {0, 3}) {
        gl::RenderOptions ro;
        ro.volume = gl::VolumeSource::Explicit;
        ro.explicitDepth = gl::ExplicitDepth::Rays;
        ro.depthWidth = ro.depthHeight = 24;
        ro.capture = mode;
        ro.volumeOptions.refineSteps = steps;
        ro.volumeOptions.depthOracle = oracle.oracle();
        SCOPED_TRACE(scene.source + " " + toString(mode) + " refine " + std::to_string(steps));
        const FrameValidation v = renderAndValidate(scene, ro);
        ASSERT_TRUE(v.meshCheck && v.meshCheck->valid()) << v.meshCheck->summary();
        EXPECT_GE(v.stencilVsCount.fraction(), kRequiredAgreement)
            << v.stencilVsCount.pixels - v.stencilVsCount.agree << " of " << v.stencilVsCount.pixels;
        EXPECT_TRUE(v.consistent) << (v.failures.empty() ? "" : v.failures.front());
        EXPECT_GT(v.exactShadowed, 0u) << "the scene casts shadows";
        ++frames;
      }
  }
  EXPECT_EQ(frames, 2 * 2 * 2);
}

// The walls on the light's rays through the silhouette instead of slanting across a texel: on
// the room at 128 texels a face, refinement (4 rays per boundary edge for the explicit volume, the
// walk for the GPU's face volumes) misses or adds fewer than a third of the pixels that the
// unrefined volume of the same source does, back and front capture (measured: 32 against 587 of
// 301,690 for the explicit volume, README "Point lights").
void expectRefinementCutsTheError(gl::VolumeSource source) {
  const Scene scene = room();
  const EmbreeDepthOracle oracle(scene);
  for (CaptureMode mode : {CaptureMode::Back, CaptureMode::Front}) {
    gl::RenderOptions ro;
    ro.volume = source;
    ro.depthWidth = ro.depthHeight = 128;
    ro.capture = mode;
    const FrameValidation plain = renderAndValidate(scene, ro);
    ro.volumeOptions.refineSteps = 4;
    if (source == gl::VolumeSource::Explicit) ro.volumeOptions.depthOracle = oracle.oracle();
    const FrameValidation refined = renderAndValidate(scene, ro);
    EXPECT_TRUE(refined.consistent) << (refined.failures.empty() ? "" : refined.failures.front());
    EXPECT_LT(3 * (refined.methodError.missed + refined.methodError.falseShadow),
              plain.methodError.missed + plain.methodError.falseShadow)
        << toString(mode);
  }
}

TEST(PointLight, RefinementCutsTheCubeVolumesError) { expectRefinementCutsTheError(gl::VolumeSource::Explicit); }

// The GPU cube volume at an even and an odd face size (the seam cells' pairing, the corners),
// both ways of drawing it (cube_gpu_volume.h).
TEST(PointLight, GpuCubeVolumeMatchesCrossingCountsInEveryCombination) {
  expectCubeVolumeMatchesCrossingCounts(gl::VolumeSource::Gpu, {24, 37});
  expectCubeVolumeMatchesCrossingCounts(gl::VolumeSource::Gpu, {24, 37}, gl::GpuVolumeDraw::AllQuads);
}

// The refined GPU cube volume (six face volumes, each the refined GPU volume of its face's guarded
// frustum), through the CPU meshes of each face's crossings and the GPU's own triangles.
TEST(PointLight, RefinedGpuCubeVolumeMatchesCrossingCountsInEveryCombination) {
  expectCubeVolumeMatchesCrossingCounts(gl::VolumeSource::Gpu, {24, 37}, gl::GpuVolumeDraw::Auto, 4);
}

// The refined GPU cube volume against the unrefined GPU cube volume (the guard band matters here:
// without it, 90 against 36 wrong pixels at this test's image size).
TEST(PointLight, RefinedGpuCubeVolumeCutsTheError) { expectRefinementCutsTheError(gl::VolumeSource::Gpu); }

// The refined GPU cube volume's face image shares the camera's depth: after a frame at another
// image size (new camera targets), a frame at the first size again, from another eye, must use
// the new depth (regression: the face image's framebuffer kept the old depth renderbuffer).
TEST(PointLight, RefinedGpuCubeVolumeFollowsTheCameraTargets) {
  gl::RenderOptions ro;
  ro.volume = gl::VolumeSource::Gpu;
  ro.depthWidth = ro.depthHeight = 32;
  ro.volumeOptions.refineSteps = 4;
  EXPECT_TRUE(renderAndValidate(room(), ro).consistent);
  Scene small = room();
  small.camera.width = 80;
  small.camera.height = 60;
  renderer().setScene(small);
  gl::RenderOptions plain = ro;  // unrefined: the face image is not remade at this size
  plain.volumeOptions.refineSteps = 0;
  renderer().render(plain);
  Scene moved = room();
  moved.camera.eye = {-4.0, 2.0, 3.5};
  const FrameValidation v = renderAndValidate(moved, ro);
  EXPECT_GE(v.stencilVsCount.fraction(), kRequiredAgreement);
  EXPECT_TRUE(v.consistent) << (v.failures.empty() ? "" : v.failures.front());
}

// A fourteenth probe's crash: reading the refined GPU volume's records set a pack alignment of 4
// and left it, so the next one-byte read-back (the stencil) padded its rows past a buffer of
// width x height at widths not a multiple of 4 (heap corruption at 322 x 240). Two frames at an
// odd width, the refined GPU cube volume in each, read their stencil whole.
TEST(PointLight, RefinedGpuCubeVolumeAtAnOddImageWidthReadsItsStencilTight) {
  gl::RenderOptions ro;
  ro.volume = gl::VolumeSource::Gpu;
  ro.depthWidth = ro.depthHeight = 24;
  ro.volumeOptions.refineSteps = 4;
  Scene odd = room();
  odd.camera.width = 161;
  odd.camera.height = 37;
  for (int frame = 0; frame < 2; ++frame) {
    const FrameValidation v = renderAndValidate(odd, ro);
    EXPECT_GE(v.stencilVsCount.fraction(), kRequiredAgreement) << "frame " << frame;
    EXPECT_TRUE(v.consistent) << (v.failures.empty() ? "" : v.failures.front());
  }
}

// A probe's scene (2026-12-05): an axis-aligned box under a point light, whose corners fall on
// texel centres of the guarded faces. The snap walked a bracket on past its probes until it shrank
// onto the far end: the GPU put the crossing on the texel (degenerate walls in its own mesh) and
// the CPU mirror's far cap had two corners at one point (CGAL's triangulation crashed). Every
// crossing now keeps 2^-(K+2) from its edge's ends, snapped or not.
TEST(PointLight, RefinedGpuCubeVolumeOfABoxOnTexelCentresIsValid) {
  Scene s;
  s.objects = {SceneObject{"ground", "plane", makePlane(10.0, 10.0, 1)},
               SceneObject{"box", "box", makeBox(1.0, 1.0, 1.0)}};
  for (auto& p : s.objects[1].mesh.positions) p.y += 1.0f;
  s.light.type = LightType::Point;
  s.light.position = {1.0, 4.0, 1.0};
  s.camera.eye = {0.0, 4.0, 7.0};
  s.camera.target = {0.0, 0.5, 0.0};
  s.camera.width = 160;
  s.camera.height = 120;
  fitLightAndCamera(s);
  for (auto capture : {CaptureMode::Back, CaptureMode::Front})
    for (int steps : {1, 4})
      for (int side : {128, 256}) {
        gl::RenderOptions ro;
        ro.volume = gl::VolumeSource::Gpu;
        ro.capture = capture;
        ro.depthWidth = ro.depthHeight = side;
        ro.volumeOptions.refineSteps = steps;
        SCOPED_TRACE(std::string(toString(capture)) + " K " + std::to_string(steps) + " " + std::to_string(side));
        const FrameValidation v = renderAndValidate(s, ro);
        EXPECT_TRUE(v.consistent) << (v.failures.empty() ? "" : v.failures.front());
      }
}

// The GPU draws the explicit volume's triangles before the cap's flattening, in float: the same
// shadow up to the pixels where a float sheet vertex falls on the other side of a surface, and
// the same number of triangles as the explicit sheet and its unflattened cap, plus twice the
// all-far triangles of cells it keeps (drawn on the sheet and the cap, where they cancel).
TEST(PointLight, GpuCubeVolumeCastsTheExplicitVolumesShadow) {
  for (const Scene& scene : {room(), lampOverSphere()})
    for (CaptureMode mode : {CaptureMode::Back, CaptureMode::Front}) {
      gl::RenderOptions ro;
      ro.depthWidth = ro.depthHeight = 64;
      ro.capture = mode;
      ro.volume = gl::VolumeSource::Explicit;
      const FrameValidation e = renderAndValidate(scene, ro);
      ro.volume = gl::VolumeSource::Gpu;
      const FrameValidation g = renderAndValidate(scene, ro);
      SCOPED_TRACE(scene.source + " " + toString(mode));
      ASSERT_EQ(e.methodError.pixels, g.methodError.pixels);
      const auto differ = [](std::size_t a, std::size_t b) { return a > b ? a - b : b - a; };
      EXPECT_LE(differ(e.methodError.missed, g.methodError.missed) + differ(e.methodError.falseShadow, g.methodError.falseShadow),
                e.methodError.pixels / 5000)
          << "explicit " << e.methodError.missed << "/" << e.methodError.falseShadow << ", gpu "
          << g.methodError.missed << "/" << g.methodError.falseShadow;
    }
  // The cells drawn, at N = 16, for a lamp inside a closed box: back capture sees the box's inner
  // faces from every texel, so no cell is dropped. The indexed way draws the cap of each face's
  // one whole quadrant of 8 x 8 cells (cells 0-7 of 15) as a fan of 32 triangles instead of 128.
  Scene box = defaultScene();
  box.objects.assign(1, SceneObject{"box", "box", makeBox(6.0, 6.0, 6.0)});
  box.light = Light{};
  box.light.type = LightType::Point;
  box.light.position = {0.4, -0.3, 0.2};
  fitLightAndCamera(box);
  renderer().setScene(box);
  for (gl::GpuVolumeDraw how : {gl::GpuVolumeDraw::Auto, gl::GpuVolumeDraw::AllQuads}) {
    gl::RenderOptions ro;
    ro.depthWidth = ro.depthHeight = 16;
    ro.volume = gl::VolumeSource::Gpu;
    ro.gpuVolumeDraw = how;
    const gl::RenderResult r = renderer().render(ro);
    const std::size_t cells = 6 * 15 * 15 + 12 * 15 + 8;
    EXPECT_EQ(r.gpuVolumeDrawUsed, how == gl::GpuVolumeDraw::Auto ? gl::GpuVolumeDraw::Indexed : how);
    EXPECT_EQ(r.gpuVolumeQuads, cells);
    EXPECT_EQ(r.gpuVolumeQuadsDrawn, cells);
    const std::size_t fanSaving = how == gl::GpuVolumeDraw::Auto ? 6 * (128 - 32) : 0;
    EXPECT_EQ(r.volumeTriangles, 2 * (12 * 16 * 16 - 4) - fanSaving) << "every sheet triangle and its cap image";
    EXPECT_EQ(r.volumeCountUsed, gl::VolumeCount::ZFail);
  }
  // With far texels (the room, back capture: its walls face the lamp), the indexed way leaves
  // out the all-far sheet triangles as buildCubeVolume does: its kept sheet triangles, and as
  // many cap triangles less 96 for each quadrant drawn as a fan (some are, in the objects).
  renderer().setScene(room());
  gl::RenderOptions ro;
  ro.depthWidth = ro.depthHeight = 48;
  ro.volume = gl::VolumeSource::Gpu;
  ro.keepVolume = true;
  const gl::RenderResult r = renderer().render(ro);
  ASSERT_TRUE(r.volumeStats.has_value());
  const std::size_t sheet = r.volumeStats->capTrianglesBefore;
  EXPECT_LT(r.volumeTriangles, 2 * sheet);
  EXPECT_GT(r.volumeTriangles, sheet);
  EXPECT_EQ((2 * sheet - r.volumeTriangles) % 96, 0u) << r.volumeTriangles << " of " << 2 * sheet;
  EXPECT_LT(r.gpuVolumeQuadsDrawn, r.gpuVolumeQuads / 2) << "most of the room's cells are all far";
}

// The shadow follows the exact one more closely as the cube's texels shrink.
TEST(PointLight, CubeVolumeErrorFallsWithResolution) {
  double previous = 1.0;
  for (int n : {32, 128}) {
    gl::RenderOptions ro;
    ro.volume = gl::VolumeSource::Explicit;
    ro.depthWidth = ro.depthHeight = n;
    const FrameValidation v = renderAndValidate(room(), ro);
    EXPECT_LT(v.methodError.errorFraction(), previous) << n;
    previous = v.methodError.errorFraction();
  }
  EXPECT_LT(previous, 0.01);
}

namespace {

// The largest depth change from texel (i, j) to a 4-neighbour that also hit (0 if none).
double neighbourDepthChange(const DepthMap& m, int i, int j) {
  const float d = m.depth[m.index(i, j)];
  double change = 0.0;
  for (const auto& [di, dj] : {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}}) {
    const int a = i + di, b = j + dj;
    if (a < 0 || b < 0 || a >= m.width || b >= m.height) continue;
    const float e = m.depth[m.index(a, b)];
    if (std::isfinite(d) && std::isfinite(e)) change = std::max(change, double(std::abs(e - d)));
  }
  return change;
}

constexpr double kSubTexel = 1.0 / 256.0;

}  // namespace

TEST(PointLight, GpuCubeCaptureMatchesEmbree) {
  const Scene scene = room();
  renderer().setScene(scene);
  for (CaptureMode mode : {CaptureMode::Back, CaptureMode::Front, CaptureMode::Midpoint}) {
    const CubeDepthMap gpu = renderer().captureCube(48, mode), cpu = captureCubeEmbree(scene, 48, mode);
    std::size_t texels = 0, agree = 0;
    std::string differ;  // the first few texels that differ: face, texel, GPU and Embree depth
    for (int f = 0; f < kCubeFaces; ++f)
      for (std::size_t k = 0; k < gpu.faces[f].depth.size(); ++k) {
        const float a = gpu.faces[f].depth[k], b = cpu.faces[f].depth[k];
        ++texels;
        // The rasteriser interpolates depth over vertices snapped to its sub-pixel grid (8 bits on
        // NVIDIA's driver and llvmpipe): on a steep surface that is kSubTexel of the depth's
        // change to the next texel (NVIDIA: 5e-4 on the ceiling at a 0.37 change per texel).
        const double slope = neighbourDepthChange(cpu.faces[f], int(k % 48), int(k / 48));
        const bool same =
            (a == b) || std::abs(a - b) <= std::max(1e-4 * std::max(a, b), kSubTexel * slope);
        agree += same;
        if (!same && texels - agree <= 12)
          differ += " face " + std::to_string(f) + " (" + std::to_string(k % 48) + ", " + std::to_string(k / 48) +
                    "): " + std::to_string(a) + " vs " + std::to_string(b) + ";";
      }
    // Texels on a silhouette may differ (rasterisation against ray casting at the same centre).
    EXPECT_GE(double(agree) / double(texels), 0.995) << toString(mode) << ":" << differ;
  }
}

TEST(PointLight, SilhouetteVolumesExtrudeFromThePoint) {
  gl::RenderOptions ro;
  ro.method = gl::ShadowMethod::Silhouette;
  const Scene scene = room();
  renderer().setScene(scene);
  ro.readVisibility = true;
  const gl::RenderResult r = renderer().render(ro);
  RenderedFrame frame;
  frame.width = r.width;
  frame.height = r.height;
  frame.hybrid = false;  // scored by its own shadow test, the stencil read as visibility
  for (auto vis : r.visibility) frame.shadowed.push_back(vis < 128);
  const FrameValidation v = validateFrame(scene, DepthMap{}, ro.volumeOptions, frame);
  EXPECT_GT(v.exactShadowed, 0u);
  EXPECT_LT(v.methodError.errorFraction(), 0.001);
}

// The cube shadow map (and PCF over it) against exact shadows, in every capture mode: scored like
// any shadow map, and closer to the exact shadow with more texels per face.
TEST(PointLight, CubeShadowMapsFollowTheExactShadow) {
  const Scene scene = room();
  renderer().setScene(scene);
  for (auto m : {gl::ShadowMethod::ShadowMap, gl::ShadowMethod::Pcf3, gl::ShadowMethod::Pcf5})
    for (CaptureMode mode : {CaptureMode::Back, CaptureMode::Front, CaptureMode::Midpoint}) {
      double previous = 1.0;
      for (int n : {32, 256}) {
        gl::RenderOptions ro;
        ro.method = m;
        ro.capture = mode;
        ro.depthWidth = ro.depthHeight = n;
        ro.readVisibility = true;
        const gl::RenderResult r = renderer().render(ro);
        RenderedFrame frame;
        frame.width = r.width;
        frame.height = r.height;
        frame.hybrid = false;
        for (auto vis : r.visibility) frame.shadowed.push_back(vis < 128);
        const FrameValidation v = validateFrame(scene, DepthMap{}, ro.volumeOptions, frame);
        EXPECT_GT(v.exactShadowed, 0u);
        EXPECT_LT(v.methodError.errorFraction(), previous) << gl::toString(m) << " " << toString(mode) << " " << n;
        previous = v.methodError.errorFraction();
      }
      EXPECT_LT(previous, 0.01) << gl::toString(m) << " " << toString(mode);
    }
}

TEST(PointLight, RefusesWhatItsFrameCannotBe) {
  renderer().setScene(room());
  gl::RenderOptions ro;
  ro.depthWidth = ro.depthHeight = 32;
  ro.volume = gl::VolumeSource::Gpu;
  ro.volumeOptions.refineSteps = 4;
  ro.capture = CaptureMode::Midpoint;  // the refined GPU cube volume walks one layer
  EXPECT_THROW(renderer().render(ro), InputError);
  ro.capture = CaptureMode::Back;
  ro.gpuVolumeDraw = gl::GpuVolumeDraw::AllQuads;  // its faces list their triangles their own way
  EXPECT_THROW(renderer().render(ro), InputError);
  ro.gpuVolumeDraw = gl::GpuVolumeDraw::Auto;
  ro.depthWidth = ro.depthHeight = 2048 - 7;  // with its guard band past 2048 texels a side
  EXPECT_THROW(renderer().render(ro), InputError);
  ro.depthWidth = ro.depthHeight = 32;
  EXPECT_NO_THROW(renderer().render(ro));
  ro.volumeOptions.refineSteps = 0;
  ro.volumeOptions.cap = FarCap::Quad;  // the cube has no border ring for the quad cap to close
  EXPECT_THROW(renderer().render(ro), InputError);
  ro.volumeOptions.cap = FarCap::Exact;
  ro.gpuVolumeDraw = gl::GpuVolumeDraw::KeptQuads;  // the cube volume is drawn indexed or per cell
  EXPECT_THROW(renderer().render(ro), InputError);
  ro.gpuVolumeDraw = gl::GpuVolumeDraw::Auto;
  ro.volume = gl::VolumeSource::Explicit;
  ro.volumeOptions.refineSteps = 4;  // without a depth oracle
  EXPECT_THROW(renderer().render(ro), InputError);
  const EmbreeDepthOracle oracle(room());
  ro.volumeOptions.depthOracle = oracle.oracle();
  ro.refineCrossings = gl::RefineCrossings::GpuWalk;  // rays only
  EXPECT_THROW(renderer().render(ro), InputError);
  ro.refineCrossings = gl::RefineCrossings::Rays;
  ro.volumeOptions.refineChords = true;
  EXPECT_THROW(renderer().render(ro), InputError);
  ro.volumeOptions.refineChords = false;
  ro.volumeOptions.refineSubdivisions = 2;
  EXPECT_THROW(renderer().render(ro), InputError);
  ro.volumeOptions.refineSubdivisions = 1;
  EXPECT_NO_THROW(renderer().render(ro));
  ro.volumeOptions.refineSteps = 0;
  ro.volumeCount = gl::VolumeCount::ZPass;
  EXPECT_THROW(renderer().render(ro), InputError);
  ro.volumeCount = gl::VolumeCount::Auto;
  ro.depthHeight = 16;
  EXPECT_THROW(renderer().render(ro), InputError);
  EXPECT_THROW(renderer().captureDepth(32, 32, CaptureMode::Back), InputError);
}

}  // namespace
}  // namespace shadowvol
