// Non-convex polygons of a mesh file cut into triangles that stay inside them: the readers fan
// every polygon from its first corner (polygon_fan.h), which covers area outside a non-convex one
// (an L-shaped face's fan fills its notch, and that surface casts shadow: a thirteenth probe's
// finding, also in CGAL's corner_poly.off and mpi.off).
#pragma once

#include <cstddef>

#include "mesh_readers/parsed_mesh.h"

namespace shadowvol::mesh_readers {

/// Re-cuts in place, by ear clipping in the plane of its Newell normal, the fan of each polygon of
/// `mesh.polygons` that is not convex there; a convex one keeps its fan, so a mesh of convex
/// polygons is unchanged. The triangles keep the polygon's winding and count (n - 2), so the
/// triangle order stays the file's. Where no ear is left (a self-intersecting or degenerate
/// polygon), or once the work exceeds a bound proportional to the mesh's size (a hostile file of
/// many large non-convex polygons: time stays bounded), the rest of the polygon keeps its fan.
/// Returns the number of polygons re-cut.
std::size_t triangulateNonConvexPolygons(ParsedMesh& mesh);

}  // namespace shadowvol::mesh_readers
