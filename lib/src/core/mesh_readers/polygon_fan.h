// Polygons of a mesh file as triangles.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace shadowvol::mesh_readers {

/// Appends the fan (c0, c[k], c[k+1]), k = 1 .. n-2, of the polygon with corner indices `corners`
/// (n >= 3, checked by the reader) to `triangles`, keeping the polygon's winding. Exact for convex
/// polygons, as OpenMesh's readers; a concave polygon gets overlapping triangles. Repeated
/// corners are kept (a degenerate triangle), never dropped.
void appendFan(std::span<const std::uint32_t> corners, std::vector<std::array<std::uint32_t, 3>>& triangles);

}  // namespace shadowvol::mesh_readers
