#include "shadowvol/depth_oracle.h"

#include <algorithm>
#include <vector>

#include "shadowvol/check.h"

namespace shadowvol {

namespace {
// Texels per oracle call: large enough to keep a parallel oracle busy, small enough that the
// batch's points (16 bytes a texel) stay a fraction of the map itself.
constexpr std::size_t kTexelsPerBatch = std::size_t(1) << 16;
}  // namespace

void fillFromOracle(DepthMap& map, const DepthOracle& oracle) {
  SV_CHECK(bool(oracle));
  SV_CHECK_EQ(map.depth.size(), std::size_t(map.width) * std::size_t(map.height));
  const int rows = int(std::max<std::size_t>(1, kTexelsPerBatch / std::size_t(std::max(map.width, 1))));
  std::vector<glm::dvec2> ndc;
  for (int j0 = 0; j0 < map.height; j0 += rows) {
    const int j1 = std::min(map.height, j0 + rows);
    ndc.clear();
    for (int j = j0; j < j1; ++j)
      for (int i = 0; i < map.width; ++i) ndc.push_back(map.texelNdc(double(i), double(j)));
    oracle(map, ndc, std::span<float>(map.depth).subspan(map.index(0, j0), ndc.size()));
  }
}

}  // namespace shadowvol
