#include "mesh_readers/off_reader.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

#include "mesh_readers/number_text.h"
#include "mesh_readers/polygon_fan.h"
#include "mesh_readers/text_lines.h"
#include "shadowvol/error.h"

// Why our own reader rather than OpenMesh's: OpenMesh 9 trusts the header's counts (10^7 declared
// vertices in a 40-byte file ran for minutes, 2e9 threw bad_alloc after gigabytes), refuses the
// '#' comment lines CGAL writes (blobby-shuffled.off), and drops faces with an out-of-range index
// or fewer than three vertices without a word. Here every loop is bounded by the lines of the file
// and the counts are checked against its size before anything is reserved.

namespace shadowvol::mesh_readers {
namespace {

// The next line holding data (comments and blank lines skipped), or nullopt at the end.
std::optional<std::string_view> nextDataLine(LineReader& lines) {
  while (const auto line = lines.next())
    if (!isBlank(withoutComment(*line))) return line;
  return std::nullopt;
}

[[noreturn]] void failAtEnd(const std::string& source, const LineReader& lines, const std::string& problem) {
  throw InputError(source, lineField(lines.number()) + " (end of file)", "", problem);
}

// Checks the keyword: OFF with optional prefixes ST, C, N in that order; nothing else.
void checkKeyword(std::string_view keyword, const TextPlace& at) {
  const std::size_t n = keyword.size();
  if (n < 3 || keyword.substr(n - 3) != "OFF")
    at.fail("cannot read the file as OFF: it must begin with OFF, COFF, NOFF, CNOFF or STOFF, not " + quoted(keyword));
  std::string_view prefix = keyword.substr(0, n - 3);
  if (prefix.find_first_of("4n") != std::string_view::npos)
    at.fail("only 3-D OFF is supported, not " + quoted(keyword));
  for (const std::string_view part : {"ST", "C", "N"})
    if (prefix.substr(0, part.size()) == part) prefix.remove_prefix(part.size());
  if (!prefix.empty()) at.fail("cannot read the file as OFF: unknown keyword " + quoted(keyword));
}

struct Counts {
  std::uint64_t vertices = 0, faces = 0;
};

// The header: keyword, then "V F [E]" on the same line or the next data line.
Counts readHeader(const std::string& source, LineReader& lines) {
  auto line = nextDataLine(lines);
  if (!line) throw InputError(source, "", "", "cannot read the file as OFF: it holds no data");
  TextPlace at{source, lines.number(), *line};
  std::string_view rest = withoutComment(*line);
  checkKeyword(nextToken(rest), at);
  if (isBlank(rest)) {
    line = nextDataLine(lines);
    if (!line) failAtEnd(source, lines, "the OFF header has no vertex and face counts");
    at = TextPlace{source, lines.number(), *line};
    rest = withoutComment(*line);
  }
  const std::string_view first = nextToken(rest), second = nextToken(rest);
  if (first == "BINARY") at.fail("binary OFF is not supported: convert the file to ASCII OFF");
  const auto v = parseInteger(first), f = parseInteger(second);
  if (!v || !f || *v < 0 || *f < 0) at.fail("expected the vertex and face counts \"V F [E]\"");
  constexpr std::int64_t kMaxIndex = std::numeric_limits<std::uint32_t>::max();
  if (*v > kMaxIndex || *f > kMaxIndex) at.fail("more vertices or faces than 32-bit indices can address");
  // The edge count (ignored) may follow; anything after it is data on the counts' line, which
  // this line-based reader does not take (it would read the next line as the first vertex).
  if (const std::string_view edges = nextToken(rest); !edges.empty() && !isBlank(rest))
    at.fail("the line of the counts holds more than \"V F [E]\": put each vertex and each face on a line of its own");
  // The shortest vertex line is "0 0 0\n" (6 bytes), the shortest face line "0\n" (2: too few
  // vertices, but the face loop says so at its line); the last line may lack its newline. Refusing
  // here keeps a hostile count from reserving memory.
  const std::uint64_t needed = 6 * std::uint64_t(*v) + 2 * std::uint64_t(*f);
  if (needed > lines.bytesLeft() + 1)
    at.fail("the header declares " + std::to_string(*v) + " vertices and " + std::to_string(*f) +
            " faces, which need at least " + std::to_string(needed - 1) + " bytes after the header; " +
            std::to_string(lines.bytesLeft()) + " bytes follow (truncated, or wrong counts)");
  return {std::uint64_t(*v), std::uint64_t(*f)};
}

// Whether a vertex line reads as a face, "n i1 ... in" of whole numbers, n >= 3 (a vertex line
// holds reals, and any colour after them): the sign of a header that declares more vertices than
// the file holds.
bool looksLikeFace(std::string_view rest) {
  const auto n = parseInteger(nextToken(rest));
  std::int64_t listed = 0;
  for (std::string_view token = nextToken(rest); !token.empty(); token = nextToken(rest), ++listed)
    if (!parseInteger(token)) return false;
  return n && *n >= 3 && listed == *n;
}

// Face `k`'s corners. A first face whose count is a real is likely a vertex line: the header then
// declares fewer vertices than the file holds, which the message says.
std::vector<std::uint32_t> faceCorners(std::string_view rest, std::uint64_t k, std::uint64_t vertexCount,
                                       const TextPlace& at) {
  const std::string_view first = nextToken(rest);
  const auto n = parseInteger(first);
  if (!n && k == 0 && parseReal(first))
    at.fail("the vertex count " + quoted(first) + " of face 0 is not an integer: is this line a vertex? The header " +
            "declares " + std::to_string(vertexCount) + " vertices");
  if (!n) at.fail("the vertex count " + quoted(first) + " of the face " + integerProblem(first));
  if (*n < 3) at.fail("a face needs at least 3 vertices, this one has " + std::to_string(*n));
  std::vector<std::uint32_t> corners;
  for (std::int64_t k = 0; k < *n; ++k) {
    const std::string_view token = nextToken(rest);  // each token takes at least a byte of the line
    if (token.empty()) at.fail("the face declares " + std::to_string(*n) + " vertices but lists " + std::to_string(k));
    const auto index = parseInteger(token);
    if (!index) at.fail("vertex index " + quoted(token) + " " + integerProblem(token));
    if (*index < 0 || std::uint64_t(*index) >= vertexCount)
      at.fail("vertex index " + std::to_string(*index) + " is out of range (the header declares " +
              std::to_string(vertexCount) + " vertices)");
    corners.push_back(std::uint32_t(*index));
  }
  return corners;  // tokens after the indices are a colour
}

}  // namespace

ParsedMesh readOff(const std::string& source, std::string_view text) {
  refuseUtf16(text, source);
  LineReader lines(text);
  const Counts counts = readHeader(source, lines);
  ParsedMesh mesh;
  mesh.positions.reserve(counts.vertices);
  mesh.triangles.reserve(std::min<std::uint64_t>(counts.faces, lines.bytesLeft() / 8));  // a triangle's line: 8+ bytes
  std::string faceAsVertex;  // the first vertex line that reads as a face, named if the faces run short
  for (std::uint64_t k = 0; k < counts.vertices; ++k) {
    const auto line = nextDataLine(lines);
    if (!line)
      failAtEnd(source, lines,
                "the file ends after " + std::to_string(k) + " of the " + std::to_string(counts.vertices) +
                    " vertices its header declares");
    std::string_view rest = withoutComment(*line);
    if (faceAsVertex.empty() && looksLikeFace(rest))
      faceAsVertex = "; line " + std::to_string(lines.number()) + ", read as vertex " + std::to_string(k) + ", reads as a face " +
                     quoted(rest.substr(0, 40)) + ": does the header declare more vertices than the file holds?";
    mesh.positions.push_back(readPoint(rest, TextPlace{source, lines.number(), *line}));
  }
  for (std::uint64_t k = 0; k < counts.faces; ++k) {
    const auto line = nextDataLine(lines);
    if (!line)
      failAtEnd(source, lines,
                "the file ends after " + std::to_string(k) + " of the " + std::to_string(counts.faces) +
                    " faces its header declares" + faceAsVertex);
    const TextPlace at{source, lines.number(), *line};
    appendPolygon(faceCorners(withoutComment(*line), k, counts.vertices, at), mesh);
  }
  if (const auto extra = nextDataLine(lines))
    TextPlace{source, lines.number(), *extra}.fail("data after the " + std::to_string(counts.faces) +
                                                   " faces the header declares");
  return mesh;
}

}  // namespace shadowvol::mesh_readers
