#include "shadowvol/cube_volume.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <chrono>
#include <cmath>
#include <numeric>
#include <optional>
#include <span>
#include <sstream>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include <tbb/parallel_for.h>

#include "cube/cube_refinement.h"
#include "shadowvol/cube_grid.h"
#include "shadowvol/check.h"
#include "shadowvol/depth_blur.h"
#include "shadowvol/error.h"
#include "shadowvol/far_cap.h"
#include "shadowvol/sheet_depth.h"
#include "shadowvol/triangulation.h"

namespace shadowvol {
namespace {

using Clock = std::chrono::steady_clock;
using Tri = std::array<std::uint32_t, 3>;
constexpr std::uint32_t kNone = UINT32_MAX;

double msSince(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

void validate(const CubeDepthMap& cube, const VolumeBuildOptions& o) {
  const int n = cube.size();
  SV_CHECK_GE(n, 2);
  for (const DepthMap& f : cube.faces) {
    SV_CHECK(f.width == n && f.height == n && f.depth.size() == std::size_t(n) * std::size_t(n));
    SV_CHECK(f.nearPlane == cube.nearPlane() && f.farPlane == cube.farPlane() && f.capture == cube.capture());
  }
  SV_CHECK_GT(cube.farPlane(), cube.nearPlane());
  SV_CHECK_GT(cube.nearPlane(), 0.0);
  checkVolumeOffsets(o, cube.nearPlane(), cube.farPlane());
  if (o.refineSteps < 0 || o.refineSteps > kMaxRefineSteps)
    throw InputError("volume options", "refine steps", std::to_string(o.refineSteps),
                     "must be between 0 (off) and " + std::to_string(kMaxRefineSteps));
  if (o.refineSteps > 0 && o.crossingSource)
    throw OptionConflict("volume options", "crossing source", "set", MarkedProblem{kCubeRefinementRule});
  if (o.refineSteps > 0 && o.refineChords)
    throw OptionConflict("volume options", "refine chords", "true", MarkedProblem{kCubeRefinementRule});
  if (o.refineSteps > 0 && o.refineSubdivisions != 1)
    throw OptionConflict("volume options", "refine subdivisions", std::to_string(o.refineSubdivisions),
                         MarkedProblem{kCubeRefinementRule});
  if (o.refineSteps > 0 && !o.depthOracle)
    throw InputError("volume options", "refine steps", std::to_string(o.refineSteps),
                     "refinement casts rays into the scene: it needs a depth oracle (an Embree scene on the "
                     "command line)");
  if (o.facePrisms)
    throw OptionConflict("volume options", "face prisms", "true",
                         "are made for spot and directional lights; a point light's cube volume has none yet");
  if (o.cap != FarCap::Exact)
    throw OptionConflict("volume options", "cap", toString(o.cap), kCubeVolumeCapRule);
  for (int f = 0; f < kCubeFaces; ++f)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const float d = cube.faces[f].at(i, j);
        if (!std::isnan(d) && d >= 0.0f) continue;
        std::ostringstream field, value;
        field << "face " << cubeFaceName(f) << ": depth of texel (" << i << ", " << j << ")";
        value << d;
        throw InputError("cube map", field.str(), value.str(),
                         "depths must be non-negative light-view distances (world units) or +inf for no hit");
      }
}

// The sheet points: every texel (ids of cube_grid.h) and, with refinement, each crossing's near
// and far vertex (ids from crossingBase(), cube_refinement.h). Their sheet depths; their sheet
// points and far images on their rays (a texel's: its centre's, cube_map.h, exact for the
// 90-degree faces), computed when asked for.
struct Texels {
  int n = 0;
  glm::dvec3 light{0.0};  // relative to the maps' origin, as the points
  double farPlane = 0.0;
  std::vector<double> depth;             // texels, then two per crossing
  std::vector<glm::dvec3> crossingRays;  // per crossing, at cube depth 1
  std::size_t size() const { return depth.size(); }
  std::uint32_t crossingBase() const { return cube::texelCount(n); }
  bool far(std::uint32_t id) const { return depth[id] == farPlane; }
  glm::dvec3 direction(std::uint32_t id) const {
    return id < crossingBase() ? cube::texelDirection(n, id) : crossingRays[(id - crossingBase()) / 2];
  }
  glm::dvec3 sheet(std::uint32_t id) const { return light + depth[id] * direction(id); }
  glm::dvec3 farImage(std::uint32_t id) const { return light + farPlane * direction(id); }
};

Texels texels(const CubeDepthMap& cube, const SheetDepthRule& rule, bool blur) {
  const int n = cube.size();
  Texels t{n, cube.lightPosition(), cube.farPlane(), std::vector<double>(std::size_t(kCubeFaces) * n * n), {}};
  for (int f = 0; f < kCubeFaces; ++f) {
    const DepthMap& map = cube.faces[f];
    tbb::parallel_for(0, n, [&](int j) {
      for (int i = 0; i < n; ++i) {
        const double stored = map.at(i, j);
        // sheet_depth.h's steps 1-3 without the border ring (the cube has none).
        t.depth[cube::texelId(n, f, i, j)] = isFarDepth(stored, map.farPlane) ? map.farPlane
                                             : blur ? rule.fromBlurred(blurredDepth(map, i, j))
                                                    : rule.fromStored(stored);
      }
    });
  }
  return t;
}

struct Sheet {
  std::vector<Tri> tris;          // kept sheet triangles, point ids, counter-clockwise from the light
  std::vector<std::uint32_t> cell;  // the cell of each
  std::vector<std::uint8_t> footprint;  // per triangle: not a wall (its far image is part of the cap)
  std::vector<std::uint8_t> boundary;  // per point: a dropped triangle has it as a corner
};

// A refined cell's triangles (cube_refinement.h), kept by one map's rule: those with three far
// vertices dropped.
// A chunk's share of the sheet (triangulate): its kept triangles, their cells and footprint flags,
// and its counts. The boundary flags go straight to the shared array (atomic stores of 1).
struct SheetPart {
  std::vector<Tri> tris;
  std::vector<std::uint32_t> cell;
  std::vector<std::uint8_t> footprint;
  std::size_t refined = 0, dropped = 0, flipped = 0;
};

void markBoundary(std::vector<std::uint8_t>& boundary, std::uint32_t point) {
  std::atomic_ref<std::uint8_t>(boundary[point]).store(1, std::memory_order_relaxed);
}

void triangulateRefined(const cube::Cell& cell, std::uint32_t c, std::uint8_t sides, const cube::CubeRefinement& r,
                        const Texels& t, double centre, bool perfect, SheetPart& out,
                        std::vector<std::uint8_t>& boundary, std::vector<volume::LocalTri>& local) {
  const cube::CubeCell loop = cube::assembleCubeCell(cell, sides, r, t.farPlane, t.n, t.crossingBase(),
                                                     [&](std::uint32_t id) { return t.depth[id]; });
  local.clear();
  volume::CellTriangulator(perfect, local)
      .run(loop.corners, loop.a, loop.b, sides, centre, t.farPlane, nullptr, nullptr, loop.count);
  for (const volume::LocalTri& tri : local) {
    if (tri.v[0]->far && tri.v[1]->far && tri.v[2]->far) {
      for (const volume::CellVertex* v : tri.v) markBoundary(boundary, v->id);
      continue;
    }
    out.tris.push_back({tri.v[0]->id, tri.v[1]->id, tri.v[2]->id});
    out.cell.push_back(c);
    out.footprint.push_back(tri.footprint ? 1 : 0);
  }
}

// The centre depths of the refined cells with 3 or 4 boundary sides, by cell (one batch of rays).
std::unordered_map<std::uint32_t, double> centreDepths(const CubeDepthMap& cube, const cube::Grid& cells,
                                                       const cube::CubeRefinement& r, const SheetDepthRule& rule,
                                                       bool blur, const DepthOracle& oracle, RayBudget& budget) {
  std::vector<std::uint32_t> which;
  std::vector<glm::dvec3> rays;
  for (std::uint32_t c : r.cells) {
    const cube::Cell cell = cells[c];
    if (std::popcount(unsigned(cube::boundarySides(cell, r))) < 3) continue;
    which.push_back(c);
    rays.push_back(cube::cellCentreDirection(cell, cube.size()));
  }
  std::vector<float> depth(rays.size(), DepthMap::kNoHit);
  cube::sampleDirections(cube, rays, oracle, depth, budget);
  std::unordered_map<std::uint32_t, double> out;
  for (std::size_t k = 0; k < which.size(); ++k) out[which[k]] = rule.ofSample(depth[k], blur);
  return out;
}

// The cells [c0, c1) into `out` (see triangulate).
void triangulateCells(const cube::Grid& cells, std::uint32_t c0, std::uint32_t c1, const Texels& t,
                      const glm::dvec3& light, bool perfect, const cube::CubeRefinement* refinement,
                      const std::unordered_map<std::uint32_t, double>& centres, SheetPart& out,
                      std::vector<std::uint8_t>& boundary) {
  std::vector<volume::LocalTri> local;
  for (std::uint32_t c = c0; c < c1; ++c) {
    const cube::Cell cell = cells[c];
    if (const std::uint8_t sides = refinement ? cube::boundarySides(cell, *refinement) : 0) {
      const auto centre = centres.find(c);
      triangulateRefined(cell, c, sides, *refinement, t, centre != centres.end() ? centre->second : t.farPlane, perfect,
                         out, boundary, local);
      ++out.refined;
      continue;
    }
    bool allFar = true;
    for (int corner = 0; corner < cell.cornerCount(); ++corner) allFar = allFar && t.far(cell.corner(corner));
    if (allFar) {  // every triangle dropped whichever the diagonal (no flip counted, as in one map's codes)
      for (int corner = 0; corner < cell.cornerCount(); ++corner) markBoundary(boundary, cell.corner(corner));
      ++out.dropped;
      continue;
    }
    const auto [a, b, cc, d] = cell.v;
    Tri cand[2];
    int k = 0;
    if (cell.triangle) {
      cand[k++] = {a, b, d};
    } else if (perfect && flipDiagonal(t.sheet(a) - light, t.sheet(b) - light, t.sheet(cc) - light, t.sheet(d) - light)) {
      cand[k++] = {a, b, cc};
      cand[k++] = {a, cc, d};
      ++out.flipped;
    } else {
      cand[k++] = {a, b, d};
      cand[k++] = {b, cc, d};
    }
    int kept = 0;
    for (int q = 0; q < k; ++q) {
      const Tri& tri = cand[q];
      if (t.far(tri[0]) && t.far(tri[1]) && t.far(tri[2])) {
        for (std::uint32_t v : tri) markBoundary(boundary, v);
        continue;
      }
      out.tris.push_back(tri);
      out.cell.push_back(c);
      out.footprint.push_back(1);
      ++kept;
    }
    if (kept == 0) ++out.dropped;
  }
}

// Every cell's kept triangles, in cell order: chunks of cells in parallel, joined in chunk order
// (the same mesh for any number of threads).
Sheet triangulate(const cube::Grid& cells, const Texels& t, const glm::dvec3& light, bool perfect,
                  const cube::CubeRefinement* refinement, const std::unordered_map<std::uint32_t, double>& centres,
                  VolumeBuildStats& stats) {
  Sheet s;
  s.boundary.assign(t.size(), 0);
  constexpr std::uint32_t kChunk = 1u << 14;
  const auto count = std::uint32_t(cells.size());
  std::vector<SheetPart> parts((count + kChunk - 1) / kChunk);
  tbb::parallel_for(std::size_t(0), parts.size(), [&](std::size_t k) {
    const auto c0 = std::uint32_t(k) * kChunk;
    triangulateCells(cells, c0, std::min(count, c0 + kChunk), t, light, perfect, refinement, centres, parts[k],
                     s.boundary);
  });
  std::size_t total = 0;
  for (const SheetPart& part : parts) total += part.tris.size();
  s.tris.reserve(total);
  s.cell.reserve(total);
  s.footprint.reserve(total);
  for (SheetPart& part : parts) {
    s.tris.insert(s.tris.end(), part.tris.begin(), part.tris.end());
    s.cell.insert(s.cell.end(), part.cell.begin(), part.cell.end());
    s.footprint.insert(s.footprint.end(), part.footprint.begin(), part.footprint.end());
    stats.refinedCells += part.refined;
    stats.droppedQuads += part.dropped;
    stats.flippedQuads += part.flipped;
    part = {};
  }
  return s;
}

// Vertex ids of the closed mesh: per kept triangle and corner, its sheet vertex and its cap vertex.
struct Vertices {
  std::vector<Tri> sheet, cap;
  std::vector<glm::dvec3> positions;
  std::vector<std::uint32_t> farTexel;  // per vertex: its texel when it is a far vertex, else kNone
};

// A crossing's two vertices lie on one ray, so they share one far image: a far edge's near vertex
// takes its far vertex (on the far cube) as its cap vertex, the one of the run that holds their
// wall; a surface edge's far vertex takes its near vertex's cap vertex. The unused copies are left
// out of the mesh (assemble).
void shareCrossingCaps(const Sheet& s, const cube::CubeRefinement& r, std::uint32_t base,
                       const std::vector<std::uint32_t>& offset,
                       const std::vector<std::pair<std::uint32_t, std::uint8_t>>& corners, Vertices& v) {
  for (std::uint32_t e = 0; e < r.edges.size(); ++e) {
    const std::uint32_t nearId = base + 2 * e, farId = nearId + 1;
    const auto fan = [&](std::uint32_t x) {
      return std::span(corners.data() + offset[x], offset[x + 1] - offset[x]);
    };
    const auto nearFan = fan(nearId), farFan = fan(farId);
    SV_CHECK(!nearFan.empty() && !farFan.empty());  // every crossing is in its two cells' walls
    if (r.edges[e].surface) {
      const std::uint32_t cap = v.cap[nearFan[0].first][nearFan[0].second];
      for (auto [k, c] : farFan) v.cap[k][c] = cap;
      continue;
    }
    std::uint32_t cap = kNone;
    for (auto [k, c] : farFan)
      if (std::find(s.tris[k].begin(), s.tris[k].end(), nearId) != s.tris[k].end()) {
        cap = v.sheet[k][c];
        break;
      }
    SV_CHECK(cap != kNone);
    for (auto [k, c] : nearFan) v.cap[k][c] = cap;
  }
}

// Far vertex rule (cube_volume.h): at a far texel with a dropped triangle around it, runs of kept
// triangles joined across edges that are not gaps or cuts (an edge to a far texel that also has a
// dropped triangle around it) share one vertex, sheet and cap alike; at a far texel without one,
// the sheet keeps one vertex and the cap gets another.
Vertices numberVertices(const Sheet& s, const Texels& t, const cube::CubeRefinement* refinement) {
  const std::size_t texelCount = t.size();
  // The kept triangles around each sheet point, texel or crossing vertex (triangle, corner), in
  // triangle order: one array with an offset per point.
  using Corner = std::pair<std::uint32_t, std::uint8_t>;
  std::vector<std::uint32_t> offset(texelCount + 1, 0);
  for (const Tri& tri : s.tris)
    for (std::uint32_t x : tri) ++offset[x + 1];
  for (std::size_t x = 0; x < texelCount; ++x) offset[x + 1] += offset[x];
  std::vector<Corner> corners(offset.back());
  {
    std::vector<std::uint32_t> fill(offset.begin(), offset.end() - 1);
    for (std::uint32_t k = 0; k < s.tris.size(); ++k)
      for (std::uint8_t c = 0; c < 3; ++c) corners[fill[s.tris[k][c]]++] = {k, c};
  }
  Vertices v;
  v.sheet.resize(s.tris.size());
  v.cap.resize(s.tris.size());
  v.positions.reserve(2 * texelCount);  // a sheet and a cap vertex per texel, far runs aside
  v.farTexel.reserve(2 * texelCount);
  auto add = [&](const glm::dvec3& p, std::uint32_t farTexel) {
    v.positions.push_back(p);
    v.farTexel.push_back(farTexel);
    return std::uint32_t(v.positions.size() - 1);
  };
  std::vector<int> parent;
  for (std::uint32_t x = 0; x < texelCount; ++x) {
    const std::span<const Corner> fan(corners.data() + offset[x], offset[x + 1] - offset[x]);
    if (fan.empty()) continue;
    if (!t.far(x)) {
      const std::uint32_t sheetId = add(t.sheet(x), kNone), capId = add(t.farImage(x), kNone);
      for (auto [k, c] : fan) v.sheet[k][c] = sheetId, v.cap[k][c] = capId;
      continue;
    }
    if (!s.boundary[x]) {
      const std::uint32_t sheetId = add(t.sheet(x), x), capId = add(t.farImage(x), x);
      for (auto [k, c] : fan) v.sheet[k][c] = sheetId, v.cap[k][c] = capId;
      continue;
    }
    parent.resize(fan.size());
    std::iota(parent.begin(), parent.end(), 0);
    auto root = [&](int a) {
      while (parent[a] != a) a = parent[a] = parent[parent[a]];
      return a;
    };
    for (std::size_t a = 0; a < fan.size(); ++a)
      for (std::size_t b = a + 1; b < fan.size(); ++b) {
        const Tri& ta = s.tris[fan[a].first];
        const Tri& tb = s.tris[fan[b].first];
        for (std::uint32_t w : ta) {
          if (w == x || std::find(tb.begin(), tb.end(), w) == tb.end()) continue;
          const bool separates = t.far(w) && s.boundary[w];  // a gap, or a cut between two boundary vertices
          if (!separates) parent[root(int(a))] = root(int(b));
        }
      }
    std::vector<std::uint32_t> runId(fan.size(), kNone);
    for (std::size_t a = 0; a < fan.size(); ++a) {  // runs numbered in the order of their first triangle
      const int r = root(int(a));
      if (runId[r] == kNone) runId[r] = add(t.sheet(x), x);
      v.sheet[fan[a].first][fan[a].second] = v.cap[fan[a].first][fan[a].second] = runId[r];
    }
  }
  if (refinement) shareCrossingCaps(s, *refinement, t.crossingBase(), offset, corners, v);
  return v;
}

// A part's directed edges grouped by their start, for lookups without hashing: the edges leaving
// vertex a are the slots begin[a] .. begin[a + 1] - 1, each with its end and its triangle's third
// corner. Ids are below `vertexCount`.
struct DirectedEdges {
  std::vector<std::uint32_t> begin, end, third;

