// The rules every JSON input of shadowvol is read by (scene files, depth maps' side files): no NUL
// byte, nesting at most 64 deep, no key twice in one object, and numbers within double's range,
// each refused as an InputError that names the source and, where it has one, the line and column.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace shadowvol {

/// The JSON document of `text`, read from `source` (named in errors), or InputError.
nlohmann::json parseJsonText(const std::string& text, const std::string& source);

}  // namespace shadowvol
