#include "mesh_readers/obj_reader.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <limits>
#include <vector>

#include "mesh_readers/number_text.h"
#include "mesh_readers/polygon_fan.h"
#include "mesh_readers/text_lines.h"
#include "shadowvol/error.h"

// Why our own reader rather than OpenMesh's: OpenMesh 9 aborts on `f / / /` (an assertion), skips a
// `nan` vertex so that later indices shift onto the wrong vertices, and drops faces with an index
// of 0, out of range, or fewer than three corners without a word. This one names the line.

namespace shadowvol::mesh_readers {
namespace {

// The statements of the OBJ format (Wavefront's specification, version 3.0): any other first
// token on every line means the file is not OBJ.
bool isObjKeyword(std::string_view k) {
  static const std::array<std::string_view, 37> kKeywords = {
      "v", "vt", "vn", "vp", "cstype", "deg", "bmat", "step", "f", "l", "p", "curv", "curv2", "surf", "parm",
      "trim", "hole", "scrv", "sp", "end", "con", "g", "s", "mg", "o", "bevel", "c_interp", "d_interp", "lod",
      "usemtl", "mtllib", "shadow_obj", "trace_obj", "ctech", "stech", "maplib", "usemap"};
  return std::find(kKeywords.begin(), kKeywords.end(), k) != kKeywords.end() || k == "call" || k == "csh";
}

// A statement continued on the next line: its last non-blank character is a backslash.
bool endsWithContinuation(std::string_view s) {
  const std::size_t end = s.find_last_not_of(" \t\r\v\f");
  return end != std::string_view::npos && s[end] == '\\';
}

// `first` and the lines that continue it, each backslash replaced by a blank, in `joined`.
std::string_view joinContinuedLines(std::string_view first, LineReader& lines, std::string& joined) {
  joined.assign(first);
  while (endsWithContinuation(joined)) {
    joined[joined.find_last_not_of(" \t\r\v\f")] = ' ';
    const auto next = lines.next();
    if (!next) break;
    joined += ' ';
    joined += withoutComment(*next);
  }
  return joined;
}

// First pass: how many `v` statements the file has, statements continued over several lines
// counted once by their first (as the second pass reads them: joinContinuedLines). A positive
// index may name a vertex defined after its face (as other OBJ readers allow), so indices are
// checked against this count.
std::size_t countVertices(std::string_view text) {
  LineReader lines(text);
  std::size_t n = 0;
  while (const auto line = lines.next()) {
    std::string_view rest = withoutComment(*line);
    bool continued = endsWithContinuation(rest);
    if (nextToken(rest) == "v") ++n;
    while (continued) {
      const auto next = lines.next();
      if (!next) break;
      continued = endsWithContinuation(withoutComment(*next));
    }
  }
  return n;
}

// The 0-based vertex of one corner token ("7", "7/2", "7/2/5", "7//5", "-1"); `before` vertices
// precede the line and the file has `total`.
std::uint32_t cornerVertex(std::string_view token, std::size_t before, std::size_t total, const TextPlace& at) {
  const std::string_view text = token.substr(0, token.find('/'));
  if (text.empty()) at.fail("face corner " + quoted(token) + " has no vertex index");
  const auto index = parseInteger(text);
  if (!index) at.fail("vertex index " + quoted(text) + " " + integerProblem(text));
  if (*index == 0) at.fail("vertex index 0 is invalid (OBJ indices start at 1; negative ones count back)");
  if (*index > 0) {
    if (std::uint64_t(*index) > total)
      at.fail("vertex index " + std::to_string(*index) + " is out of range (the file has " + std::to_string(total) +
              " vertices)");
    return std::uint32_t(*index - 1);
  }
  if (*index < -std::int64_t(before))
    at.fail("relative vertex index " + std::to_string(*index) + " reaches before the first vertex (" +
            std::to_string(before) + " vertices precede this line)");
  return std::uint32_t(std::int64_t(before) + *index);
}

std::vector<std::uint32_t> faceCorners(std::string_view rest, std::size_t before, std::size_t total,
                                       const TextPlace& at) {
  std::vector<std::uint32_t> corners;
  for (std::string_view token = nextToken(rest); !token.empty(); token = nextToken(rest))
    corners.push_back(cornerVertex(token, before, total, at));
  if (corners.size() < 3) at.fail("a face needs at least 3 vertices, this one has " + std::to_string(corners.size()));
  return corners;
}

}  // namespace

ParsedMesh readObj(const std::string& source, std::string_view text) {
  refuseUtf16(text, source);
  const std::size_t total = countVertices(text);  // at most one per 2 bytes, so reserving is safe
  if (total > std::numeric_limits<std::uint32_t>::max())
    throw InputError(source, "", std::to_string(total), "more vertices than 32-bit indices can address");
  ParsedMesh mesh;
  mesh.positions.reserve(total);
  LineReader lines(text);
  bool objStatement = false;                                    // any statement of the OBJ format at all
  std::optional<std::pair<std::size_t, std::string>> firstUnknown;  // the first line that is none
  std::string joined;
  while (const auto line = lines.next()) {
    std::string_view statement = withoutComment(*line);
    const std::size_t number = lines.number();
    const bool continued = endsWithContinuation(statement);
    if (continued) statement = joinContinuedLines(statement, lines, joined);
    const TextPlace at{source, number, continued ? statement : *line};
    std::string_view rest = statement;
    const std::string_view keyword = nextToken(rest);
    if (keyword == "v") {
      mesh.positions.push_back(readPoint(rest, at));
    } else if (keyword == "f") {
      appendPolygon(faceCorners(rest, mesh.positions.size(), total, at), mesh);
    }
    if (isObjKeyword(keyword)) objStatement = true;
    else if (!keyword.empty() && !firstUnknown) firstUnknown.emplace(number, std::string(at.text));
  }
  if (!objStatement && firstUnknown)  // text that is not OBJ at all (it read as an empty mesh)
    TextPlace{source, firstUnknown->first, firstUnknown->second}.fail(
        "not an OBJ statement, and the file has none: it is not an OBJ file");
  return mesh;
}

}  // namespace shadowvol::mesh_readers
