#include "mesh_readers/obj_reader.h"

#include <cstdint>
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

// First pass: how many `v` statements the file has. A positive index may name a vertex defined
// after its face (as other OBJ readers allow), so indices are checked against this count.
std::size_t countVertices(std::string_view text) {
  LineReader lines(text);
  std::size_t n = 0;
  while (const auto line = lines.next()) {
    std::string_view rest = withoutComment(*line);
    if (nextToken(rest) == "v") ++n;
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
  const std::size_t total = countVertices(text);  // at most one per 2 bytes, so reserving is safe
  if (total > std::numeric_limits<std::uint32_t>::max())
    throw InputError(source, "", std::to_string(total), "more vertices than 32-bit indices can address");
  ParsedMesh mesh;
  mesh.positions.reserve(total);
  LineReader lines(text);
  while (const auto line = lines.next()) {
    const TextPlace at{source, lines.number(), *line};
    std::string_view rest = withoutComment(*line);
    const std::string_view keyword = nextToken(rest);
    if (keyword == "v") {
      mesh.positions.push_back(readPoint(rest, at));
    } else if (keyword == "f") {
      appendPolygon(faceCorners(rest, mesh.positions.size(), total, at), mesh);
    }
  }
  return mesh;
}

}  // namespace shadowvol::mesh_readers