  DirectedEdges(const std::vector<Tri>& part, std::size_t vertexCount)
      : begin(vertexCount + 1, 0), end(3 * part.size()), third(3 * part.size()) {
    for (const Tri& t : part)
      for (std::uint32_t a : t) ++begin[a + 1];
    std::partial_sum(begin.begin(), begin.end(), begin.begin());
    std::vector<std::uint32_t> fill(begin.begin(), begin.end() - 1);
    for (const Tri& t : part)
      for (int e = 0; e < 3; ++e) {
        const std::uint32_t s = fill[t[e]]++;
        end[s] = t[(e + 1) % 3];
        third[s] = t[(e + 2) % 3];
      }
  }
  // The slot of a -> b, or kNone; of repeated edges (a non-manifold part), the last triangle's.
  std::uint32_t slot(std::uint32_t a, std::uint32_t b) const {
    for (std::uint32_t s = begin[a + 1]; s-- > begin[a];)
      if (end[s] == b) return s;
    return kNone;
  }
  bool boundary(std::uint32_t a, std::uint32_t b) const { return slot(b, a) == kNone; }
  std::uint32_t thirdOf(std::uint32_t a, std::uint32_t b) const {
    const std::uint32_t s = slot(a, b);
    SV_CHECK(s != kNone);
    return third[s];
  }
  int boundaryEdgesLeaving(std::uint32_t a) const {
    int count = 0;
    for (std::uint32_t s = begin[a]; s < begin[a + 1]; ++s) count += boundary(a, end[s]);
    return count;
  }
};

// Face `face`'s part of the cap, flattened: the CDT of far_cap.h over the boundary of its mirrored
// triangles, in the face's texel space (texelOf, by vertex). A vertex where the part touches itself
// (two or more wedges of it around one vertex, the cap across the cube's edge between them) enters
// the CDT once per wedge, as the pinches of one map do, and each wedge's triangles get it back. The
// part is numbered on its own (localOf: a scratch array by vertex, kNone where unused, restored on
// return; the faces' parts have no vertex in common, so they may share it at once).
std::vector<Tri> flattenFace(const std::vector<Tri>& globalPart, const std::vector<glm::dvec2>& texelOfVertex,
                             std::vector<std::uint32_t>& localOf) {
  std::vector<std::uint32_t> global;  // local id -> vertex
  std::vector<Tri> part(globalPart.size());
  for (std::size_t k = 0; k < part.size(); ++k)
    for (int c = 0; c < 3; ++c) {
      std::uint32_t& local = localOf[globalPart[k][c]];
      if (local == kNone) {
        local = std::uint32_t(global.size());
        global.push_back(globalPart[k][c]);
      }
      part[k][c] = local;
    }
  std::vector<glm::dvec2> texelOf(global.size());
  for (std::size_t i = 0; i < global.size(); ++i) {
    texelOf[i] = texelOfVertex[global[i]];
    localOf[global[i]] = kNone;
  }
  const std::uint32_t firstTemp = std::uint32_t(texelOf.size());
  const DirectedEdges directed(part, firstTemp);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;  // boundary edges a -> b of the part
  for (const Tri& t : part)
    for (int e = 0; e < 3; ++e)
      if (directed.boundary(t[e], t[(e + 1) % 3])) edges.push_back({t[e], t[(e + 1) % 3]});
  // The wedge of an edge a -> v's end v: turn around v inside the part to the boundary edge
  // leaving v; that edge's start v is the same wedge's.
  std::vector<std::uint32_t> original;  // temp id - firstTemp -> vertex
  std::vector<std::uint32_t> startId(directed.end.size(), kNone);  // boundary edge's slot -> the id of its start
  std::unordered_map<std::uint32_t, int> wedgesSeen;  // at vertices with two or more wedges
  std::vector<std::uint32_t> endId(edges.size());
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const auto [a, v] = edges[k];
    std::uint32_t x = directed.thirdOf(a, v);
    for (std::size_t steps = 0; !directed.boundary(v, x); ++steps) {
      SV_CHECK_LT(steps, part.size());
      x = directed.thirdOf(x, v);
    }
    std::uint32_t id = v;
    if (directed.boundaryEdgesLeaving(v) > 1 && wedgesSeen[v]++ > 0) {
      id = firstTemp + std::uint32_t(original.size());
      original.push_back(v);
      texelOf.push_back(texelOf[v]);
    }
    endId[k] = id;
    startId[directed.slot(v, x)] = id;
  }
  // The cap's triangles are clockwise in texel space: the region lies right of a -> b, so the
  // CDT's edges (region on the left) run b -> a.
  std::vector<CapEdge> capEdges;
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const std::uint32_t from = endId[k], to = startId[directed.slot(edges[k].first, edges[k].second)];
    SV_CHECK(to != kNone);
    capEdges.push_back({from, to, texelOf[from], texelOf[to]});
  }
  std::vector<Tri> out;
  auto back = [&](std::uint32_t id) { return global[id < firstTemp ? id : original[id - firstTemp]]; };
  for (const auto& t : triangulateCapLoops(capEdges)) out.push_back({back(t[2]), back(t[1]), back(t[0])});
  return out;
}

}  // namespace

