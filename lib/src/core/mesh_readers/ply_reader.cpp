#include "mesh_readers/ply_reader.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "mesh_readers/number_text.h"
#include "mesh_readers/ply_body_cursor.h"
#include "mesh_readers/ply_header.h"
#include "mesh_readers/polygon_fan.h"
#include "shadowvol/error.h"

// Why our own reader, header and body, rather than a header check in front of OpenMesh or CGAL:
// tested on hostile files, both crash on a property before any element (SIGSEGV), OpenMesh loops
// forever on a truncated header, and a header that passes every check still leaves the body to
// them: a face list declaring 4e9 indices in a 100-byte file made CGAL's read_PLY throw bad_alloc,
// and both accept an index out of range or a truncated body (OpenMesh drops those faces silently,
// CGAL returns the bad index). OpenMesh's half-edge kernel also duplicates the vertices of
// non-manifold faces. Reading the two properties we need ourselves bounds every read by the file.

namespace shadowvol::mesh_readers {
namespace {

// What the mesh needs from the header: the vertex element's x, y, z and the face element's list.
struct Layout {
  const PlyElement* vertex = nullptr;
  int xyz[3] = {-1, -1, -1};  // property indices in the vertex element
  const PlyElement* face = nullptr;
  int indices = -1;  // property index of the face's vertex list
};

Layout findLayout(const std::string& source, const PlyHeader& h) {
  Layout l;
  for (const PlyElement& e : h.elements) {
    if (e.name == "vertex" && !l.vertex) l.vertex = &e;
    if (e.name == "face" && !l.face) l.face = &e;
  }
  if (!l.vertex) throw InputError(source, "header", "", "the PLY file has no vertex element");
  const TextPlace vertexLine{source, l.vertex->line, l.vertex->text};
  if (l.vertex->count > std::numeric_limits<std::uint32_t>::max())
    vertexLine.fail("more vertices than 32-bit indices can address");
  for (int k = 0; k < int(l.vertex->properties.size()); ++k) {
    const PlyProperty& p = l.vertex->properties[k];
    for (int c = 0; c < 3; ++c)
      if (p.name == std::string(1, char('x' + c)) && !p.isList) l.xyz[c] = k;
  }
  if (l.xyz[0] < 0 || l.xyz[1] < 0 || l.xyz[2] < 0)
    vertexLine.fail("the vertex element needs scalar properties x, y and z");
  if (!l.face) {
    for (const PlyElement& e : h.elements)  // faces as strips: not read, said rather than an empty mesh
      if (e.name == "tristrips" && e.count > 0)
        TextPlace{source, e.line, e.text}.fail("triangle strips are not read: store the triangles as a face element");
    return l;
  }
  for (int k = 0; k < int(l.face->properties.size()); ++k) {
    const PlyProperty& p = l.face->properties[k];
    if (p.isList && (p.name == "vertex_indices" || p.name == "vertex_index")) l.indices = k;
  }
  const TextPlace faceLine{source, l.face->line, l.face->text};
  if (l.indices < 0) faceLine.fail("the face element has no list property vertex_indices");
  if (!plyTypeIsInteger(l.face->properties[l.indices].type)) faceLine.fail("vertex indices must have an integer type");
  return l;
}

// Reads element e from the cursor: vertices into mesh.positions, faces fanned into
// mesh.triangles, any other element read past.
void readElement(const std::string& source, const PlyElement& e, const Layout& l, PlyBodyCursor& body,
                 ParsedMesh& mesh) {
  const bool isVertex = &e == l.vertex, isFace = &e == l.face;
  std::vector<std::uint32_t> corners;
  for (std::uint64_t r = 0; r < e.count; ++r) {
    const auto fail = [&](const std::string& value, const std::string& problem) {
      throw InputError(source, e.name + " " + std::to_string(r) + body.where(), value, problem);
    };
    const auto value = [&](PlyType t) {
      const auto v = body.read(t);
      if (!v && body.ended()) fail("", "the file ends inside this element (truncated)");
      if (!v && body.lineEnded())
        fail("", "its line ends before its values do (ASCII PLY holds one element a line, with a value for "
                 "each property the header declares)");
      if (!v) fail(body.lastValue(), plyTypeIsInteger(t) ? "not an integer" : "not a number");
      return *v;
    };
    body.beginRow();
    double xyz[3] = {0, 0, 0};
    for (int k = 0; k < int(e.properties.size()); ++k) {
      const PlyProperty& p = e.properties[k];
      if (!p.isList) {
        const double v = value(p.type);
        for (int c = 0; c < 3; ++c)
          if (isVertex && k == l.xyz[c]) xyz[c] = v;
        continue;
      }
      const double n = value(p.countType);
      if (n < 0) fail(body.lastValue(), "a negative list length");
      if (n > double(body.valuesLeft(p.type)))
        fail(body.lastValue(),
             "a list of " + std::to_string(std::uint64_t(n)) + " values, more than the rest of the file holds");
      if (!(isFace && k == l.indices)) {
        if (!body.skip(p.type, std::uint64_t(n))) fail("", "the file ends inside this element (truncated)");
        continue;
      }
      if (n < 3) fail(body.lastValue(), "a face needs at least 3 vertices");
      corners.clear();
      for (std::uint64_t c = 0; c < std::uint64_t(n); ++c) {
        const double index = value(p.type);
        if (index < 0 || index >= double(l.vertex->count))
          fail(body.lastValue(),
               "vertex index out of range (the file declares " + std::to_string(l.vertex->count) + " vertices)");
        corners.push_back(std::uint32_t(index));
      }
      appendPolygon(corners, mesh);
    }
    if (const std::string left = body.rowLeftover(); !left.empty())
      fail(left, "more values on its line than the header declares properties (ASCII PLY holds one element a line)");
    if (!isVertex) continue;
    const auto point = checkedPoint(xyz[0], xyz[1], xyz[2]);
    if (!point) {
      char buf[96];
      std::snprintf(buf, sizeof buf, "%.9g %.9g %.9g", xyz[0], xyz[1], xyz[2]);
      fail(buf, "non-finite vertex coordinate (or beyond single precision)");
    }
    mesh.positions.push_back(*point);
  }
}

}  // namespace

ParsedMesh readPly(const std::string& source, std::string_view bytes) {
  const PlyHeader header = parsePlyHeader(source, bytes);
  const Layout layout = findLayout(source, header);
  ParsedMesh mesh;
  mesh.positions.reserve(layout.vertex->count);  // the header check bounds it by the file size
  PlyBodyCursor body(bytes, header);
  for (const PlyElement& e : header.elements) {
    if (e.properties.empty()) continue;  // rows without data: nothing to read, however many
    readElement(source, e, layout, body, mesh);
  }
  bool floatXyz = false;
  for (const int k : layout.xyz) floatXyz = floatXyz || layout.vertex->properties[k].type == PlyType::Float32;
  if (header.format != PlyFormat::Ascii && floatXyz) mesh.floatPlacement = FloatPlacement::of(mesh.positions);
  const std::string left = body.dataLeft();
  if (!left.empty())
    throw InputError(source, "after the last element" + body.where(), left,
                     "data after the elements the header declares");
  return mesh;
}

}  // namespace shadowvol::mesh_readers
