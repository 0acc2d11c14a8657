// Depth-map files: a little-endian PFM ("Pf", one float channel, rows bottom to top as PFM
// specifies, which is exactly DepthMap's row order) with kNoHit written as +infinity, and a JSON
// side file "<name>.pfm.json" holding the light type, matrices (column-major, as GLM stores them),
// near/far and capture mode. Both are written to temporary names and renamed at the end.
#pragma once

#include <filesystem>

#include "shadowvol/depth_map.h"

namespace shadowvol {

/// Path of the JSON side file of a PFM: "D.pfm" -> "D.pfm.json".
std::filesystem::path depthSidecarPath(const std::filesystem::path& pfm);

void writeDepthMap(const DepthMap& map, const std::filesystem::path& pfm);

/// Reads a PFM and its side file; throws InputError naming the file and field on bad input.
DepthMap readDepthMap(const std::filesystem::path& pfm);

}  // namespace shadowvol
