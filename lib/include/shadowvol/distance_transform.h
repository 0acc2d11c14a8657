// Squared Euclidean distance transform of a grid (Felzenszwalb and Huttenlocher's lower envelope
// of parabolas, exact, linear time): the sweep's distances of wrong pixels from the exact shadow's
// outline (bench/shadow_error.h) and the validation's leak criterion (validate/shadow_leaks.h).
#pragma once

#include <cstdint>
#include <vector>

namespace shadowvol {

/// Squared Euclidean distance transform on a w x h grid (image order): for every cell, the squared
/// distance in cells to the nearest cell with site[k] != 0; +inf where there is no site at all.
std::vector<double> squaredDistanceTransform(int width, int height, const std::vector<std::uint8_t>& site);

}  // namespace shadowvol
