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

/// Refuses (InputError: `source`, `field`, the path) a depth map's output path whose extension is
/// not .pfm in any case (.PFM too, as the mesh formats' extensions): a PFM named x.png would
/// mislead every reader. The command line's `depth --out` and the Python module's DepthMap.save.
void checkDepthMapPath(const std::filesystem::path& pfm, const std::string& source, const std::string& field);

/// Reads a PFM and its side file; throws InputError naming the file and field on bad input.
/// The checks are the two below.
DepthMap readDepthMap(const std::filesystem::path& pfm);

/// Refuses (InputError naming `source`, the texel and the value) depths that are NaN or negative
/// (+inf is kNoHit), and a depth vector whose size is not width x height.
void checkDepthValues(const DepthMap& map, const std::string& source);

/// What checkDepthMapLight calls the map's fields: a side file's JSON pointers, the DepthMap
/// struct's members (buildVolume's checks) or, given by the Python module itself, the keywords of
/// DepthMap.from_array.
struct DepthMapFieldNames {
  const char* size;
  const char* nearPlane;
  const char* farPlane;
  const char* lightView;
  const char* lightProjection;
  const char* lightType;
  const char* origin;
};
inline constexpr DepthMapFieldNames kSideFileFields{"/width", "/near", "/far", "/lightView", "/lightProjection", "/light",
                                                    "/origin"};
inline constexpr DepthMapFieldNames kDepthMapMembers{"width x height", "nearPlane", "farPlane", "lightView",
                                                     "lightProjection", "lightType", "origin"};

/// Refuses a light that the volume cannot be built from: size below 2 x 2, a point light (a map is
/// one spot or directional view; a point light's six faces are a CubeDepthMap), near/far not finite
/// or not 0 <= near < far < 1e30 (near > 0 for a spot light), a view that is not rigid, a
/// projection not of the light's kind (perspective for spot, orthographic for directional) or not
/// mapping near and far to NDC z -1 and +1, window corners not finite in world space, or an origin
/// not finite within +-1e12 (a scene's range). Fields named by `names`.
/// `mixedAxes`: allow a projection that mixes light-view x and y into clip x and y (a rotated
/// window), which the CPU builder unprojects with the whole matrix (buildVolume's check) but a
/// depth file does not hold (the GPU's volume reads the axis-aligned entries only).
void checkDepthMapLight(const DepthMap& map, const std::string& source,
                        const DepthMapFieldNames& names = kSideFileFields, bool mixedAxes = false);

/// A 4 x 4 matrix as text, columns as listed in a side file ([[c0], [c1], [c2], [c3]]), every
/// number as numberText writes it (so NaN and infinities show as such).
std::string matrixText(const glm::dmat4& m);

}  // namespace shadowvol
