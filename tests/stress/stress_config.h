// One configuration of the stress suite: a scene file, the category it stresses, what the judge
// expects of it (run normally, or be refused naming a field), and which twin it is compared with.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace shadowvol::stress {

/// The categories, in the order the table prints them.
inline const std::vector<std::string> kCategories = {
    "scale",      "offset",       "grazing", "spot-fov", "light-depth-range", "camera-depth-range", "camera-in-volume",
    "degenerate", "light-inside", "refused"};

/// How a twin comparison counts: required by the goal (offset), or reported only (scale, depth ranges).
enum class TwinRole { Required, Informational };

struct StressConfig {
  std::string name;       ///< unique and file-safe: the scene is OUT/scenes/<name>.json
  std::string category;   ///< one of kCategories
  std::string what;       ///< one line for the failure list
  nlohmann::json scene;   ///< the scene document (unused when `sceneText` is set)
  std::string sceneText;  ///< verbatim file text, for what JSON values cannot hold (1e400, NaN); empty = dump `scene`
  bool refused = false;   ///< must be refused: exit 1, a field of `fields` and the file named on stderr
  std::vector<std::string> fields;  ///< refused: any one of these must appear on stderr (JSON pointers)
  std::optional<std::string> twin;  ///< name of the configuration this one must reproduce (same picture)
  TwinRole twinRole = TwinRole::Informational;
  bool gpu = true;                ///< also validate with --volume gpu (legal configurations)
  bool front = false;             ///< also validate with --capture front
  bool refined = false;           ///< also validate with --refine 6 --refine-grid 4, with --refine 6
                                  ///< --crossings gpu-walk (explicit volume) and with --refine 6
                                  ///< --depth-from rays; a point light's with --refine 6 alone (its
                                  ///< cube volume takes rays only) and with --depth-from rays
  bool quick = false;             ///< part of the --quick subset (its twin is added automatically)
  std::optional<bool> eyeInside;  ///< where the geometry is clear: whether the eye lies in the shadow volume
};

/// A legal configuration with the defaults above.
inline StressConfig makeConfig(std::string category, std::string name, std::string what, nlohmann::json scene) {
  StressConfig c;
  c.category = std::move(category);
  c.name = std::move(name);
  c.what = std::move(what);
  c.scene = std::move(scene);
  return c;
}

}  // namespace shadowvol::stress
