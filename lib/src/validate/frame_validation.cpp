#include "shadowvol/validate/frame_validation.h"

#include "shadowvol/validate/double_recount.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "shadowvol/check.h"
#include "shadowvol/cube_map.h"
#include "shadowvol/embree/embree_scene.h"
#include "shadowvol/error.h"

namespace shadowvol {
namespace {

bool facesLight(PixelClass c) { return c == PixelClass::Lit || c == PixelClass::Shadowed; }

std::string percent(double fraction) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g %%", 100.0 * fraction);
  return buf;
}

void score(ShadowError& e, PixelClass exact, bool testShadowed) {
  if (!facesLight(exact)) return;
  ++e.pixels;
  const bool exactShadowed = exact == PixelClass::Shadowed;
  if (exactShadowed && !testShadowed) ++e.missed;
  if (!exactShadowed && testShadowed) ++e.falseShadow;
}

}  // namespace

FrameValidation validateFrame(const Scene& scene, const DepthMap& depth, const VolumeBuildOptions& volumeOptions,
                              const RenderedFrame& frame, const ValidationOptions& options) {
  const std::size_t n = std::size_t(frame.width) * std::size_t(frame.height);
  SV_CHECK_EQ(frame.width, scene.camera.width);
  SV_CHECK_EQ(frame.height, scene.camera.height);
  if (frame.hybrid) SV_CHECK_EQ(frame.stencil.size(), n);
  if (!frame.shadowed.empty()) SV_CHECK_EQ(frame.shadowed.size(), n);

  FrameValidation v;
  v.width = frame.width;
  v.height = frame.height;

  // Exact shadows by ray casting the scene.
  const EmbreeDevice device;
  std::vector<const TriangleMesh*> meshes;
  for (const auto& o : scene.objects) meshes.push_back(&o.mesh);
  const EmbreeScene sceneRt(device, meshes);
  const CameraHits hits = castPrimaryRays(sceneRt, scene.camera);
  v.exact = exactShadows(sceneRt, scene, hits, shadowRayOffset(scene));
  for (PixelClass c : v.exact) {
    switch (c) {
      case PixelClass::Background: ++v.background; break;
      case PixelClass::FacingAway: ++v.facingAway; break;
      case PixelClass::OutsideLight: ++v.outsideLight; break;
      case PixelClass::Lit: ++v.exactLit; break;
      case PixelClass::Shadowed: ++v.exactShadowed; break;
    }
  }
  v.visible = n - v.background;

  // The method's own test.
  for (std::size_t k = 0; k < n; ++k) {
    const bool shadowed = !frame.shadowed.empty() ? frame.shadowed[k] != 0 : (frame.hybrid && frame.stencil[k] != 0);
    score(v.methodError, v.exact[k], shadowed);
  }

  if (frame.hybrid) {
    // The explicit volume of the same depth map and options, its checks and crossing counts.
    if (!frame.volume && scene.light.type == LightType::Point)
      throw InputError(scene.source, "/light/type", "point",
                       "validating a point light's frame needs its volume (RenderOptions::keepVolume)");
    const VolumeMesh volume = frame.volume ? *frame.volume : buildVolume(depth, volumeOptions).mesh;
    MeshCheckOptions co;
    co.selfIntersections = options.selfIntersections;
    // Sheet and cap may touch on the far plane (a point light's: its far cube, cube_map.h).
    const Light& light = scene.light;
    const double far = light.type == LightType::Point ? light.farPlane : depth.farPlane, farTolerance = 1e-7 * far;
    co.allowedTouch = [&depth, &light, far, farTolerance](const glm::dvec3& p) {
      const double d = light.type == LightType::Point ? cubeDepth(p - light.position) : depth.viewDepthOf(p);
      return std::abs(d - far) <= farTolerance;
    };
    v.meshCheck = checkMesh(volume, co);
    if (frame.gpuVolume) v.gpuMeshCheck = checkMesh(*frame.gpuVolume, co);
    const TriangleMesh volumeF = volume.toTriangleMesh();
    const EmbreeScene volumeRt(device, {&volumeF});
    v.counts = countCrossings(volumeRt, scene.camera, hits);
    if (v.meshCheck->closedManifold() && volume.triangleCount() > 0) {
      const auto side = VolumeClassifier(volume).classify(scene.camera.eye);
      v.eyeInsideVolume = side != VolumeClassifier::Side::Outside;
      if (side != VolumeClassifier::Side::Boundary)
        v.recountedPixels = recountInconsistentPixels(volume, scene.camera, hits, v.eyeInsideVolume ? 1 : 0, *v.counts);
    }
    Agreement zz;
    ShadowError stencilErr, countErr;
    v.stencilOverLitFrustumOnly = frame.zPass;
    for (std::size_t k = 0; k < n; ++k) {
      if (v.exact[k] == PixelClass::Background) continue;
      const int zfail = v.counts->zfail[k];
      if (!(frame.zPass && v.exact[k] == PixelClass::OutsideLight)) {
        ++v.stencilVsCount.pixels;
        if (std::uint8_t(zfail) == frame.stencil[k]) {
          ++v.stencilVsCount.agree;
        } else {
          for (int c = v.counts->zfailMin[k]; c <= v.counts->zfailMax[k]; ++c)
            if (std::uint8_t(c) == frame.stencil[k]) {
              ++v.stencilVsCount.agree;
              ++v.stencilVsCount.ties;
              break;
            }
        }
      }
      ++zz.pixels;
      if (zfail == v.counts->zpass[k]) ++zz.agree;
      score(stencilErr, v.exact[k], frame.stencil[k] != 0);
      score(countErr, v.exact[k], zfail != 0);
    }
    if (!v.eyeInsideVolume) v.zfailVsZpass = zz;
    v.stencilError = stencilErr;
    v.countError = countErr;
    const MeshCheckReport& m = *v.meshCheck;
    bool meshOk = m.valid();
    if (volumeOptions.cap == FarCap::Quad) {
      v.meshChecksNotApplicable = "outward orientation and self-intersections: the quad cap's far rectangle "
                                  "coincides with the far-plane sheet by design";
      meshOk = m.closedManifold() && m.nonFiniteVertices == 0 && m.degenerateTriangles == 0 && m.isolatedVertices == 0;
    }
    if (v.stencilVsCount.fraction() < kRequiredAgreement)
      v.failures.push_back("stencil and crossing counts agree on " + percent(v.stencilVsCount.fraction()) +
                           " of visible pixels, below the required " + percent(kRequiredAgreement));
    if (!meshOk) v.failures.push_back("the volume's mesh checks fail: " + m.summary());
    if (v.gpuMeshCheck && !v.gpuMeshCheck->valid())
      v.failures.push_back("the GPU volume's mesh checks fail: " + v.gpuMeshCheck->summary());
    v.consistent = v.failures.empty();
  }
  // The accuracy verdict: the method's own test against the exact shadows.
  const ShadowError& e = v.methodError;
  std::vector<std::string> inaccurate;
  if (e.pixels == 0)  // a verdict on no pixel would pass whatever the method does
    inaccurate.push_back("no visible pixel faces the light inside its frustum, so the frame checks nothing "
                         "(are the light, the camera and the objects where they were meant to be?)");
  if (e.errorFraction() > options.maxError)
    inaccurate.push_back("the method misclassifies " + percent(e.errorFraction()) + " of the pixels facing the light, "
                         "above the allowed " + percent(options.maxError) + " (--max-error)");
  if (v.exactShadowed >= kMinShadowPixels && double(e.missed) > options.maxMissedShare * double(v.exactShadowed))
    inaccurate.push_back("the method misses " + std::to_string(e.missed) + " of the exact shadow's " +
                         std::to_string(v.exactShadowed) + " pixels, more than " + percent(options.maxMissedShare));
  v.accurate = inaccurate.empty();
  v.failures.insert(v.failures.end(), inaccurate.begin(), inaccurate.end());
  v.passed = v.consistent && v.accurate;
  device.throwIfError();
  return v;
}

}  // namespace shadowvol
