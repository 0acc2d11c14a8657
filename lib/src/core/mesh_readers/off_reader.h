// The strict ASCII OFF reader behind readTriangleMesh.
#pragma once

#include <string>
#include <string_view>

#include "mesh_readers/parsed_mesh.h"

namespace shadowvol::mesh_readers {

/// Reads ASCII OFF: the keyword OFF with the optional prefixes ST, C and N (STOFF, COFF, NOFF,
/// CNOFF...), the counts "V F [E]" (on the keyword's line or the next), V vertex lines whose first
/// three numbers are the position (colours, normals, texture coordinates after them are ignored),
/// then F face lines "n i1 .. in [colour]" with 0-based indices; polygons are fanned. '#' starts a
/// comment, blank lines are skipped. Refuses (InputError naming `source`, the line and its text)
/// binary OFF, 4OFF / nOFF, counts the file is too short to hold, a bad vertex, a face with fewer
/// than 3 vertices or an index out of range, a file ending early and data after the last face.
ParsedMesh readOff(const std::string& source, std::string_view text);

}  // namespace shadowvol::mesh_readers
