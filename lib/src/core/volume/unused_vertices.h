// The last step of the adaptive sub-grid (subgrid_cells.h): the plain crossings of boundary edges
// between two gridded quads have vertices that no triangle uses; they are dropped.
#pragma once

#include <cstdint>

#include "shadowvol/volume_mesh.h"

namespace shadowvol::volume {

/// Drops the vertices from index `from` on that no triangle uses, keeping the order of the others
/// and renumbering the triangles' indices; returns how many were dropped.
std::size_t dropUnusedVertices(VolumeMesh& mesh, std::uint32_t from);

}  // namespace shadowvol::volume
