// A mesh check as JSON: what `validate` reports for its volume and `check` for a mesh file.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "shadowvol/cgal/mesh_check.h"

namespace shadowvol {

/// Every count of `m`, its verdicts (valid, closedManifold, outward) and its summary line;
/// `notApplicable` says which checks did not apply (null when empty).
nlohmann::json meshCheckJson(const MeshCheckReport& m, const std::string& notApplicable = "");

}  // namespace shadowvol