double defaultCubeBias(const CubeDepthMap& cube) { return defaultBias(cube.faces[0]); }

namespace {

// The far cap: each kept sheet triangle's image, mirrored, but the walls' (their images have no
// area); with `flatten`, each face's part (its inner cells' images, in its far plane) replaced by
// its CDT (flattenFace).
std::vector<Tri> capTriangles(int n, const cube::Grid& cells, const Sheet& sheet, const Vertices& v, bool flatten,
                              const cube::CubeRefinement* refinement) {
  std::vector<Tri> cap;
  cap.reserve(sheet.tris.size());
  std::array<std::vector<Tri>, kCubeFaces> facePart;
  for (std::size_t k = 0; k < sheet.tris.size(); ++k) {
    if (!sheet.footprint[k]) continue;  // a wall: its far image has no area
    const Tri& c = v.cap[k];
    const Tri mirrored{c[2], c[1], c[0]};
    const cube::Cell cell = cells[sheet.cell[k]];
    if (flatten && cell.inner) facePart[cell.face].push_back(mirrored);
    else cap.push_back(mirrored);
  }
  if (!flatten) return cap;
  // Texel coordinates of the faces' cap vertices, each in its face (an inner cell's corners are
  // its face's texels and the crossings on its edges).
  std::vector<glm::dvec2> texelOf(v.positions.size());
  const std::uint32_t crossingBase = cube::texelCount(n);  // the crossings' points follow the texels
  for (std::size_t k = 0; k < sheet.tris.size(); ++k) {
    const cube::Cell cell = cells[sheet.cell[k]];
    if (!sheet.footprint[k] || !cell.inner) continue;
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t point = sheet.tris[k][c];
      if (point >= crossingBase) {
        texelOf[v.cap[k][c]] = refinement->faceTexel[(point - crossingBase) / 2];
        continue;
      }
      const std::uint32_t id = point - cube::texelId(n, cell.face, 0, 0);
      texelOf[v.cap[k][c]] = {double(id % std::uint32_t(n)), double(id / std::uint32_t(n))};
    }
  }
  std::vector<std::uint32_t> localOf(v.positions.size(), kNone);
  std::array<std::vector<Tri>, kCubeFaces> flat;
  tbb::parallel_for(0, kCubeFaces, [&](int f) {
    if (!facePart[f].empty()) flat[f] = flattenFace(facePart[f], texelOf, localOf);
  });
  for (const std::vector<Tri>& face : flat) cap.insert(cap.end(), face.begin(), face.end());
  return cap;
}

