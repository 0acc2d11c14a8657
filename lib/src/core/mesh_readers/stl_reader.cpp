#include "mesh_readers/stl_reader.h"

#include <bit>
#include <cctype>
#include <string>
#include <cstdint>
#include <cstring>
#include <limits>

#include "mesh_readers/corner_welder.h"
#include "mesh_readers/number_text.h"
#include "mesh_readers/text_lines.h"
#include "shadowvol/error.h"

// Why our own reader rather than OpenMesh's: OpenMesh 9 welds the corners into its half-edge
// kernel and skips every triangle whose welded corners are not distinct. On spider.stl
// (assimp-testmodels) that lost 56 of 1,368 triangles (two or three corners at identical
// positions), and 6 more on complex edges were kept only by duplicating their vertices. A soup
// keeps them all.

namespace shadowvol::mesh_readers {
namespace {

constexpr std::size_t kBinaryHeader = 84, kBinaryTriangle = 50;

// A triangle's corner, welded with the corners before it at bit-identical double positions (and
// again once stored in float: ParsedMesh::weldCorners), so a soup of corners is never held.
std::uint32_t cornerOf(const glm::dvec3& p, CornerWelder<glm::dvec3>& weld, const ParsedMesh& mesh,
                       const std::string& source) {
  if (mesh.positions.size() >= std::numeric_limits<std::uint32_t>::max())
    throw InputError(source, "", std::to_string(mesh.positions.size()), "more vertices than 32-bit indices can address");
  return weld.vertex(p);
}

ParsedMesh readBinary(const std::string& source, std::string_view bytes, std::uint32_t count) {
  static_assert(std::endian::native == std::endian::little, "the STL reader assumes a little-endian host");
  ParsedMesh mesh;
  mesh.weldCorners = true;
  CornerWelder<glm::dvec3> weld(mesh.positions);
  mesh.triangles.reserve(count);  // the size was checked: 50 bytes per triangle
  for (std::uint32_t t = 0; t < count; ++t) {
    float v[12];  // normal, then three corners
    std::memcpy(v, bytes.data() + kBinaryHeader + kBinaryTriangle * std::size_t(t), sizeof v);
    std::array<std::uint32_t, 3> tri{};
    for (int c = 0; c < 3; ++c) {
      const auto p = checkedPoint(v[3 + 3 * c], v[4 + 3 * c], v[5 + 3 * c]);
      if (!p)
        throw InputError(
            source, "triangle " + std::to_string(t),
            numberText(v[3 + 3 * c]) + " " + numberText(v[4 + 3 * c]) + " " + numberText(v[5 + 3 * c]),
            "non-finite vertex coordinate");
      tri[c] = cornerOf(*p, weld, mesh, source);
    }
    mesh.triangles.push_back(tri);
  }
  mesh.floatPlacement = FloatPlacement::of(mesh.positions);
  return mesh;
}

// ASCII STL, one statement per line; `facet` ... `endfacet` must hold one loop of 3 vertices.
ParsedMesh readAscii(const std::string& source, std::string_view text) {
  ParsedMesh mesh;
  mesh.weldCorners = true;
  CornerWelder<glm::dvec3> weld(mesh.positions);
  LineReader lines(text);
  std::array<std::uint32_t, 3> tri{};
  int corners = -1;  // -1 outside a loop, else the vertices read in it
  bool inFacet = false;
  while (const auto line = lines.next()) {
    const TextPlace at{source, lines.number(), *line};
    std::string_view rest = *line;
    const std::string_view token = nextToken(rest);
    const std::string keyword = lowerCase(token);  // SOLID, FACET... as some exporters write them
    if (keyword.empty() || keyword == "solid" || keyword == "endsolid") {
      if (inFacet && !keyword.empty()) at.fail("a solid ends inside a facet");
    } else if (keyword == "facet") {
      if (inFacet) at.fail("a facet begins inside a facet");
      inFacet = true;
    } else if (keyword == "outer") {
      if (!inFacet || corners >= 0) at.fail("\"outer loop\" outside a facet or inside a loop");
      corners = 0;
    } else if (keyword == "vertex") {
      if (corners < 0) at.fail("a vertex outside \"outer loop\"");
      if (corners == 3) at.fail("a facet with more than 3 vertices (STL holds triangles)");
      tri[corners++] = cornerOf(readPoint(rest, at), weld, mesh, source);
    } else if (keyword == "endloop") {
      if (corners != 3)
        at.fail("a loop of " + std::to_string(std::max(corners, 0)) + " vertices (STL holds triangles)");
      corners = -1;
      mesh.triangles.push_back(tri);
    } else if (keyword == "endfacet") {
      if (!inFacet || corners >= 0) at.fail("\"endfacet\" outside a facet or inside a loop");
      inFacet = false;
    } else {
      at.fail("unknown ASCII STL statement " + quoted(token));
    }
  }
  if (inFacet)
    throw InputError(source, lineField(lines.number()) + " (end of file)", "", "the file ends inside a facet");
  return mesh;
}

bool beginsWithSolid(std::string_view bytes) {
  std::string_view rest = withoutBom(bytes).substr(0, 512);
  return lowerCase(nextToken(rest)) == "solid";
}

}  // namespace

ParsedMesh readStl(const std::string& source, std::string_view bytes) {
  // Binary when the size matches its count exactly (binary files often begin with "solid" too).
  if (bytes.size() >= kBinaryHeader) {
    std::uint32_t count = 0;
    std::memcpy(&count, bytes.data() + 80, 4);
    const std::uint64_t expected = kBinaryHeader + kBinaryTriangle * std::uint64_t(count);
    if (bytes.size() == expected) return readBinary(source, bytes, count);
    // ASCII STL holds no NUL byte; a binary file whose header begins with "solid" usually does.
    const bool binaryLooking = bytes.substr(0, 1024).find('\0') != std::string_view::npos;
    // Some exporters pad a binary file: fewer bytes than a triangle after the last are passed over.
    if (bytes.size() > expected && bytes.size() - expected < kBinaryTriangle && (binaryLooking || !beginsWithSolid(bytes)))
      return readBinary(source, bytes, count);
    refuseUtf16(bytes, source);
    if (!beginsWithSolid(bytes) || binaryLooking)
      throw InputError(source, "triangle count", std::to_string(count),
                       "cannot read the file as STL: binary STL of that many triangles has " +
                           std::to_string(expected) + " bytes, the file " + std::to_string(bytes.size()) +
                           " (truncated or corrupt; not ASCII STL either)");
  }
  if (!beginsWithSolid(bytes))
    throw InputError(source, "", "",
                     "cannot read the file as STL: too short for binary STL (84 bytes) and it "
                     "does not begin with \"solid\" (ASCII STL)");
  return readAscii(source, bytes);
}

}  // namespace shadowvol::mesh_readers
