// Stage 5 of the volume builder: the grid sheet's vertex positions and triangles (pass B), and
// the pinch copies' positions and triangle corners.
#pragma once

#include <cstdint>

#include "shadowvol/volume_mesh.h"
#include "volume/cap_boundary.h"
#include "volume/grid_unprojector.h"
#include "volume/sheet_depths.h"
#include "volume/sheet_vertices.h"

namespace shadowvol::volume {

/// Writes the positions of the sheet's vertices (mesh.positions[0, vertices.count())) and its
/// triangles (mesh.triangles[0, codes.sheetTriangles()), the kept triangles of every quad in quad
/// order, counter-clockwise in texel space), row-parallel with two rolling rows of vertex indices
/// per task. quadTri[q] gets the index of quad q's first triangle (kept quads only). Both mesh
/// buffers must be sized already.
void emitSheet(const SheetDepths& sheet, const GridUnprojector& unproject, const TexelUse& use, const QuadCodes& codes,
               const SheetVertices& vertices, VolumeMesh& mesh, Scratch<std::uint32_t>& quadTri);

/// The pinch copies (cap.copies, numbered from vertices.count()): their positions (those of the
/// vertex they copy), and the corners of their runs' triangles.
void emitPinchCopies(const QuadGrid& grid, const CapBoundary& cap, const Scratch<std::uint32_t>& quadTri,
                     VolumeMesh& mesh);

}  // namespace shadowvol::volume
