// The JSON descriptions every report shares (the command line's --json output, validate's
// report.json, the Python module's dictionaries): one place, so the field names stay the same.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "shadowvol/scene.h"
#include "shadowvol/volume_builder.h"

namespace shadowvol {

/// The scene as used: source, object and triangle counts, local origin (Scene::origin), bounds,
/// light (the first) and camera with their fitted near/far, and with several lights `lights`, one
/// such description per light in order; positions in world units (stored + origin).
nlohmann::json describeScene(const Scene& scene);

/// A volume build's counts and times (VolumeBuildStats; the times in milliseconds under "ms").
nlohmann::json describeVolumeStats(const VolumeBuildStats& s);

/// How a point light's dual-paraboloid maps for a cube face side of `cubeFaceSide` spend their
/// texels beside the cube map of that side (dual_paraboloid.h): each one's texel count, the
/// fraction in use, the solid angles (sr) of its smallest and largest texel and their ratio, and
/// the ratio of the two maps' largest texels (paraboloid over cube).
nlohmann::json describeDualParaboloid(int cubeFaceSide);

/// `j` as text with `indent` (-1: one line): a byte that is not UTF-8 (a file name in another
/// encoding) becomes U+FFFD instead of an exception (a twenty-second probe's Latin-1 file name
/// ended build --json with an internal error after its mesh was written).
std::string jsonText(const nlohmann::json& j, int indent = 2);

}  // namespace shadowvol
