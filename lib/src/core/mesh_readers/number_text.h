// Numbers in the text of a mesh file: whole tokens only ("1.5x" is not a number), in the C locale.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include <glm/vec3.hpp>

#include "mesh_readers/text_lines.h"

namespace shadowvol::mesh_readers {

/// A decimal real ("-1.5e3", "+2", ".5"; also "nan", "inf", and "1e400" as infinity, which the
/// callers refuse through storedPoint; "1e-400" is 0), or nullopt when the token is not a number.
std::optional<double> parseReal(std::string_view token);

/// A decimal integer with an optional sign, or nullopt when the token is not one or does not fit
/// in 64 bits.
std::optional<std::int64_t> parseInteger(std::string_view token);

/// Why parseInteger refused `token`: "is out of range" for digits beyond 64 bits, else "is not an
/// integer".
const char* integerProblem(std::string_view token);

/// (x, y, z), or nullopt when a coordinate is non-finite or beyond the float range (the mesh is
/// stored in float, where it would become infinite).
std::optional<glm::dvec3> checkedPoint(double x, double y, double z);

/// The first three tokens of `rest` (removed from it) as a point, in double. Fails at `at` naming
/// the token when there are fewer than three, one is not a number, non-finite, or beyond float.
glm::dvec3 readPoint(std::string_view& rest, const TextPlace& at);

}  // namespace shadowvol::mesh_readers
