#include "volume/subgrid_cells.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "shadowvol/boundary_edges.h"
#include "shadowvol/check.h"
#include "shadowvol/silhouette_refinement.h"
#include "shadowvol/triangulation.h"
#include "volume/cell_triangulator.h"
#include "volume/quad_codes.h"

namespace shadowvol::volume {
namespace {

struct Node {
  glm::dvec2 texel{0.0};
  glm::dvec3 lv{0.0};       // light-view point (the diagonal rule)
  double depth = 0.0;       // sheet depth (the far plane when far): where its vertex goes
  double rule = 0.0;        // the depth the discontinuity rule reads: without the blur's averaging
  std::uint32_t id = kNone; // vertex; kNone when far
  bool far = false;
  bool virt = false;        // on a side towards an unrefined quad (no ray)
  bool sampled = false;     // its depth comes from the oracle
  std::int64_t fi = 0, fj = 0;  // lattice coordinates (S per texel)
};

// A sub-edge from node p (its lower end) one lattice step along axis to node q.
struct FineEdge {
  std::uint32_t p = 0, q = 0;
  std::uint8_t axis = 0;
  bool boundary = false, surface = false, nearAtP = false;
  std::uint32_t crossing = kNone;  // index among the boundary sub-edges
};

// A sub-cell: its corner nodes A B C D and its side edges 0..3 (A->B, B->C, C->D, D->A).
struct SubCell {
  std::uint32_t node[4];
  std::uint32_t edge[4];
};

constexpr int kSideDqi[4] = {0, 1, 0, -1}, kSideDqj[4] = {-1, 0, 1, 0};

// The depth at fraction f from d0 to d1 along a straight edge of the sheet, as the light's
// projection interpolates it: 1 / depth is linear in texel space for a spot light.
double depthAlongEdge(double d0, double d1, double f, bool perspective) {
  return perspective ? 1.0 / ((1.0 - f) / d0 + f / d1) : (1.0 - f) * d0 + f * d1;
}

class SubgridBuilder {
 public:
  SubgridBuilder(const RefinedQuads& quads, const TexelUse& use, const SheetVertices& vertices, const SheetDepths& sheet,
                 const DepthOracle& oracle, const SubgridOptions& options, std::uint32_t firstVertex)
      : quads_(quads), use_(use), vertices_(vertices), sheet_(sheet), map_(sheet.map()), oracle_(oracle),
        o_(options), s_(options.subdivisions), n1_(options.subdivisions + 1), farPlane_(sheet.rule().farPlane),
        unproject_(sheet.map()), firstVertex_(firstVertex), rowIds_(std::size_t(sheet.map().height)) {}

  SubgridCells run() {
    collectNodes();
    sampleNodes();
    collectEdgesAndCells();
    classifyEdges();
    keepSubCellsUnfolded();
    numberNodeVertices();
    bisect();
    triangulate();
    collectSplits();
    return std::move(out_);
  }

 private:
  int qw() const { return map_.width - 1; }
  std::size_t quadCount() const { return quads_.quads.size(); }

  // Per refined quad g (its index in quads_): node (a, b), horizontal sub-edge (a, b) -> (a + 1, b)
  // and vertical sub-edge (a, b) -> (a, b + 1), a, b = 0..S.
  std::uint32_t& node(std::size_t g, int a, int b) { return quadNodes_[(g * n1_ + std::size_t(b)) * n1_ + std::size_t(a)]; }
  std::uint32_t node(std::size_t g, int a, int b) const { return quadNodes_[(g * n1_ + std::size_t(b)) * n1_ + std::size_t(a)]; }
  std::uint32_t& hEdge(std::size_t g, int a, int b) { return hEdges_[(g * n1_ + std::size_t(b)) * s_ + std::size_t(a)]; }
  std::uint32_t& vEdge(std::size_t g, int a, int b) { return vEdges_[(g * n1_ + std::size_t(a)) * s_ + std::size_t(b)]; }

