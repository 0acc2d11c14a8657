#include "volume/cap_boundary.h"

#include <algorithm>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "shadowvol/check.h"

namespace shadowvol::volume {
namespace {

// The up to 6 triangle slots around texel (i, j), counter-clockwise from +i; a missing quad is
// one gap slot.
void collectSlots(const QuadGrid& grid, int i, int j, Fan& fan) {
  const int qw = grid.qw, qh = grid.qh, w = qw + 1;
  int n = 0;
  const int quads[4][3] = {{i, j, 0}, {i - 1, j, 1}, {i - 1, j - 1, 2}, {i, j - 1, 3}};  // NE, NW, SW, SE
  for (const auto& [qi, qj, corner] : quads) {
    if (qi < 0 || qj < 0 || qi >= qw || qj >= qh) {
      fan.slots[n++] = {false, 0, 0, 0, 0, 0};
      continue;
    }
    const std::size_t qIndex = std::size_t(qj) * qw + qi;
    const std::uint8_t q = grid.code[qIndex];
    const int f = q & kFlip;
    int order[2] = {0, 1};  // counter-clockwise order of the quad's triangles around this corner
    if ((corner == 1 && !f) || (corner == 2 && f)) std::swap(order[0], order[1]);
    for (int t : order) {
      const int* cs = kTriCorners[f][t];
      const int k = cs[0] == corner ? 0 : cs[1] == corner ? 1 : cs[2] == corner ? 2 : -1;
      if (k < 0) continue;
      const int ccw = cs[(k + 2) % 3];
      fan.slots[n++] = {(q & keepBit(t)) != 0, std::uint32_t(qIndex), std::uint8_t(t), std::uint8_t(k), 0,
                        std::size_t(qj + kCornerDj[ccw]) * w + qi + kCornerDi[ccw]};
    }
  }
  fan.n = n;
}

}  // namespace

CapBoundary findCapBoundary(const TexelUse& use, const SheetVertices& vertices, const SheetDepths& sheet) {
  const QuadGrid& grid = use.grid();
  const int qw = grid.qw, h = grid.qh + 1, w = qw + 1;
  const double farPlane = sheet.rule().farPlane;
  const auto& rowBoundary = vertices.rowBoundary;
  CapBoundary result;
  auto& rowFans = result.rowFans;
  auto texelBoundary = [&](std::size_t t) { return use.isBoundary(int(t % std::size_t(w)), int(t / std::size_t(w))); };
  rowFans.resize(h);
  tbb::parallel_for(tbb::blocked_range<int>(0, h, 32), [&](const tbb::blocked_range<int>& rows) {
    for (int j = rows.begin(); j != rows.end(); ++j) {
      rowFans[j].resize(rowBoundary[j].size());
      for (std::size_t b = 0; b < rowBoundary[j].size(); ++b) {
        Fan& fan = rowFans[j][b];
        collectSlots(grid, rowBoundary[j][b].i, j, fan);
        fan.id = std::uint32_t(vertices.rowVerts[j] + rowBoundary[j][b].local);
        int gap = 0;
        while (fan.slots[gap].kept) ++gap;
        int fans = 0;
        for (int s = 1; s <= fan.n; ++s) {
          FanSlot& slot = fan.slots[(gap + s) % fan.n];
          const FanSlot& prev = fan.slots[(gap + s - 1) % fan.n];
          if (!slot.kept) continue;
          const bool cut = prev.kept && texelBoundary(prev.ccwTexel);
          if (!prev.kept || cut) ++fans;  // a run starts here
          slot.run = std::uint8_t(fans - 1);
        }
        fan.firstCopy = std::uint32_t(fans - 1);  // the number of copies, until numbered below
      }
    }
  });
  for (auto& fans : rowFans)
    for (Fan& fan : fans) {
      const std::uint32_t n = fan.firstCopy;
      fan.firstCopy = std::uint32_t(vertices.count()) + result.copies;
      result.copies += n;
    }
  auto fanAt = [&](int i, int j) -> const Fan& {
    const auto& list = rowBoundary[j];
    const auto it = std::lower_bound(list.begin(), list.end(), i,
                                     [](const SheetVertices::Boundary& b, int x) { return b.i < x; });
    SV_CHECK(it != list.end() && it->i == i);
    return rowFans[j][std::size_t(it - list.begin())];
  };

  // Cap edges. Both ends are boundary vertices, so the edges are found from the boundary fans,
  // each once, from its first vertex; then put in (quad, triangle, edge) order.
  std::vector<std::vector<std::pair<std::uint64_t, CapEdge>>> rowKeyed(h);
  tbb::parallel_for(tbb::blocked_range<int>(0, h, 32), [&](const tbb::blocked_range<int>& rows) {
    for (int j0 = rows.begin(); j0 != rows.end(); ++j0)
      for (std::size_t b = 0; b < rowBoundary[j0].size(); ++b) {
        const int i0 = rowBoundary[j0][b].i;
        const Fan& fan = rowFans[j0][b];
        for (int s = 0; s < fan.n; ++s) {
          const FanSlot& slot = fan.slots[s];
          if (!slot.kept) continue;
          const int qi = int(slot.quad % std::uint32_t(qw)), qj = int(slot.quad / std::uint32_t(qw));
          const int* cs = kTriCorners[grid.code[slot.quad] & kFlip][slot.t];
          const int c1 = cs[(slot.k + 1) % 3];
          const int i1 = qi + kCornerDi[c1], j1 = qj + kCornerDj[c1];
          if (sheet.at(i1, j1) != farPlane) continue;
          const bool cut = use.isBoundary(i1, j1);
          if (!cut && grid.neighbourKept(qi, qj, slot.t, slot.k)) continue;
          const Fan& other = fanAt(i1, j1);  // the same triangle, at its next corner
          const FanSlot* end = nullptr;
          for (int o = 0; o < other.n && !end; ++o)
            if (other.slots[o].kept && other.slots[o].quad == slot.quad && other.slots[o].t == slot.t)
              end = &other.slots[o];
          SV_CHECK(end != nullptr);
          rowKeyed[j0].push_back({(std::uint64_t(slot.quad) * 2 + slot.t) * 3 + slot.k,
                                  {fan.slotId(slot), other.slotId(*end), {double(i0), double(j0)},
                                   {double(i1), double(j1)}}});
        }
      }
  });
  std::vector<std::pair<std::uint64_t, CapEdge>> keyed;
  for (auto& row : rowKeyed) keyed.insert(keyed.end(), row.begin(), row.end());
  std::sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  result.edges.reserve(keyed.size());
  for (const auto& [key, edge] : keyed) result.edges.push_back(edge);
  return result;
}

}  // namespace shadowvol::volume
