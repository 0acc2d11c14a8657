#include "volume/subgrid_bias.h"

#include <algorithm>

#include "volume/sheet_depths.h"

namespace shadowvol::volume {

double subCellBias(const std::array<double, 4>& corners, double centre, const std::function<double()>& foldBound,
                   double bias, int subdivisions, bool perspective, double farPlane) {
  if (centre == farPlane) return bias;
  for (double d : corners)
    if (d == farPlane) return bias;
  const double sheet = std::min(depthAlongEdge(corners[0], corners[2], 0.5, perspective),
                                depthAlongEdge(corners[1], corners[3], 0.5, perspective));
  const double behind = centre - sheet;
  if (behind > 2.0 * bias) return bias;
  const double floor = kSubgridBiasFloor * bias / subdivisions;
  if (behind <= 0.0) return floor;
  if (behind + floor >= bias) return bias;  // the bound cannot lower it
  return std::min(std::min(2.0 * behind, std::max(behind, foldBound())) + floor, bias);
}

}  // namespace shadowvol::volume