  // The index in quads_ of quad (qi, qj), or kNone when it is not refined (or off the grid).
  std::uint32_t refinedIndex(int qi, int qj) const {
    if (qi < 0 || qj < 0 || qi >= qw() || qj >= map_.height - 1) return kNone;
    const std::uint32_t quad = std::uint32_t(qj) * std::uint32_t(qw()) + std::uint32_t(qi);
    const auto it = std::lower_bound(quads_.quads.begin(), quads_.quads.end(), quad);
    return (it != quads_.quads.end() && *it == quad) ? std::uint32_t(it - quads_.quads.begin()) : kNone;
  }

  // The lattice node at (fi, fj) (S per texel), or kNone where no refined quad holds it.
  std::uint32_t nodeAt(std::int64_t fi, std::int64_t fj) const {
    if (fi < 0 || fj < 0) return kNone;
    const int qi = int(fi / s_), qj = int(fj / s_), a = int(fi % s_), b = int(fj % s_);
    const int tries[4][4] = {{qi, qj, a, b}, {qi - 1, qj, s_, b}, {qi, qj - 1, a, s_}, {qi - 1, qj - 1, s_, s_}};
    for (int t = 0; t < 4; ++t) {
      if ((t == 1 || t == 3) && a != 0) continue;
      if ((t == 2 || t == 3) && b != 0) continue;
      const std::uint32_t g = refinedIndex(tries[t][0], tries[t][1]);
      if (g != kNone) return node(g, tries[t][2], tries[t][3]);
    }
    return kNone;
  }

  // The sheet vertex of a used texel (kNone for an unused one), numbered as stage 3 does.
  std::uint32_t texelVertex(int i, int j) {
    std::vector<std::uint32_t>& ids = rowIds_[std::size_t(j)];
    if (ids.empty()) {
      ids.assign(std::size_t(map_.width), kNone);
      used_.resize(std::size_t(map_.width));
      const auto [b, e] = use_.row(j, used_.data());
      numberRow(used_.data() + b, ids.data() + b, e - b, std::uint32_t(vertices_.rowVerts[std::size_t(j)]), kNone);
    }
    return ids[std::size_t(i)];
  }

  // Every lattice node of every refined quad, once: a node on a side or corner shared with a
  // refined quad of lower index is that quad's.
  void collectNodes() {
    quadNodes_.assign(quadCount() * n1_ * n1_, kNone);
    nodes_.reserve(quadCount() * std::size_t(s_) * std::size_t(s_) + quadCount() * 2);
    for (std::size_t g = 0; g < quadCount(); ++g) {
      const int qi = int(quads_.quads[g] % std::uint32_t(qw())), qj = int(quads_.quads[g] / std::uint32_t(qw()));
      const std::uint32_t left = refinedIndex(qi - 1, qj), down = refinedIndex(qi, qj - 1);
      const std::uint32_t downLeft = refinedIndex(qi - 1, qj - 1), downRight = refinedIndex(qi + 1, qj - 1);
      for (int b = 0; b <= s_; ++b)
        for (int a = 0; a <= s_; ++a) {
          std::uint32_t k = kNone;
          if (a == 0 && left != kNone) k = node(left, s_, b);
          else if (b == 0 && down != kNone) k = node(down, a, s_);
          else if (a == 0 && b == 0 && downLeft != kNone) k = node(downLeft, s_, s_);
          else if (a == s_ && b == 0 && downRight != kNone) k = node(downRight, 0, s_);
          if (k == kNone) {
            k = std::uint32_t(nodes_.size());
            nodes_.push_back(makeNode(qi, qj, a, b));
          }
          node(g, a, b) = k;
        }
    }
  }

