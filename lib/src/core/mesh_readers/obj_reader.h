// The strict Wavefront OBJ reader behind readTriangleMesh.
#pragma once

#include <string>
#include <string_view>

#include "mesh_readers/parsed_mesh.h"

namespace shadowvol::mesh_readers {

/// Reads OBJ text: `v x y z [w | r g b]` lines and `f` lines of corners `i`, `i/t`, `i/t/n` or
/// `i//n` (1-based; a negative index counts back from the last vertex before the line); polygons
/// are fanned (polygon_fan.h). Other statements (vt, vn, g, o, s, usemtl, l, p, ...) are ignored;
/// '#' starts a comment. May return a mesh without triangles. Throws InputError naming `source`,
/// the line and its text for a vertex with fewer than three numbers or a non-finite one, and for
/// a face with fewer than three corners or an index that is not an integer, 0 or out of range.
ParsedMesh readObj(const std::string& source, std::string_view text);

}  // namespace shadowvol::mesh_readers