// The mesh: sheet first, cap last (as buildVolume's), without the vertices no triangle uses (a
// flattened cap leaves its inner far images out); splitVertices counts the far texels' extra copies.
void assemble(const Vertices& v, const std::vector<Tri>& cap, VolumeMesh& mesh, VolumeBuildStats& stats) {
  std::vector<std::uint32_t> remap(v.positions.size(), kNone);
  for (const auto* tris : {&v.sheet, &cap})
    for (const Tri& tri : *tris)
      for (std::uint32_t id : tri) remap[id] = 0;
  std::uint32_t next = 0;
  std::unordered_map<std::uint32_t, std::uint32_t> farCopies;
  for (std::uint32_t id = 0; id < remap.size(); ++id) {
    if (remap[id] == kNone) continue;
    remap[id] = next++;
    if (v.farTexel[id] != kNone) ++farCopies[v.farTexel[id]];
  }
  for (const auto& [texel, copies] : farCopies) stats.splitVertices += copies - 1;
  mesh.positions.resize(next);
  for (std::uint32_t id = 0; id < remap.size(); ++id)
    if (remap[id] != kNone) mesh.positions[remap[id]] = v.positions[id];
  mesh.triangles.resize(v.sheet.size() + cap.size());
  std::size_t k = 0;
  for (const auto* tris : {&v.sheet, &cap})
    for (const Tri& tri : *tris) mesh.triangles[k++] = {remap[tri[0]], remap[tri[1]], remap[tri[2]]};
}