  Node makeNode(int qi, int qj, int a, int b) {
    Node n;
    n.texel = {qi + double(a) / s_, qj + double(b) / s_};
    n.fi = std::int64_t(s_) * qi + a, n.fj = std::int64_t(s_) * qj + b;
    const bool edgeA = a == 0 || a == s_, edgeB = b == 0 || b == s_;
    if (edgeA && edgeB) {  // a texel centre
      const int i = qi + a / s_, j = qj + b / s_;
      n.depth = sheet_.at(i, j);
      n.far = n.depth == farPlane_;
      n.rule = unblurred(i, j, n.depth);
      n.id = n.far ? kNone : texelVertex(i, j);
      SV_CHECK(n.far == (n.id == kNone));  // refinement: the used texels are the non-far ones
      return n;
    }
    if (!edgeA && !edgeB) {
      n.sampled = true;
      return n;
    }
    const int k = b == 0 ? 0 : a == s_ ? 1 : b == s_ ? 2 : 3;
    if (use_.grid().at(qi + kSideDqi[k], qj + kSideDqj[k]) & kRefined) {
      n.sampled = true;
      return n;
    }
    // A virtual node: on side k, at fraction f from corner k to corner k + 1.
    const double f = (k == 0 ? a : k == 1 ? b : k == 2 ? s_ - a : s_ - b) / double(s_);
    const int i0 = qi + kCornerDi[k], j0 = qj + kCornerDj[k];
    const int i1 = qi + kCornerDi[(k + 1) % 4], j1 = qj + kCornerDj[(k + 1) % 4];
    const double d0 = sheet_.at(i0, j0), d1 = sheet_.at(i1, j1);
    SV_CHECK_EQ(d0 == farPlane_, d1 == farPlane_);  // a continuous side (see the header comment)
    n.virt = true;
    n.far = d0 == farPlane_;
    const bool perspective = map_.lightProjection[2][3] != 0.0;
    n.depth = n.far ? farPlane_ : depthAlongEdge(d0, d1, f, perspective);
    n.rule = n.far ? farPlane_ : depthAlongEdge(unblurred(i0, j0, d0), unblurred(i1, j1, d1), f, perspective);
    return n;
  }

  // A texel's depth for the discontinuity rule: its own sample's sheet depth (SheetDepthRule::
  // ofSample, as boundary_edges.h decides on), not the blur's average of its neighbours; its final
  // sheet depth where the blur alone keeps it short of the far plane.
  double unblurred(int i, int j, double sheetDepth) const {
    if (!o_.blur || sheetDepth == farPlane_) return sheetDepth;
    const double u = SheetDepthRule::ring(i, j, map_.width, map_.height) ? farPlane_
                                                                        : sheet_.rule().ofSample(map_.at(i, j), true);
    return u != farPlane_ ? u : sheetDepth;
  }

