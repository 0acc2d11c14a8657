// Error of a shadow test against the exact shadows, for the sweep (issue 6).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "shadowvol/distance_transform.h"
#include "shadowvol/embree/ray_queries.h"

namespace shadowvol {

struct ShadowErrorMetrics {
  std::size_t pixels = 0;        ///< pixels compared: exact class Lit or Shadowed
  std::size_t leak = 0;          ///< exact shadowed, test lit
  std::size_t acne = 0;          ///< exact lit, test shadowed
  std::size_t bandPixels = 0;    ///< compared pixels within `band` pixels of the exact boundary
  std::size_t bandLeak = 0, bandAcne = 0;
  std::optional<double> distMean, distP99, distMax;  ///< of misclassified pixels, image pixels
};

/// Compares a shadow test (1 = shadowed; image order, w x h) with the exact classes. The exact
/// boundary runs between 4- or 8-neighbouring compared pixels of opposite exact state; a pixel's
/// distance from it is its Euclidean distance (exact transform, pixel centres) to the nearest
/// compared pixel of the opposite exact state, minus half a pixel, so a pixel next to the boundary
/// is 0.5 from it. The band holds the compared pixels at distance <= band. Without pixels of one of
/// the two states there is no boundary: every distance is unset and the band is empty.
/// p99 is the nearest-rank 99th percentile.
ShadowErrorMetrics measureShadowError(int width, int height, const std::vector<PixelClass>& exact,
                                      const std::vector<std::uint8_t>& testShadowed, double band);


}  // namespace shadowvol
