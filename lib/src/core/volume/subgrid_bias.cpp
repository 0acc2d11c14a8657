#include "volume/subgrid_bias.h"

#include <algorithm>

#include "volume/sheet_depths.h"

namespace shadowvol::volume {

double subCellBias(const std::array<double, 4>& corners, double centre, double bias, int subdivisions, bool perspective,
                   double farPlane) {
  if (centre == farPlane) return bias;
  for (double d : corners)
    if (d == farPlane) return bias;
  const double sheet = std::min(depthAlongEdge(corners[0], corners[2], 0.5, perspective),
                                depthAlongEdge(corners[1], corners[3], 0.5, perspective));
  const double behind = centre - sheet;
  if (behind > 2.0 * bias) return bias;
  const double floor = kSubgridBiasFloor * bias / subdivisions;
  return std::clamp(behind + floor, floor, bias);
}

}  // namespace shadowvol::volume