  // One oracle batch for every node inside a refined quad or between two of them.
  void sampleNodes() {
    std::vector<std::uint32_t> which;
    std::vector<glm::dvec2> ndc;
    for (std::uint32_t k = 0; k < nodes_.size(); ++k)
      if (nodes_[k].sampled) {
        which.push_back(k);
        ndc.push_back(map_.texelNdc(nodes_[k].texel.x, nodes_[k].texel.y));
      }
    std::vector<float> depth(ndc.size(), DepthMap::kNoHit);
    if (!ndc.empty()) {
      const auto t0 = std::chrono::steady_clock::now();
      oracle_(map_, ndc, depth);
      out_.msRays += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    }
    for (std::size_t k = 0; k < which.size(); ++k) {
      Node& n = nodes_[which[k]];
      n.depth = n.rule = sheet_.rule().ofSample(depth[k], o_.blur);
      n.far = n.depth == farPlane_;
    }
    out_.samples = which.size();
    out_.raysCast += which.size();
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nodes_.size(), 2048), [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t k = r.begin(); k != r.end(); ++k)
        nodes_[k].lv = unproject_.lightViewPoint(nodes_[k].texel.x, nodes_[k].texel.y, nodes_[k].depth);
    });
  }

  std::uint32_t newEdge(std::uint32_t p, std::uint32_t q, int axis) {
    FineEdge e;
    e.p = p, e.q = q, e.axis = std::uint8_t(axis);
    edges_.push_back(e);
    return std::uint32_t(edges_.size() - 1);
  }

  // The sub-edges (a side's shared with a refined quad of lower index are that quad's) and sub-cells.
  void collectEdgesAndCells() {
    hEdges_.assign(quadCount() * n1_ * s_, kNone);
    vEdges_.assign(quadCount() * n1_ * s_, kNone);
    edges_.reserve(quadCount() * 2 * n1_ * s_);
    cells_.reserve(quadCount() * std::size_t(s_) * std::size_t(s_));
    for (std::size_t g = 0; g < quadCount(); ++g) {
      const int qi = int(quads_.quads[g] % std::uint32_t(qw())), qj = int(quads_.quads[g] / std::uint32_t(qw()));
      const std::uint32_t left = refinedIndex(qi - 1, qj), down = refinedIndex(qi, qj - 1);
      for (int b = 0; b <= s_; ++b)
        for (int a = 0; a < s_; ++a)
          hEdge(g, a, b) = (b == 0 && down != kNone) ? hEdge(down, a, s_) : newEdge(node(g, a, b), node(g, a + 1, b), 0);
      for (int a = 0; a <= s_; ++a)
        for (int b = 0; b < s_; ++b)
          vEdge(g, a, b) = (a == 0 && left != kNone) ? vEdge(left, s_, b) : newEdge(node(g, a, b), node(g, a, b + 1), 1);
      for (int b = 0; b < s_; ++b)
        for (int a = 0; a < s_; ++a) {
          SubCell c;
          c.node[0] = node(g, a, b), c.node[1] = node(g, a + 1, b), c.node[2] = node(g, a + 1, b + 1);
          c.node[3] = node(g, a, b + 1);
          c.edge[0] = hEdge(g, a, b), c.edge[1] = vEdge(g, a + 1, b), c.edge[2] = hEdge(g, a, b + 1);
          c.edge[3] = vEdge(g, a, b);
          cells_.push_back(c);
        }
    }
  }

  // The depth step from node `at` to the lattice node (fi, fj) next to it (-1: none there, or far).
  double stepTo(const Node& at, std::int64_t fi, std::int64_t fj) const {
    const std::uint32_t k = nodeAt(fi, fj);
    if (k == kNone || nodes_[k].far) return -1.0;
    return std::abs(nodes_[k].rule - at.rule);
  }

  // boundary_edges.h's rules on the lattice, with the texel footprint divided by S.
  void classifyEdges() {
    const TexelFootprint coarse = TexelFootprint::of(map_);
    const TexelFootprint fine{coarse.a / s_, coarse.b / s_};
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, edges_.size(), 1024), [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t k = r.begin(); k != r.end(); ++k) {
        FineEdge& e = edges_[k];
        const Node &p = nodes_[e.p], &q = nodes_[e.q];
        // Along a side towards an unrefined quad (virtual nodes and the side's corners): continuous,
        // as that quad's triangle edge is.
        if ((p.virt || q.virt) && !p.sampled && !q.sampled) continue;
        if (p.far != q.far) {
          e.boundary = true, e.nearAtP = !p.far;
          continue;
        }
        if (p.far) continue;
        const std::int64_t di = e.axis == 0, dj = e.axis == 1;
        const double gP = stepTo(p, p.fi - di, p.fj - dj), gQ = stepTo(q, q.fi + di, q.fj + dj);
        if (discontinuous(p.rule, q.rule, gP, gQ, fine)) e.boundary = e.surface = true, e.nearAtP = p.rule < q.rule;
      }
    });
  }

  // A sub-cell whose two boundary sides are surface edges with the near surface on the same side
  // of both would fold its wall: both sides are made continuous, until none is left
  // (boundary_edges.h, keepWallsUnfolded).
  void keepSubCellsUnfolded() {
    for (bool changed = true; changed;) {
      changed = false;
      for (const SubCell& c : cells_) {
        int split[4], n = 0;
        for (int k = 0; k < 4; ++k)
          if (edges_[c.edge[k]].boundary) split[n++] = k;
        if (n != 2 || !edges_[c.edge[split[0]]].surface || !edges_[c.edge[split[1]]].surface) continue;
        auto nearAtStart = [&](int k) { return k < 2 ? edges_[c.edge[k]].nearAtP : !edges_[c.edge[k]].nearAtP; };
        if (nearAtStart(split[0]) != nearAtStart(split[1])) continue;
        edges_[c.edge[split[0]]].boundary = edges_[c.edge[split[1]]].boundary = false;
        changed = true;
      }
    }
  }

  void numberNodeVertices() {
    std::uint32_t next = firstVertex_;
    std::vector<std::uint32_t> numbered;
    for (std::uint32_t k = 0; k < nodes_.size(); ++k) {
      Node& n = nodes_[k];
      if (n.far || n.id != kNone) continue;
      n.id = next++;
      numbered.push_back(k);
    }
    crossingBase_ = next;
    out_.positions.resize(numbered.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, numbered.size(), 2048), [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t k = r.begin(); k != r.end(); ++k) {
        const Node& n = nodes_[numbered[k]];
        out_.positions[k] = unproject_.worldPoint(n.texel.x, n.texel.y, n.depth);
      }
    });
  }

  // Bisection along every boundary sub-edge, with the ambiguous sub-cells' centres in its first batch.
  void bisect() {
    std::vector<BisectionSegment> segments;
    for (FineEdge& e : edges_) {
      if (!e.boundary) continue;
      e.crossing = std::uint32_t(segments.size());
      const Node &nearN = nodes_[e.nearAtP ? e.p : e.q], &farN = nodes_[e.nearAtP ? e.q : e.p];
      BisectionSegment g;
      g.nearPoint = nearN.texel, g.farPoint = farN.texel;
      g.surface = e.surface;
      // The rule's depths, as refineBoundaryEdges takes (a hit end's is short of the far plane).
      g.nearDepth = g.nearFallback = nearN.rule;
      g.farDepth = e.surface ? farN.rule : farPlane_;
      segments.push_back(g);
      out_.farBoundaryEdges += e.surface ? 0 : 1;
    }
    centreOf_.assign(cells_.size(), kNone);
    for (std::size_t k = 0; k < cells_.size(); ++k) {
      const SubCell& c = cells_[k];
      int n = 0;
      for (int side = 0; side < 4; ++side) n += edges_[c.edge[side]].boundary ? 1 : 0;
      if (n < 3) continue;
      centreOf_[k] = std::uint32_t(centres_.size());
      centres_.push_back(0.25 * (nodes_[c.node[0]].texel + nodes_[c.node[1]].texel + nodes_[c.node[2]].texel +
                                 nodes_[c.node[3]].texel));
    }
    out_.boundaryEdges = segments.size();
    out_.ambiguousCells = centres_.size();
    RayBudget budget;
    if (!segments.empty())
      crossings_ = bisectSegments(map_, segments, sheet_.rule(), o_.blur, oracle_, o_.steps, budget, centres_,
                                  &centreDepths_);
    out_.raysCast += budget.rays;
    out_.msRays += budget.ms;
    // The crossings' two vertices: texel point, light-view points, world positions.
    const std::size_t base = out_.positions.size();
    out_.positions.resize(base + 2 * segments.size());
    crossingVertices_.resize(2 * segments.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, segments.size(), 512), [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t k = r.begin(); k != r.end(); ++k) {
        const glm::dvec2 t = segments[k].nearPoint + crossings_[k].s * (segments[k].farPoint - segments[k].nearPoint);
        for (int side = 0; side < 2; ++side) {
          CellVertex& v = crossingVertices_[2 * k + std::size_t(side)];
          v.texel = t;
          v.depth = side == 0 ? crossings_[k].nearDepth : crossings_[k].farDepth;
          v.id = crossingBase_ + 2 * std::uint32_t(k) + std::uint32_t(side);
          v.far = side == 1 && !segments[k].surface;
          v.lv = unproject_.lightViewPoint(t.x, t.y, v.depth);
          out_.positions[base + 2 * k + std::size_t(side)] = unproject_.worldPoint(t.x, t.y, v.depth);
        }
      }
    });
  }

  // The sub-cells' triangles, in blocks of quads in parallel, joined in quad order.
  void triangulate() {
    constexpr std::size_t kBlock = 32;
    const std::size_t cellsPerQuad = std::size_t(s_) * std::size_t(s_);
    const std::size_t blocks = (quadCount() + kBlock - 1) / kBlock;
    std::vector<std::vector<Tri>> triangles(blocks);
    std::vector<std::vector<CapEdge>> capEdges(blocks);
    std::vector<std::size_t> footprint(blocks, 0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, blocks, 1), [&](const tbb::blocked_range<std::size_t>& r) {
      std::vector<LocalTri> tris;
      for (std::size_t block = r.begin(); block != r.end(); ++block) {
        const std::size_t end = std::min(quadCount(), (block + 1) * kBlock) * cellsPerQuad;
        for (std::size_t k = block * kBlock * cellsPerQuad; k < end; ++k) {
          footprint[block] += triangulateCell(k, tris, triangles[block], capEdges[block]);
        }
      }
    });
    for (std::size_t block = 0; block < blocks; ++block) {
      out_.triangles.insert(out_.triangles.end(), triangles[block].begin(), triangles[block].end());
      out_.capEdges.insert(out_.capEdges.end(), capEdges[block].begin(), capEdges[block].end());
      out_.footprintTriangles += footprint[block];
    }
  }

  // One sub-cell's kept triangles and cap edges (its local triangles point into this frame); returns
  // how many of the kept ones are not walls.
  std::size_t triangulateCell(std::size_t k, std::vector<LocalTri>& tris, std::vector<Tri>& triangles,
                              std::vector<CapEdge>& capEdges) const {
    const SubCell& c = cells_[k];
    CellVertex corners[4], a[4], b[4];
    std::uint8_t sides = 0;
    for (int side = 0; side < 4; ++side) {
      const Node& n = nodes_[c.node[side]];
      CellVertex& v = corners[side];
      v.id = n.id, v.far = n.far, v.texel = n.texel, v.lv = n.lv, v.depth = n.depth;
      const FineEdge& e = edges_[c.edge[side]];
      if (!e.boundary) continue;
      sides |= std::uint8_t(1 << side);
      const CellVertex& nearV = crossingVertices_[2 * std::size_t(e.crossing)];
      const CellVertex& farV = crossingVertices_[2 * std::size_t(e.crossing) + 1];
      const bool forward = side < 2;  // sides 0, 1 run from the edge's lower end
      const bool cornerIsNear = forward == e.nearAtP;
      a[side] = cornerIsNear ? nearV : farV;
      b[side] = cornerIsNear ? farV : nearV;
    }
    tris.clear();
    if (sides == 0) {
      plainCell(corners, tris);
    } else {
      const double centreDepth = centreOf_[k] != kNone ? centreDepths_[centreOf_[k]] : farPlane_;
      CellTriangulator(o_.perfect, tris).run(corners, a, b, sides, centreDepth, farPlane_);
    }
    keepCellTriangles(tris, o_.exact, triangles, capEdges, nullptr);
    return std::size_t(std::count_if(tris.begin(), tris.end(), [&](const LocalTri& t) {
      return t.footprint && !(o_.exact && t.v[0]->far && t.v[1]->far && t.v[2]->far);
    }));
  }

  // A sub-cell without a boundary side: all far (dropped by the exact cap) or all hit, two
  // triangles by the diagonal rule, as the texel grid's quads.
  void plainCell(const CellVertex* corners, std::vector<LocalTri>& tris) const {
    const bool far = corners[0].far;
    for (int k = 1; k < 4; ++k) SV_CHECK_EQ(corners[k].far, far);  // a hit-far side is a boundary edge
    if (far && o_.exact) return;
    const int f = (o_.perfect && flipDiagonal(corners[0].lv, corners[1].lv, corners[2].lv, corners[3].lv)) ? 1 : 0;
    for (int t = 0; t < 2; ++t) {
      const int* cs = kTriCorners[f][t];
      tris.push_back({{&corners[cs[0]], &corners[cs[1]], &corners[cs[2]]}, true});
    }
  }

  // The sides with virtual nodes on hit corners: what splitSheetTriangles splits.
  void collectSplits() {
    for (std::size_t g = 0; g < quadCount(); ++g) {
      const int qi = int(quads_.quads[g] % std::uint32_t(qw())), qj = int(quads_.quads[g] / std::uint32_t(qw()));
      for (int k = 0; k < 4; ++k) {
        const int ni = qi + kSideDqi[k], nj = qj + kSideDqj[k];
        if (use_.grid().at(ni, nj) & kRefined) continue;
        // Side k's nodes from corner k to corner k + 1: (m, 0), (S, m), (S - m, S), (0, S - m).
        auto sideNode = [&](int m) -> const Node& {
          const int a = k == 0 ? m : k == 1 ? s_ : k == 2 ? s_ - m : 0;
          const int b = k == 0 ? 0 : k == 1 ? m : k == 2 ? s_ : s_ - m;
          return nodes_[node(g, a, b)];
        };
        if (sideNode(0).far) continue;  // a far side: its nodes are far and unused
        SV_CHECK(ni >= 0 && nj >= 0 && ni < qw() && nj < map_.height - 1);  // the ring is far
        SideSplit split;
        split.quad = std::uint32_t(nj) * std::uint32_t(qw()) + std::uint32_t(ni);
        split.from = sideNode(0).id, split.to = sideNode(s_).id;
        for (int m = 1; m < s_; ++m) split.points.push_back(sideNode(m).id);
        out_.splits.push_back(std::move(split));
      }
    }
    std::stable_sort(out_.splits.begin(), out_.splits.end(),
                     [](const SideSplit& x, const SideSplit& y) { return x.quad < y.quad; });
  }

  const RefinedQuads& quads_;
  const TexelUse& use_;
  const SheetVertices& vertices_;
  const SheetDepths& sheet_;
  const DepthMap& map_;
  const DepthOracle& oracle_;
  const SubgridOptions o_;
  const int s_;
  const std::size_t n1_;  // S + 1
  const double farPlane_;
  const TexelUnprojector unproject_;
  const std::uint32_t firstVertex_;
  std::uint32_t crossingBase_ = 0;
  std::vector<std::vector<std::uint32_t>> rowIds_;
  std::vector<std::uint8_t> used_;
  std::vector<std::uint32_t> quadNodes_, hEdges_, vEdges_;
  std::vector<Node> nodes_;
  std::vector<FineEdge> edges_;
  std::vector<SubCell> cells_;
  std::vector<glm::dvec2> centres_;
  std::vector<std::uint32_t> centreOf_;       // per sub-cell: its centre sample, or kNone
  std::vector<CellVertex> crossingVertices_;  // per boundary sub-edge: near, far
  std::vector<double> centreDepths_;
  std::vector<Crossing> crossings_;
  SubgridCells out_;
};

}  // namespace

