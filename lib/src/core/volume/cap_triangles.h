// Stage 6 of the volume builder: the far cap's triangles, appended to the mesh facing away from
// the light. Flattened: the CDT of the boundary loops (far_cap.h). Unflattened: the mirror image
// of every kept sheet triangle that is not a wall on the far plane.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "shadowvol/far_cap.h"
#include "shadowvol/volume_mesh.h"
#include "volume/grid_unprojector.h"
#include "volume/quad_codes.h"
#include "volume/refined_cells.h"

namespace shadowvol::volume {

/// Appends the cap's triangles (counter-clockwise in texel space, as triangulateCapLoops gives
/// them) reversed, so that they face away from the light.
void appendFlatCap(const std::vector<std::array<std::uint32_t, 3>>& cap, VolumeMesh& mesh);

/// The refined quads' part of the mirrored cap: their footprint triangles, and where the cap
/// points of crossings are.
struct RefinedFootprint {
  const RefinedCells& cells;
  const BoundaryEdges& edges;
  const Refinement& refinement;
  const ChordPoints* chords;  ///< null without chord points
  std::uint32_t crossingBase, chordBase;
};

/// Appends one far-plane triangle per kept sheet triangle of the grid (found through the codes
/// and quadTri) and per footprint triangle of the refined quads, reversed. Vertices on the cap's
/// boundary (the ends of `edges`) are shared with the sheet (the sheet triangle already names the
/// right pinch copy), so is a far edge's crossing or chord point (its far vertex); every other texel
/// and every surface crossing or chord point gets one far-plane vertex, appended in order of first
/// use. Returns the
/// number of cap triangles.
std::size_t appendMirroredCap(const QuadGrid& grid, const Scratch<std::uint32_t>& quadTri,
                              const std::vector<CapEdge>& edges, const GridUnprojector& unproject, const DepthMap& map,
                              const RefinedFootprint* refined, VolumeMesh& mesh);

}  // namespace shadowvol::volume
