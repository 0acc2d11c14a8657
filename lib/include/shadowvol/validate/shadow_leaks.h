// The accuracy verdict's leak criterion: a shadow the method misses where its resolution cannot
// explain it (a probe's finding: a camera whose near plane cut a closed occluder showed its inside
// lit, 11.5 % of the exact shadow missed in one solid patch, and passed the share thresholds).
//
// A depth-map method errs within a few texels of a shadow's outline (texel sampling, the sheet's
// interpolation, filtering), and its depth offset moves the outline too: a shadow map's bias, the
// volume's bias and blur offset push the start of a contact shadow along the receiver. A missed
// pixel (exact: shadowed, method: lit) is *deep* when every pixel within its allowance of it is
// exactly shadowed too: it lies inside the exact shadow, further from its outline than the
// method's texels and offset reach. Its allowance along the surface, in world units:
//
//   kLeakTexels x F / max(N . L, kLeakMinCos) + B / max(sin a, kLeakMinCos),
//   B = offset + slope x F x min(tan a, 10)
//
// with F the light's texel width at the pixel's surface point (the map's TexelFootprint; a point
// light's cube face: 2 d / N at cube depth d), N . L against the ray to the light, a the angle
// between the normal and the light's view axis (a point light's: its cube face's), B the method's
// depth offset along that axis (scene.frag's shadow-map bias; the volume's bias and blur offset);
// moving s along a surface tilted by a changes that depth by s sin a. It is converted to image
// pixels by the width an image pixel covers at the point (pixelPerDepth x z^2 / r at camera depth z
// and distance r, the least over the image), plus kLeakPixels. An exact method (silhouette volumes)
// has F = B = 0. The outline is taken generously, so that a shadow's edge hidden from the camera
// cannot make a pixel look deep: every pixel that is not exactly shadowed (lit, background, facing
// away, outside the light), every pixel on the image's border and every pixel beside a jump in the
// camera's view (another object, or a camera depth changing by more than kLeakDepthJump) counts as
// outline. A shadow missed at the light's frustum border (the map's outer ring lies on the far
// plane: README "Volume mesh") borders pixels outside the light and is not deep. The verdict fails
// when more than kMaxLeakPixels pixels are deep.
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

/// How far the method may stray: its texels (a depth map of a spot or directional light, `map`; a
/// point light's cube faces of `cubeSide` texels; neither: an exact method) and its depth offset
/// (`offset` world units plus `slope` texel widths x min(tan a, 10); see above).
struct LeakTexels {
  const DepthMap* map = nullptr;
  int cubeSide = 0;
  double offset = 0.0;
  double slope = 0.0;
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