SubgridCells buildSubgridCells(const RefinedQuads& quads, const TexelUse& use, const SheetVertices& vertices,
                               const SheetDepths& sheet, const DepthOracle& oracle, const SubgridOptions& options,
                               std::uint32_t firstVertex) {
  SV_CHECK_GE(options.subdivisions, 2);
  SV_CHECK_GE(options.steps, 1);
  return SubgridBuilder(quads, use, vertices, sheet, oracle, options, firstVertex).run();
}

void splitSheetTriangles(const std::vector<SideSplit>& splits, const Scratch<std::uint32_t>& quadTri,
                         VolumeMesh& mesh) {
  std::vector<std::uint32_t> polygon;
  for (std::size_t g = 0; g < splits.size();) {
    std::size_t end = g;
    while (end < splits.size() && splits[end].quad == splits[g].quad) ++end;
    std::size_t applied = 0;
    for (std::uint32_t t = 0; t < 2; ++t) {  // an unrefined quad next to a refined one keeps both triangles
      const std::size_t slot = quadTri[splits[g].quad] + t;
      const Tri tri = mesh.triangles[slot];
      polygon.clear();
      for (int m = 0; m < 3; ++m) {
        const std::uint32_t u = tri[m], v = tri[(m + 1) % 3];
        polygon.push_back(u);
        for (std::size_t k = g; k < end; ++k) {
          const SideSplit& s = splits[k];
          if (s.from == u && s.to == v) polygon.insert(polygon.end(), s.points.begin(), s.points.end());
          else if (s.from == v && s.to == u) polygon.insert(polygon.end(), s.points.rbegin(), s.points.rend());
          else continue;
          ++applied;
        }
      }
      if (polygon.size() == 3) continue;
      const auto centroid = std::uint32_t(mesh.positions.size());
      mesh.positions.push_back((mesh.positions[tri[0]] + mesh.positions[tri[1]] + mesh.positions[tri[2]]) / 3.0);
      mesh.triangles[slot] = {centroid, polygon[0], polygon[1]};
      for (std::size_t k = 1; k < polygon.size(); ++k)
        mesh.triangles.push_back({centroid, polygon[k], polygon[(k + 1) % polygon.size()]});
    }
    SV_CHECK_EQ(applied, end - g);  // every split side belongs to one of the quad's triangles
    g = end;
  }
}

}  // namespace shadowvol::volume
