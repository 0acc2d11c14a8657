// The accuracy verdict's leak criterion: a shadow the method misses where its resolution cannot
// explain it (a probe's finding: a camera whose near plane cut a closed occluder showed its inside
// lit, 11.5 % of the exact shadow missed in one solid patch, and passed the share thresholds).
//
// A depth-map method errs within a few texels of a shadow's outline: texel sampling, the sheet's
// interpolation, filtering, its bias. A missed pixel (exact: shadowed, method: lit) is *deep* when
// every pixel within its allowance of it is exactly shadowed too: it lies inside the exact shadow,
// further from its outline than the method's texels reach. Its allowance, in image pixels:
//
//   kLeakTexels x F / max(|N . L|, kLeakMinCos) / P + kLeakPixels
//
// with F the light's texel width at the pixel's surface point (the map's TexelFootprint; a point
// light's cube face: 2 d / N at cube depth d), stretched along a surface tilted from the light by
// 1 / N . L (capped), and P the width of an image pixel at the point's camera depth. An exact
// method (silhouette volumes) has F = 0. The outline is taken generously, so that a shadow's edge
// hidden from the camera cannot make a pixel look deep: every pixel that is not exactly shadowed
// (lit, background, facing away, outside the light), every pixel on the image's border and every
// pixel beside a jump in the camera's view (another object, or a camera depth changing by more than
// kLeakDepthJump) counts as outline. A shadow missed at the light's frustum border (the map's outer
// ring lies on the far plane: README "Known limits") borders pixels outside the light and is not
// deep. The verdict fails when more than kMaxLeakPixels pixels are deep.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "shadowvol/depth_map.h"
#include "shadowvol/embree/ray_queries.h"
#include "shadowvol/scene.h"

namespace shadowvol {

inline constexpr double kLeakTexels = 3.0;       ///< texels of the method's reach beyond an outline
inline constexpr double kLeakPixels = 2.0;       ///< image pixels more: the image's own sampling
inline constexpr double kLeakMinCos = 0.05;      ///< N . L floor: at most 20 times the texel along a grazing surface
inline constexpr double kLeakDepthJump = 0.02;   ///< relative camera-depth change that is a jump in the view
inline constexpr std::size_t kMaxLeakPixels = 16;  ///< deep pixels tolerated (isolated round-off)

/// How the method's texels are sized: a depth map of a spot or directional light (`map`), a point
/// light's cube faces of `cubeSide` texels, or none (an exact method: no texel allowance).
struct LeakTexels {
  const DepthMap* map = nullptr;
  int cubeSide = 0;
};

/// The deep missed pixels of a frame (see above): their count, and the first ones found (row-major
/// image indices, at most 16) for the report.
struct ShadowLeaks {
  std::size_t deep = 0;
  std::vector<std::size_t> firstDeep;
};

ShadowLeaks findShadowLeaks(const Scene& scene, const LeakTexels& texels, const CameraHits& hits,
                            const std::vector<PixelClass>& exact, const std::vector<std::uint8_t>& methodShadowed);

}  // namespace shadowvol
