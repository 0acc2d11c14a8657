#include "shadowvol/cube_grid.h"

#include <algorithm>
#include <cstdint>
#include <set>

#include "shadowvol/check.h"
#include "shadowvol/cube_map.h"

namespace shadowvol::cube {
namespace {

// Face f's texel (i, j), where (i, j) may be one step outside the face: then the texel it pairs
// with across the edge (the step from the border texel it is next to).
struct Extended {
  int n, face;
  std::uint32_t operator()(int i, int j) const {
    const int ci = std::clamp(i, 0, n - 1), cj = std::clamp(j, 0, n - 1);
    if (ci == i && cj == j) return texelId(n, face, i, j);
    SV_CHECK(ci == i || cj == j);  // never diagonal: corner triangles name only edge neighbours
    const CubeTexel t = cubeTexelAcross(n, face, ci, cj, i - ci, j - cj);
    return texelId(n, t.face, t.i, t.j);
  }
};

}  // namespace

glm::dvec3 texelDirection(int n, std::uint32_t id) {
  const std::uint32_t nn = std::uint32_t(n) * std::uint32_t(n), r = id % nn;
  return cubeTexelDirection(n, int(id / nn), double(r % std::uint32_t(n)), double(r / std::uint32_t(n)));
}

Grid::Grid(int n) : n_(n), inner_(innerQuadCount(n)) {
  SV_CHECK_GE(n, 2);
  std::vector<Cell>& out = seams_;
  out.reserve(12u * std::size_t(n - 1) + 8u);
  // Edge quads and corners are met from two and three faces: each once, the first time.
  std::set<std::array<std::uint32_t, 4>> seen;
  auto add = [&](int f, std::array<std::uint32_t, 4> v, bool triangle) {
    std::array<std::uint32_t, 4> key = v;
    if (triangle) key[2] = UINT32_MAX;  // the unused corner
    std::sort(key.begin(), key.end());
    if (seen.insert(key).second) out.push_back({v, triangle, f, false});
  };
  for (int f = 0; f < kCubeFaces; ++f) {
    const Extended t{n, f};
    const int e = n - 1;
    for (int k = 0; k + 1 < n; ++k) {
      add(f, {t(e, k), t(n, k), t(n, k + 1), t(e, k + 1)}, false);      // right border
      add(f, {t(k, e), t(k + 1, e), t(k + 1, n), t(k, n)}, false);      // top border
      add(f, {t(-1, k), t(0, k), t(0, k + 1), t(-1, k + 1)}, false);    // left border
      add(f, {t(k, -1), t(k + 1, -1), t(k + 1, 0), t(k, 0)}, false);    // bottom border
    }
    // Corner triangles as A, B, D of the quad they would be in a map continued past the corner.
    add(f, {t(e, e), t(n, e), 0, t(e, n)}, true);     // top right
    add(f, {t(-1, e), t(0, e), 0, t(0, n)}, true);    // top left
    add(f, {t(0, -1), t(0, 0), 0, t(-1, 0)}, true);   // bottom left
    add(f, {t(e, -1), t(n, 0), 0, t(e, 0)}, true);    // bottom right
  }
  SV_CHECK_EQ(out.size(), 12u * std::size_t(n - 1) + 8u);
}

}  // namespace shadowvol::cube
