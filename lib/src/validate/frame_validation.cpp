#include "shadowvol/validate/frame_validation.h"

#include "shadowvol/validate/double_recount.h"
#include "shadowvol/validate/image_plane_surfaces.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

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

// One volume's mesh checks and crossing counts, with the eye's side and the double recount of the
// pixels that contradict it (double_recount.h).
struct CountedVolume {
  MeshCheckReport mesh;
  std::optional<MeshCheckReport> gpuMesh;
  CrossingCounts counts;
  bool eyeInside = false;
  std::size_t recounted = 0;
};

// One part's crossing counts (its mesh checked already: `closed` when a closed 2-manifold), the
// eye's side and the double recount of the pixels that contradict it. The eye's winding number in
// the part: the classifier's side for a simple solid (a part that does not overlap itself: the
// first), the signed count of windingNumber for one that may (the face prisms, where two overlapping
// prisms put the eye at 2 and parity would say outside).
void countPart(const EmbreeDevice& device, const VolumeMesh& part, bool overlapping, bool closed, const Camera& camera,
               const CameraHits& hits, CountedVolume& c) {
  const TriangleMesh partF = part.toTriangleMesh();
  const EmbreeScene partRt(device, {&partF});
  c.counts = countCrossings(partRt, camera, hits);
  if (!closed || part.triangleCount() == 0) return;
  int winding = 0;
  if (overlapping) {
    winding = windingNumber(part, camera.eye - part.origin);
  } else {
    const auto side = VolumeClassifier(part).classify(camera.eye);
    if (side == VolumeClassifier::Side::Boundary) {
      c.eyeInside = true;
      return;  // no recount: the eye on the surface has no side
    }
    winding = side == VolumeClassifier::Side::Inside ? 1 : 0;
  }
  c.eyeInside = winding != 0;
  c.recounted = recountInconsistentPixels(part, camera, hits, winding, c.counts);
}

// A volume's mesh checks and crossing counts. A volume of several overlapping parts
// (VolumeMesh::partStarts) is counted part by part, the counts added (a z-fail count is a sum over
// the faces: the parts' add up, as in the stencil), the ranges too, so that each part's eye side
// and recount are its own.
CountedVolume countVolume(const EmbreeDevice& device, const VolumeMesh& volume, const VolumeMesh* gpuVolume,
                          const MeshCheckOptions& co, const Camera& camera, const CameraHits& hits) {
  CountedVolume c;
  c.mesh = checkMesh(volume, co);
  if (gpuVolume) c.gpuMesh = checkMesh(*gpuVolume, co);
  const bool closed = c.mesh.closedManifold();
  if (volume.partCount() == 1) {
    countPart(device, volume, false, closed, camera, hits, c);
    return c;
  }
  for (std::size_t k = 0; k < volume.partCount(); ++k) {
    CountedVolume p;
    countPart(device, volume.partMesh(k), k > 0, closed, camera, hits, p);
    if (k == 0) {
      c.counts = std::move(p.counts);
    } else {
      for (std::size_t i = 0; i < c.counts.zfail.size(); ++i) {
        c.counts.zfail[i] += p.counts.zfail[i];
        c.counts.zpass[i] += p.counts.zpass[i];
        c.counts.zfailMin[i] += p.counts.zfailMin[i];
        c.counts.zfailMax[i] += p.counts.zfailMax[i];
      }
    }
    c.eyeInside = c.eyeInside || p.eyeInside;
    c.recounted += p.recounted;
  }
  return c;
}

// The faces a surface point's counts may come from (RenderedFrame::faceVolumes): cubeLookup's, and
// the face of the second largest |coordinate| when that is within kFaceTieTolerance of the largest
// (else the same face twice).
std::pair<int, int> pixelFaces(const glm::dvec3& offset) {
  const int first = cubeLookup(offset, 1).face, axis = first / 2;
  const glm::dvec3 a = glm::abs(offset);
  int second = -1;
  for (int k = 0; k < 3; ++k)
    if (k != axis && (second < 0 || a[k] > a[second])) second = k;
  if (!(a[second] >= a[axis] * (1.0 - kFaceTieTolerance))) return {first, first};
  return {first, 2 * second + (offset[second] < 0.0 ? 1 : 0)};
}

