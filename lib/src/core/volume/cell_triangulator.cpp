#include "volume/cell_triangulator.h"

#include <algorithm>

namespace shadowvol::volume {

void keepCellTriangles(const std::vector<LocalTri>& tris, bool exact, std::vector<Tri>& triangles,
                       std::vector<CapEdge>& capEdges, std::vector<std::array<CapPoint, 3>>* footprint) {
  auto dropped = [&](const LocalTri& t) { return exact && t.v[0]->far && t.v[1]->far && t.v[2]->far; };
  for (const LocalTri& t : tris) {
    if (dropped(t)) continue;
    triangles.push_back({t.v[0]->id, t.v[1]->id, t.v[2]->id});
    if (footprint && t.footprint) footprint->push_back({t.v[0]->cap, t.v[1]->cap, t.v[2]->cap});
    for (int m = 0; m < 3; ++m) {
      const CellVertex* u = t.v[m];
      const CellVertex* v = t.v[(m + 1) % 3];
      if (!u->far || !v->far) continue;
      const bool acrossDropped = std::any_of(tris.begin(), tris.end(), [&](const LocalTri& o) {
        if (!dropped(o)) return false;
        for (int c = 0; c < 3; ++c)
          if (o.v[c]->id == v->id && o.v[(c + 1) % 3]->id == u->id) return true;
        return false;
      });
      if (acrossDropped) capEdges.push_back({u->id, v->id, u->texel, v->texel});
    }
  }
}

}  // namespace shadowvol::volume
