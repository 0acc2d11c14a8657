// Polygons of a mesh file as triangles: fanned while the file is read, the fans of non-convex
// polygons re-cut once every position is known (polygon_triangulation.h).
#pragma once

#include <cstdint>
#include <span>

#include "mesh_readers/parsed_mesh.h"

namespace shadowvol::mesh_readers {

/// Appends the fan (c0, c[k], c[k+1]), k = 1 .. n-2, of the polygon with corner indices `corners`
/// (n >= 3, checked by the reader) to `mesh.triangles`, keeping the polygon's winding, and records
/// a polygon of more than 3 corners in `mesh.polygons`. The fan is exact for convex polygons;
/// triangulateNonConvexPolygons re-cuts the others. Repeated corners are kept (a degenerate
/// triangle), never dropped.
void appendPolygon(std::span<const std::uint32_t> corners, ParsedMesh& mesh);

}  // namespace shadowvol::mesh_readers
