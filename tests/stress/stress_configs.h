// The stress suite's configurations: deterministic parameter lists per category (no randomness).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "stress_config.h"

namespace shadowvol::stress {

/// Every configuration of the full suite (over 300), in category order; names are unique.
std::vector<StressConfig> generateConfigs();

/// Categories built in their own files (camera_in_volume_configs.cpp, degenerate_configs.cpp,
/// refused_configs.cpp); each appends to `out`.
void addCameraInVolume(std::vector<StressConfig>& out);
void addDegenerate(std::vector<StressConfig>& out);
void addLightInside(std::vector<StressConfig>& out);
void addRefused(std::vector<StressConfig>& out);

/// The configurations to run: those of `category` (all when empty), only the --quick subset when
/// `quick`, plus every twin a chosen one is compared with. A config run with --capture front makes
/// its twin run it too.
std::vector<StressConfig> selectConfigs(std::vector<StressConfig> all, bool quick,
                                        const std::optional<std::string>& category);

}  // namespace shadowvol::stress
