#include "volume/sheet_emit.h"

#include <cstring>
#include <utility>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace shadowvol::volume {

void emitSheet(const SheetDepths& sheet, const GridUnprojector& unproject, const TexelUse& use, const QuadCodes& codes,
               const SheetVertices& vertices, VolumeMesh& mesh, Scratch<std::uint32_t>& quadTri) {
  const QuadGrid& grid = use.grid();
  const int qw = grid.qw, qh = grid.qh, w = qw + 1;
  const auto& rowVerts = vertices.rowVerts;
  tbb::parallel_for(tbb::blocked_range<int>(0, qh, 8), [&](const tbb::blocked_range<int>& rows) {
    std::vector<std::uint32_t> idxLo(w), idxHi(w);
    std::vector<std::uint8_t> used(w);
    std::vector<double> depth(w), x(w), y(w), z(w);
    bool bad = false;  // already reported by stage 2
    // Vertex indices of row j over its used span (entries outside it are stale and never read:
    // the triangles of a quad row lie within its span).
    auto vertexRow = [&](int j, std::vector<std::uint32_t>& idx) {
      const auto [b, e] = use.row(j, used.data());
      numberRow(used.data() + b, idx.data() + b, e - b, std::uint32_t(rowVerts[j]), kNone);
      return std::pair<int, int>{b, e};
    };
    auto emitRow = [&](int j, const std::vector<std::uint32_t>& idx, std::pair<int, int> span) {
      if (rowVerts[j + 1] == rowVerts[j]) return;
      auto [b, e] = span;
      while (idx[b] == kNone) ++b;
      while (idx[e - 1] == kNone) --e;
      sheet.row(j, depth.data(), bad, b, e);
      unproject.worldPoints(j, b, e, depth.data(), x.data(), y.data(), z.data());
      for (int i = b; i < e; ++i)
        if (idx[i] != kNone) mesh.positions[idx[i]] = {x[i], y[i], z[i]};
    };
    std::pair<int, int> spanLo, spanHi = vertexRow(rows.begin(), idxHi);
    for (int qj = rows.begin(); qj != rows.end(); ++qj) {
      std::swap(idxLo, idxHi);
      spanLo = spanHi;
      spanHi = vertexRow(qj + 1, idxHi);
      emitRow(qj, idxLo, spanLo);
      if (qj + 1 == qh) emitRow(qj + 1, idxHi, spanHi);
      std::size_t next = codes.rowTriOffset[qj];
      const std::uint8_t* rowCode = grid.code + std::size_t(qj) * qw;
      const auto [qb, qe] = codes.rowSpan[qj];
      for (int qi = qb; qi < qe; ++qi) {
        const std::size_t qIndex = std::size_t(qj) * qw + qi;
        if (qi + 8 <= qe) {  // runs of dropped quads (code 0), 8 at a time
          std::uint64_t eight;
          std::memcpy(&eight, rowCode + qi, 8);
          if (eight == 0) {  // quadTri of a dropped quad is never read
            qi += 7;
            continue;
          }
        }
        const std::uint8_t q = rowCode[qi];
        quadTri[qIndex] = std::uint32_t(next);
        const int f = q & kFlip;
        const std::uint32_t corner[4] = {idxLo[qi], idxLo[qi + 1], idxHi[qi + 1], idxHi[qi]};
        for (int t = 0; t < 2; ++t) {
          if (!(q & keepBit(t))) continue;
          const int* cs = kTriCorners[f][t];
          mesh.triangles[next++] = {corner[cs[0]], corner[cs[1]], corner[cs[2]]};
        }
      }
    }
  });
}

void emitPinchCopies(const QuadGrid& grid, const CapBoundary& cap, const Scratch<std::uint32_t>& quadTri,
                     VolumeMesh& mesh) {
  const int h = grid.qh + 1;
  tbb::parallel_for(tbb::blocked_range<int>(0, h, 32), [&](const tbb::blocked_range<int>& rows) {
    for (int j = rows.begin(); j != rows.end(); ++j)
      for (const Fan& fan : cap.rowFans[j])
        for (int s = 0; s < fan.n; ++s) {
          const FanSlot& slot = fan.slots[s];
          if (!slot.kept || slot.run == 0) continue;
          mesh.positions[fan.firstCopy + slot.run - 1u] = mesh.positions[fan.id];
          const std::uint8_t q = grid.code[slot.quad];
          mesh.triangles[quadTri[slot.quad] + ((slot.t == 1 && (q & kKeep0)) ? 1u : 0u)][slot.k] = fan.slotId(slot);
        }
  });
}

}  // namespace shadowvol::volume
