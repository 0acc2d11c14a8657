// The accuracy verdict's per-occluder criterion: each object's shadow is judged on its own (a
// twenty-third probe's finding: a rod's thin shadow, 85 % missed, passed beside a sphere's large
// one, which diluted the frame's missed share, and on its own when under the 100 pixels that share
// needs; a shadow thinner than the method's texels has no pixel deep enough for the leak criterion).
//
// Every exactly shadowed pixel is attributed to its occluder: the object its exact shadow ray meets
// first (exactShadows' occluders). An object whose shadow covers at least kMinOccluderPixels
// pixels of the image is judged: the method may miss at most ValidationOptions::maxMissedShare of
// them. A shadow lost whole (an occluder thinner than a texel, which no sample sees) fails; a large
// object's self-shadows are judged with the rest of its shadow.
//
// Where the missed pixels lie is counted too: on the occluding object itself (a self-shadow: one
// part of a mesh shadowing another, which a depth map's sheet must follow between its texel
// centres and within its bias, and a silhouette volume gets from the mesh) or on another object
// (a cast shadow's outline on a receiver). On issue 10's closed-mesh scenes at 256² most of the
// refined volume's missed pixels are self-shadows (docs/results/error-places).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "shadowvol/embree/ray_queries.h"

namespace shadowvol {

/// A smaller shadow is not judged on its own. Below the frame's kMinShadowPixels (100) on purpose:
/// a lost line of shadow (the probe's rod at 180 x 135: 96 pixels) is that small, while 32 pixels
/// are more than the outline a few texels of a shadow's edge give at the image sizes validated.
inline constexpr std::size_t kMinOccluderPixels = 32;

struct OccluderShadow {
  std::uint32_t object = 0;  ///< the occluding object's index in the scene
  std::size_t pixels = 0;    ///< exactly shadowed pixels it occludes first
  std::size_t missed = 0;    ///< of which the method calls lit
  std::size_t missedSelf = 0;  ///< of the missed, those on the occluding object itself (self-shadows)
  std::size_t first = 0;     ///< the first of them in row order (row 0 at the top)
  std::string name;          ///< the object's name, where the caller knows it (frame validation does)
};

struct LostShadows {
  std::size_t occluders = 0;             ///< objects that shadow some pixel
  std::size_t judged = 0;                ///< of which shadow at least kMinOccluderPixels
  std::optional<OccluderShadow> worst;   ///< the judged one with the largest missed share (ties: lower index)
  std::size_t missedSelf = 0;            ///< missed pixels on the object that occludes them, all occluders
  std::size_t missedOnOthers = 0;        ///< missed pixels on another object than their occluder
};

/// Groups the exactly shadowed pixels by `occluders` (per pixel, kNoOccluder where none) and finds
/// the worst judged group; `receivers` (per pixel, the object the pixel's surface belongs to, as
/// CameraHits::Triangle::geomID) splits the missed pixels into self-shadows and the others.
LostShadows findLostShadows(const std::vector<PixelClass>& exact, const std::vector<std::uint8_t>& methodShadowed,
                            const std::vector<std::uint32_t>& occluders, const std::vector<std::uint32_t>& receivers);

}  // namespace shadowvol
