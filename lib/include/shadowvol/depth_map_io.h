// Depth-map files: a little-endian PFM ("Pf", one float channel, rows bottom to top as PFM
// specifies, which is exactly DepthMap's row order) with kNoHit written as +infinity, and a JSON
// side file "<name>.pfm.json" holding the light type, matrices (column-major, as GLM stores them),
// near/far and capture mode. Both are written to temporary names and renamed at the end.
#pragma once

#include <filesystem>
#include <string>

#include "shadowvol/depth_map.h"

namespace shadowvol {

/// Path of the JSON side file of a PFM: "D.pfm" -> "D.pfm.json".
std::filesystem::path depthSidecarPath(const std::filesystem::path& pfm);

void writeDepthMap(const DepthMap& map, const std::filesystem::path& pfm);

/// Reads a PFM and its side file; throws InputError naming the file and field on bad input.
/// The checks are the two below.
DepthMap readDepthMap(const std::filesystem::path& pfm);

/// Refuses (InputError naming `source`, the texel and the value) depths that are NaN or negative
/// (+inf is kNoHit), and a depth vector whose size is not width x height.
void checkDepthValues(const DepthMap& map, const std::string& source);

/// Refuses a light that the volume cannot be built from: size below 2 x 2, near/far not finite or
/// not 0 <= near < far < 1e30 (near > 0 for a spot light), a view that is not rigid, a projection
/// not of the light's kind (perspective for spot, orthographic for directional) or not mapping
/// near and far to NDC z -1 and +1, or window corners not finite in world space. The field is
/// named as in the side file ("/near", "/lightView", "/lightProjection").
void checkDepthMapLight(const DepthMap& map, const std::string& source);

}  // namespace shadowvol
