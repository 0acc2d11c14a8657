// The STL reader behind readTriangleMesh: a triangle soup, every triangle kept.
#pragma once

#include <string>
#include <string_view>

#include "mesh_readers/parsed_mesh.h"

namespace shadowvol::mesh_readers {

/// Reads binary STL (80-byte header, uint32 count, 50 bytes per triangle; the file size must be
/// exactly 84 + 50 * count) or ASCII STL (`solid` ... `facet` / `outer loop` / 3 x `vertex x y z`
/// / `endloop` / `endfacet` ... `endsolid`, several solids allowed). Corners at bit-identical
/// positions (0 and -0 alike) become one vertex; every triangle is kept, degenerate ones too.
/// Throws InputError naming `source` and the triangle (binary) or line (ASCII) for a non-finite
/// coordinate, a size that matches neither form, or a malformed ASCII statement.
ParsedMesh readStl(const std::string& source, std::string_view bytes);

}  // namespace shadowvol::mesh_readers