// A refined GPU cube volume's six face volumes counted as one: their checks summed (each face's
// sheet and cap may touch on the face's far plane), each pixel's counts those of its face, its
// admissible range both faces' in the tie band.
CountedVolume countFaceVolumes(const EmbreeDevice& device, const RenderedFrame& frame, const Light& light,
                               bool selfIntersections, const Camera& camera, const CameraHits& hits) {
  if (frame.faceVolumes.size() != std::size_t(kCubeFaces) ||
      !(frame.faceGpuVolumes.empty() || frame.faceGpuVolumes.size() == std::size_t(kCubeFaces)))
    throw InputError("RenderedFrame", "faceVolumes", std::to_string(frame.faceVolumes.size()) + " meshes",
                     "a refined GPU cube volume has one volume per cube face (6)");
  std::vector<CountedVolume> faces;
  std::vector<MeshCheckReport> meshes, gpuMeshes;
  const double far = light.farPlane, farTolerance = 1e-7 * far;
  for (int f = 0; f < kCubeFaces; ++f) {
    MeshCheckOptions co;
    co.selfIntersections = selfIntersections;
    const glm::dvec3 axis = cubeFaceDirection(f), apex = light.position;
    co.allowedTouch = [axis, apex, far, farTolerance](const glm::dvec3& p) {
      return std::abs(glm::dot(p - apex, axis) - far) <= farTolerance;
    };
    const VolumeMesh* gpu = frame.faceGpuVolumes.empty() ? nullptr : &frame.faceGpuVolumes[std::size_t(f)];
    faces.push_back(countVolume(device, frame.faceVolumes[std::size_t(f)], gpu, co, camera, hits));
    meshes.push_back(faces.back().mesh);
    if (faces.back().gpuMesh) gpuMeshes.push_back(*faces.back().gpuMesh);
  }
  CountedVolume c;
  c.mesh = sumReports(meshes);
  if (!gpuMeshes.empty()) c.gpuMesh = sumReports(gpuMeshes);
  c.counts = faces[0].counts;
  for (std::size_t k = 0; k < hits.point.size(); ++k) {
    if (hits.isBackground(k)) continue;
    const auto [first, second] = pixelFaces(hits.point[k] - light.position);
    const CrossingCounts& a = faces[std::size_t(first)].counts;
    const CrossingCounts& b = faces[std::size_t(second)].counts;
    c.counts.zfail[k] = a.zfail[k];
    c.counts.zpass[k] = a.zpass[k];
    c.counts.zfailMin[k] = std::min(a.zfailMin[k], b.zfailMin[k]);
    c.counts.zfailMax[k] = std::max(a.zfailMax[k], b.zfailMax[k]);
  }
  for (const CountedVolume& f : faces) {
    c.eyeInside = c.eyeInside || f.eyeInside;
    c.recounted += f.recounted;
  }
  return c;
}

// "(x, row)" of image index k.
std::string pixelText(std::size_t k, int width) {
  return "(" + std::to_string(k % std::size_t(width)) + ", " + std::to_string(k / std::size_t(width)) + ")";
}

}  // namespace