// Refinement (cube_refinement.h): the boundary edges, their crossings as points of `t` and the
// centre depths of the cells with 3 or 4 boundary sides; its counts into `stats`.
cube::CubeRefinement refine(const CubeDepthMap& cube, const cube::Grid& cells, const SheetDepthRule& rule,
                            const VolumeBuildOptions& o, Texels& t, std::unordered_map<std::uint32_t, double>& centres,
                            VolumeBuildStats& stats) {
  cube::CubeRefinement r = cube::refineCube(cube, cells, rule, o.blur, t.depth, o.depthOracle, o.refineSteps);
  centres = centreDepths(cube, cells, r, rule, o.blur, o.depthOracle, r.budget);
  t.depth.reserve(t.depth.size() + 2 * r.edges.size());
  t.crossingRays = r.directions;
  for (const Crossing& x : r.crossings) {
    t.depth.push_back(x.nearDepth);
    t.depth.push_back(x.farDepth);
  }
  stats.boundaryEdges = r.edges.size();
  stats.farBoundaryEdges = std::size_t(
      std::count_if(r.edges.begin(), r.edges.end(), [](const cube::BoundaryEdge& e) { return !e.surface; }));
  stats.ambiguousCells = centres.size();
  stats.raysCast = r.budget.rays;
  stats.msRays = r.budget.ms;
  return r;
}

}  // namespace

