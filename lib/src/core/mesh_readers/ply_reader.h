// The strict PLY reader behind readTriangleMesh.
#pragma once

#include <string>
#include <string_view>

#include "mesh_readers/parsed_mesh.h"

namespace shadowvol::mesh_readers {

/// Reads ASCII or binary (either endianness) PLY: the `vertex` element's scalar x, y, z and the
/// `face` element's list `vertex_indices` (or `vertex_index`) of 0-based integer indices, polygons
/// fanned; every other element and property is read past. The header is checked first
/// (ply_header.h). Throws InputError naming `source`, the element and index ("face 17", plus the
/// line in ASCII) and the value for a truncated body, a value that is not a number, a non-finite
/// coordinate, a face with fewer than 3 vertices or an index out of range. May return a mesh
/// without triangles (a file without a face element).
ParsedMesh readPly(const std::string& source, std::string_view bytes);

}  // namespace shadowvol::mesh_readers
