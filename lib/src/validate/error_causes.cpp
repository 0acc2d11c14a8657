#include "shadowvol/validate/error_causes.h"

#include <algorithm>

#include <glm/vec2.hpp>

#include "shadowvol/check.h"
#include "shadowvol/embree/embree_depth_oracle.h"

namespace shadowvol {

bool inVolumeBorderBand(const glm::dvec2& texel, int width, int height) {
  return std::min(std::min(texel.x, texel.y), std::min(width - 1 - texel.x, height - 1 - texel.y)) < 1.0;
}

ErrorCauses splitErrorCauses(const Scene& scene, const DepthMap& map, double offset, const CameraHits& hits,
                             const std::vector<PixelClass>& exact, const std::vector<std::uint8_t>& methodShadowed,
                             bool volumeRing) {
  SV_CHECK_EQ(exact.size(), methodShadowed.size());
  SV_CHECK_EQ(exact.size(), hits.point.size());
  ErrorCauses causes;
  causes.offset = offset;
  std::vector<std::size_t> wrong;
  std::vector<glm::dvec2> ndc;
  std::vector<std::uint8_t> band;
  for (std::size_t k = 0; k < exact.size(); ++k) {
    if (exact[k] != PixelClass::Lit && exact[k] != PixelClass::Shadowed) continue;
    if ((exact[k] == PixelClass::Shadowed) == (methodShadowed[k] != 0)) continue;
    wrong.push_back(k);
    const glm::dvec2 texel = map.texelOf(hits.point[k]);
    ndc.push_back(map.texelNdc(texel.x, texel.y));
    // Only a missed shadow: the ring on the far plane lights the band, it shadows nothing. With a
    // guard band the strip is the light window's own (the band's texels lie outside it).
    const glm::dvec2 inWindow = texel - glm::dvec2(map.guard);
    band.push_back(volumeRing && exact[k] == PixelClass::Shadowed &&
                   inVolumeBorderBand(inWindow, map.width - 2 * map.guard, map.height - 2 * map.guard));
  }
  if (wrong.empty()) return causes;
  const EmbreeDepthOracle oracle(scene);
  std::vector<float> captured(wrong.size());
  oracle.oracle()(map, ndc, captured);
  for (std::size_t q = 0; q < wrong.size(); ++q) {
    const std::size_t k = wrong[q];
    const bool ideal =
        !DepthMap::isNoHit(captured[q]) && double(captured[q]) + offset < map.viewDepthOf(hits.point[k]);
    if (ideal != (exact[k] == PixelClass::Shadowed)) ++causes.capture;
    else ++(band[q] ? causes.border : causes.resolution);
  }
  return causes;
}

}  // namespace shadowvol
