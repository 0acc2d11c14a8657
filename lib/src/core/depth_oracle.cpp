#include "shadowvol/depth_oracle.h"

#include <vector>

#include "shadowvol/check.h"

namespace shadowvol {

void fillFromOracle(DepthMap& map, const DepthOracle& oracle) {
  SV_CHECK(bool(oracle));
  SV_CHECK_EQ(map.depth.size(), std::size_t(map.width) * std::size_t(map.height));
  std::vector<glm::dvec2> ndc(map.depth.size());
  for (int j = 0; j < map.height; ++j)
    for (int i = 0; i < map.width; ++i) ndc[map.index(i, j)] = map.texelNdc(double(i), double(j));
  oracle(map, ndc, map.depth);
}

}  // namespace shadowvol
