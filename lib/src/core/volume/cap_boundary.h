// Stage 4 of the volume builder (grid sheet): the boundary of the far cap, from the quad codes
// alone. A far vertex is a boundary vertex when its fan of triangles has a gap (a dropped triangle
// or the grid border). An edge between two far boundary vertices with kept triangles on both
// sides (a "slit": the sheet touches the far plane along it) is cut open, so the cap cannot reuse
// it. Each boundary vertex then gets one vertex per run of its fan between gaps and cuts: regions
// touching at a point or along a cut are split apart and the closed mesh stays a 2-manifold. Far
// vertices without a gap stay single (sheet only). Copies are numbered after the sheet's
// vertices, in texel order, then run order. The cap's edges are the edges of kept triangles
// between two far vertices with no kept triangle across (or cut open).
#pragma once

#include <cstdint>
#include <vector>

#include "shadowvol/far_cap.h"
#include "volume/sheet_depths.h"
#include "volume/sheet_vertices.h"

namespace shadowvol::volume {

/// One triangle slot of a boundary texel's fan.
struct FanSlot {
  bool kept;
  std::uint32_t quad;    ///< quad index
  std::uint8_t t, k;     ///< triangle of the quad, position of the vertex in it
  std::uint8_t run;      ///< kept slots: 0 = the original vertex, r = copy r - 1
  std::size_t ccwTexel;  ///< texel at the far end of the slot's counter-clockwise edge
};

/// The up to 6 triangle slots around a boundary texel, counter-clockwise from +i (a missing quad
/// is one gap slot), with the vertex indices of its runs.
struct Fan {
  std::uint32_t id = 0, firstCopy = 0;
  int n = 0;
  FanSlot slots[8];
  /// The vertex index a kept slot's triangle uses.
  std::uint32_t slotId(const FanSlot& slot) const { return slot.run == 0 ? id : firstCopy + slot.run - 1u; }
};

struct CapBoundary {
  std::vector<std::vector<Fan>> rowFans;  ///< per texel row, parallel to SheetVertices::rowBoundary
  std::uint32_t copies = 0;               ///< vertex copies at pinches and cuts
  std::vector<CapEdge> edges;             ///< in (quad, triangle, edge) order
};

/// Stage 4: fans, pinch and cut copies, and the cap's edges of the grid sheet.
CapBoundary findCapBoundary(const TexelUse& use, const SheetVertices& vertices, const SheetDepths& sheet);

}  // namespace shadowvol::volume
