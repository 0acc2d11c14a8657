#include "mesh_readers/number_text.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <string>

namespace shadowvol::mesh_readers {
namespace {

// std::from_chars refuses a leading '+', which some writers emit; it may only precede a digit or
// a '.' (so "+-1" and "+nan" stay refused).
std::string_view withoutPlus(std::string_view t) {
  if (t.size() > 1 && t[0] == '+' && (t[1] == '.' || (t[1] >= '0' && t[1] <= '9'))) t.remove_prefix(1);
  return t;
}

}  // namespace

std::optional<double> parseReal(std::string_view token) {
  token = withoutPlus(token);
  double v = 0;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), v);
  if (token.empty() || end != token.data() + token.size()) return std::nullopt;
  if (ec == std::errc::result_out_of_range) {
    // A well-formed number beyond double: "1e-400" underflows to zero, "1e400" to infinity (which
    // storedPoint then refuses, naming the value).
    const std::size_t e = token.find_first_of("eE");
    const bool tiny = e != std::string_view::npos && e + 1 < token.size() && token[e + 1] == '-';
    const double magnitude = tiny ? 0.0 : std::numeric_limits<double>::infinity();
    return token[0] == '-' ? -magnitude : magnitude;
  }
  if (ec != std::errc()) return std::nullopt;
  return v;
}

std::optional<std::int64_t> parseInteger(std::string_view token) {
  token = withoutPlus(token);
  std::int64_t v = 0;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), v);
  if (ec != std::errc() || end != token.data() + token.size() || token.empty()) return std::nullopt;
  return v;
}

const char* integerProblem(std::string_view token) {
  if (!token.empty() && (token[0] == '-' || token[0] == '+')) token.remove_prefix(1);
  const bool digits =
      !token.empty() && std::all_of(token.begin(), token.end(), [](char c) { return c >= '0' && c <= '9'; });
  return digits ? "is out of range" : "is not an integer";
}

std::optional<glm::dvec3> checkedPoint(double x, double y, double z) {
  constexpr double kMax = std::numeric_limits<float>::max();
  for (const double c : {x, y, z})
    if (!std::isfinite(c) || std::abs(c) > kMax) return std::nullopt;
  return glm::dvec3(x, y, z);
}

glm::dvec3 readPoint(std::string_view& rest, const TextPlace& at) {
  double c[3];
  for (int k = 0; k < 3; ++k) {
    const std::string_view token = nextToken(rest);
    if (token.empty()) at.fail("a vertex needs three coordinates, the line has " + std::to_string(k));
    const auto v = parseReal(token);
    if (!v) at.fail("coordinate " + quoted(token) + " is not a number");
    if (!std::isfinite(*v)) at.fail("non-finite vertex coordinate " + quoted(token));
    if (std::abs(*v) > std::numeric_limits<float>::max())
      at.fail("vertex coordinate " + quoted(token) + " is beyond single precision (meshes are stored in float)");
    c[k] = *v;
  }
  return glm::dvec3(c[0], c[1], c[2]);
}

}  // namespace shadowvol::mesh_readers