VolumeBuildResult buildCubeVolume(const CubeDepthMap& cube, const VolumeBuildOptions& options) {
  checkVolumeFitsMemory(cube.faces);  // before the clock, as buildVolume's
  const auto t0 = Clock::now();
  validate(cube, options);
  const int n = cube.size();
  VolumeBuildResult r;
  VolumeBuildStats& stats = r.stats;
  stats.biasUsed = options.bias ? *options.bias : defaultCubeBias(cube);
  const SheetDepthRule rule(cube.faces[0], stats.biasUsed, options.blurOffset);
  const cube::Grid cells(n);
  stats.quads = cells.size();

  const auto tSheet = Clock::now();
  Texels t = texels(cube, rule, options.blur);
  std::optional<cube::CubeRefinement> refinement;
  std::unordered_map<std::uint32_t, double> centres;  // refined cells with 3 or 4 boundary sides
  if (options.refineSteps > 0) {
    const auto tRefine = Clock::now();
    refinement = refine(cube, cells, rule, options, t, centres, stats);
    stats.msRefine = msSince(tRefine);
  }
  const Sheet sheet = triangulate(cells, t, cube.lightPosition(), options.triangulation == Triangulation::Perfect,
                                  refinement ? &*refinement : nullptr, centres, stats);
  const Vertices v = numberVertices(sheet, t, refinement ? &*refinement : nullptr);
  stats.msSheet = msSince(tSheet) - stats.msRefine;
  stats.capTrianglesBefore = std::size_t(std::count(sheet.footprint.begin(), sheet.footprint.end(), 1));

  const auto tCap = Clock::now();
  const std::vector<Tri> cap =
      capTriangles(n, cells, sheet, v, options.flattenCap, refinement ? &*refinement : nullptr);
  stats.msCap = msSince(tCap);
  stats.capTrianglesAfter = cap.size();
  r.mesh.origin = cube.faces[0].origin;
  assemble(v, cap, r.mesh, stats);
  stats.msTotal = msSince(t0);
  return r;
}

}  // namespace shadowvol
