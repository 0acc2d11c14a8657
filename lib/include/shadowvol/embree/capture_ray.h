// The capture rule of one light ray (depth_capture.h's modes), shared by the CPU depth capture and
// the Embree depth oracle so that both record the same surface.
#pragma once

#include <span>

#include <embree3/rtcore.h>

#include "shadowvol/depth_map.h"

namespace shadowvol {

/// The light-view depth that `mode` records along the ray (its parameter is the light-view depth,
/// TexelUnprojector::ray), within [tNear, tFar]; DepthMap::kNoHit when nothing is recorded.
float captureRay(RTCScene scene, const TexelUnprojector::Ray& ray, float tNear, float tFar, CaptureMode mode);

/// captureRay for each of `rays` into depth[k], with the same values (tests/embree: bit for bit):
/// front, back and entry capture trace packets of eight consecutive rays (rtcIntersect8; a map's
/// rows capture faster so, README "Depth maps"), midpoint capture one ray at a time (its filter
/// keeps one ray's two nearest surfaces). depth.size() == rays.size().
void captureRays(RTCScene scene, std::span<const TexelUnprojector::Ray> rays, float tNear, float tFar, CaptureMode mode,
                 std::span<float> depth);

/// The hit captureRay records, for front, back and entry capture: its depth, geometry and triangle;
/// geomID RTC_INVALID_GEOMETRY_ID when nothing is recorded (and always for midpoint capture, whose
/// record is the middle of two hits, no triangle's).
struct CapturedHit {
  float depth = DepthMap::kNoHit;
  unsigned geomID = RTC_INVALID_GEOMETRY_ID, primID = RTC_INVALID_GEOMETRY_ID;
};
CapturedHit captureHit(RTCScene scene, const TexelUnprojector::Ray& ray, float tNear, float tFar, CaptureMode mode);

}  // namespace shadowvol