FrameValidation validateFrame(const Scene& scene, const DepthMap& depth, const VolumeBuildOptions& volumeOptions,
                              const RenderedFrame& frame, const ValidationOptions& options) {
  const std::size_t n = std::size_t(frame.width) * std::size_t(frame.height);
  SV_CHECK_EQ(frame.width, scene.camera.width);
  SV_CHECK_EQ(frame.height, scene.camera.height);
  if (frame.hybrid) SV_CHECK_EQ(frame.stencil.size(), n);
  if (!frame.shadowed.empty()) SV_CHECK_EQ(frame.shadowed.size(), n);
  if (!(options.maxError >= 0.0 && options.maxError <= 1.0))  // NaN too: it would pass every frame
    throw InputError("ValidationOptions", "maxError", numberText(options.maxError), "must be in [0, 1]");
  if (!(options.maxMissedShare >= 0.0 && options.maxMissedShare <= 1.0))
    throw InputError("ValidationOptions", "maxMissedShare", numberText(options.maxMissedShare),
                     "must be in [0, 1]");
  if (!(options.exactOffsetScale >= 0.0 && options.exactOffsetScale <= 1.0))
    throw InputError("ValidationOptions", "exactOffsetScale", numberText(options.exactOffsetScale),
                     "must be in [0, 1]");

  FrameValidation v;
  v.width = frame.width;
  v.height = frame.height;

  // Exact shadows by ray casting the scene.
  const EmbreeDevice device;
  std::vector<const TriangleMesh*> meshes;
  for (const auto& o : scene.objects) meshes.push_back(&o.mesh);
  const EmbreeScene sceneRt(device, meshes);
  const CameraHits hits = castPrimaryRays(sceneRt, scene.camera);
  std::vector<std::uint32_t> occluders;
  v.exact = exactShadows(sceneRt, scene, hits, options.exactOffsetScale * shadowRayOffset(scene), &occluders);
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

  // The method's own test, and its errors by cause where it has one depth map.
  std::vector<std::uint8_t> methodShadowed(n);
  for (std::size_t k = 0; k < n; ++k) {
    methodShadowed[k] = !frame.shadowed.empty() ? frame.shadowed[k] != 0 : (frame.hybrid && frame.stencil[k] != 0);
    score(v.methodError, v.exact[k], methodShadowed[k] != 0);
  }
  std::vector<std::uint32_t> receivers(n);
  for (std::size_t k = 0; k < n; ++k) receivers[k] = hits.triangle[k].geomID;
  v.lostShadows = findLostShadows(v.exact, methodShadowed, occluders, receivers);
  if (auto& w = v.lostShadows.worst; w && w->object < scene.objects.size()) w->name = scene.objects[w->object].name;
  if (frame.depthOffset && depth.width > 0 && scene.light.type != LightType::Point)
    v.errorCauses = splitErrorCauses(scene, depth, *frame.depthOffset, hits, v.exact, methodShadowed, frame.hybrid);
  if (frame.leakMapSide) {
    LeakTexels texels;
    texels.offset = frame.leakOffset;
    texels.slope = frame.leakOffsetSlope;
    if (*frame.leakMapSide > 0 && scene.light.type == LightType::Point) texels.cubeSide = *frame.leakMapSide;
    else if (*frame.leakMapSide > 0) texels.map = &depth;
    if (!(texels.map && depth.width == 0)) v.leaks = findShadowLeaks(scene, texels, hits, v.exact, methodShadowed);
  }

  if (frame.hybrid) {
    // The explicit volume of the same depth map and options (or a cube volume's six faces), its
    // checks and crossing counts.
    const bool faces = !frame.faceVolumes.empty();
    if (!frame.volume && !faces && scene.light.type == LightType::Point)
      throw InputError(scene.source, "/light/type", "point",
                       "validating a point light's frame needs its volume (RenderOptions::keepVolume)");
    const Light& light = scene.light;
    CountedVolume counted;
    std::optional<VolumeMesh> volume;  // the single volume counted (else a cube's face volumes)
    if (faces) {
      counted = countFaceVolumes(device, frame, light, options.selfIntersections, scene.camera, hits);
    } else {
      volume = frame.volume ? *frame.volume : buildVolume(depth, volumeOptions).mesh;
      MeshCheckOptions co;
      co.selfIntersections = options.selfIntersections;
      // Sheet and cap may touch on the far plane (a point light's: its far cube, cube_map.h).
      const double far = light.type == LightType::Point ? light.farPlane : depth.farPlane, farTolerance = 1e-7 * far;
      co.allowedTouch = [&depth, &light, far, farTolerance](const glm::dvec3& p) {
        const double d = light.type == LightType::Point ? cubeDepth(p - light.position) : depth.viewDepthOf(p);
        return std::abs(d - far) <= farTolerance;
      };
      counted = countVolume(device, *volume, frame.gpuVolume ? &*frame.gpuVolume : nullptr, co, scene.camera, hits);
    }
    v.meshCheck = counted.mesh;
    v.gpuMeshCheck = counted.gpuMesh;
    v.counts = std::move(counted.counts);
    v.eyeInsideVolume = counted.eyeInside;
    v.recountedPixels = counted.recounted;
    // Counts modulo the stencil's counting bits (2^8 but for the refined GPU cube volume's 2^7).
    const int modulus = 1 << std::clamp(frame.stencilBits, 1, 8);
    const auto wrapped = [modulus](int c) { return std::uint8_t(((c % modulus) + modulus) % modulus); };
    Agreement zz;
    ShadowError stencilErr, countErr;
    v.stencilOverLitFrustumOnly = frame.zPass;
    const auto compared = [&](std::size_t k) {
      return v.exact[k] != PixelClass::Background && !(frame.zPass && v.exact[k] == PixelClass::OutsideLight);
    };
    const auto admissible = [&](std::size_t k) {
      for (int c = v.counts->zfailMin[k]; c <= v.counts->zfailMax[k]; ++c)
        if (wrapped(c) == frame.stencil[k]) return true;
      return wrapped(v.counts->zfail[k]) == frame.stencil[k];
    };
    // The pixels outside their admissible range get the image-plane tie band (double_recount.h).
    std::vector<std::size_t> outside;
    for (std::size_t k = 0; k < n; ++k)
      if (compared(k) && !admissible(k)) outside.push_back(k);
    if (!outside.empty()) {
      // The scene's visible depth at the tie square's corners (its own silhouettes snap too).
      const auto cornerDepthsOf = [&](const std::vector<std::size_t>& pixels) {
        return visibleDepths(sceneRt, scene.camera, pixels, imagePlaneTieCorners());
      };
      std::vector<const TriangleMesh*> meshes;
      for (const auto& o : scene.objects) meshes.push_back(&o.mesh);
      const auto nearDepthsOf = [&](const std::vector<std::size_t>& pixels) {
        return surfaceDepthsNearPixels(meshes, scene.camera, pixels, kImagePlaneTie);
      };
      if (volume) {
        widenImagePlaneTies(*volume, scene.camera, hits, outside, *v.counts, cornerDepthsOf(outside),
                            nearDepthsOf(outside));
      } else {  // a cube's face volumes: each pixel by the volumes of its faces (pixelFaces)
        std::array<std::vector<std::size_t>, kCubeFaces> byFace;
        for (std::size_t k : outside) {
          const auto [first, second] = pixelFaces(hits.point[k] - light.position);
          byFace[std::size_t(first)].push_back(k);
          if (second != first) byFace[std::size_t(second)].push_back(k);
        }
        for (int f = 0; f < kCubeFaces; ++f)
          widenImagePlaneTies(frame.faceVolumes[std::size_t(f)], scene.camera, hits, byFace[std::size_t(f)], *v.counts,
                              cornerDepthsOf(byFace[std::size_t(f)]), nearDepthsOf(byFace[std::size_t(f)]));
      }
      for (std::size_t k : outside) v.stencilVsCount.imagePlaneTies += admissible(k);
    }
    for (std::size_t k = 0; k < n; ++k) {
      if (v.exact[k] == PixelClass::Background) continue;
      const int zfail = v.counts->zfail[k];
      if (compared(k)) {
        ++v.stencilVsCount.pixels;
        if (wrapped(zfail) == frame.stencil[k]) {
          ++v.stencilVsCount.agree;
        } else if (admissible(k)) {
          ++v.stencilVsCount.agree;
          ++v.stencilVsCount.ties;
        } else if (v.stencilVsCount.firstMisses.size() < Agreement::kListedMisses) {
          const int x = int(k % std::size_t(frame.width)), row = int(k / std::size_t(frame.width));
          v.stencilVsCount.firstMisses.push_back(
              {x, row, frame.stencil[k], zfail, v.counts->zfailMin[k], v.counts->zfailMax[k]});
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
    if (v.stencilVsCount.fraction() < kRequiredAgreement) {
      // Digits enough to show the shortfall (a probe saw "99.99 %, below the required 99.99 %").
      char agreed[96];
      std::snprintf(agreed, sizeof agreed, "%.4f %% (%zu of %zu)", 100.0 * v.stencilVsCount.fraction(),
                    std::size_t(v.stencilVsCount.agree), std::size_t(v.stencilVsCount.pixels));
      v.failures.push_back("stencil and crossing counts agree on " + std::string(agreed) +
                           " of visible pixels, below the required " + percent(kRequiredAgreement));
    }
    if (!meshOk)
      v.failures.push_back(std::string(faces ? "the face volumes' mesh checks (summed over the six) fail: "
                                             : "the volume's mesh checks fail: ") +
                           m.summary());
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
  if (v.leaks && v.leaks->deep > kMaxLeakPixels)
    inaccurate.push_back("the method misses " + std::to_string(v.leaks->deep) + " pixels deep inside the exact "
                         "shadow, further from its outline than its texels and depth offset reach (at most " +
                         std::to_string(kMaxLeakPixels) + "): a hole in the shadow (the first at pixel " + pixelText(v.leaks->firstDeep.front(), frame.width) + ", row 0 at the top)");
  if (const auto& worst = v.lostShadows.worst;
      worst && double(worst->missed) > options.maxMissedShare * double(worst->pixels))
    inaccurate.push_back("the method misses " + std::to_string(worst->missed) + " of the " +
                         std::to_string(worst->pixels) + " pixels of object \"" + worst->name +
                         "\"'s shadow (the first at pixel " + pixelText(worst->first, frame.width) +
                         ", row 0 at the top), more than " + percent(options.maxMissedShare) +
                         " (--max-missed): a shadow lost (an occluder thinner than the method's texels, say: a finer "
                         "map finds it" + (frame.hybrid ? ", as does the explicit volume's sub-grid)" : ")"));
  if (v.errorCauses && v.errorCauses->border > kMaxBorderPixels)
    inaccurate.push_back("the method misses " + std::to_string(v.errorCauses->border) +
                         " pixels less than a texel inside the light window's outermost texel centres, where a "
                         "shadow reaches the window's edge (at most " + std::to_string(kMaxBorderPixels) +
                         "): the volume's map has no guard band there (its outermost ring lies on the far plane; "
                         "light.h, kVolumeGuardTexels), or the band failed");
  v.accurate = inaccurate.empty();
  v.failures.insert(v.failures.end(), inaccurate.begin(), inaccurate.end());
  v.passed = v.consistent && v.accurate;
  device.throwIfError();
  return v;
}

}  // namespace shadowvol
