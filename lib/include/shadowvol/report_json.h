// The JSON descriptions every report shares (the command line's --json output, validate's
// report.json, the Python module's dictionaries): one place, so the field names stay the same.
#pragma once

#include <nlohmann/json.hpp>

#include "shadowvol/scene.h"
#include "shadowvol/volume_builder.h"

namespace shadowvol {

/// The scene as used: source, object and triangle counts, local origin (Scene::origin), bounds,
/// light and camera with their fitted near/far; positions in world units (stored + origin).
nlohmann::json describeScene(const Scene& scene);

/// A volume build's counts and times (VolumeBuildStats; the times in milliseconds under "ms").
nlohmann::json describeVolumeStats(const VolumeBuildStats& s);

}  // namespace shadowvol
