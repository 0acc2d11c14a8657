#include "volume/subgrid_cells.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <chrono>
#include <cmath>
#include <limits>
#include <span>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "shadowvol/boundary_edges.h"
#include "shadowvol/check.h"
#include "shadowvol/silhouette_refinement.h"
#include "shadowvol/triangulation.h"
#include "volume/cell_triangulator.h"
#include "volume/quad_codes.h"
#include "volume/rim_bias.h"
#include "volume/sheet_depths.h"
#include "volume/subgrid_bias.h"

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
  std::uint32_t preset = kNone;    // a plain quad's crossing on it: index into presets_
};

// A sub-edge on a side towards a plain refined quad that holds that side's crossing (adaptive).
struct PresetCrossing {
  std::uint32_t edge = 0;      // the FineEdge
  std::size_t plainEdge = 0;   // the texel grid's boundary edge
  bool nearAtP = false;        // the FineEdge's p end is on the near side
};

// A sub-cell: its corner nodes A B C D and its side edges 0..3 (A->B, B->C, C->D, D->A).
struct SubCell {
  std::uint32_t node[4];
  std::uint32_t edge[4];
};

constexpr int kSideDqi[4] = {0, 1, 0, -1}, kSideDqj[4] = {-1, 0, 1, 0};

class SubgridBuilder {
 public:
  SubgridBuilder(const RefinedQuads& quads, const TexelUse& use, const SheetVertices& vertices, const SheetDepths& sheet,
                 const DepthOracle& oracle, const SubgridOptions& options, std::uint32_t firstVertex,
                 const PlainRefinement* plain)
      : quads_(quads), use_(use), vertices_(vertices), sheet_(sheet), map_(sheet.map()), oracle_(oracle),
        o_(options), s_(options.subdivisions), n1_(options.subdivisions + 1), farPlane_(sheet.rule().farPlane),
        perspective_(sheet.map().lightProjection[2][3] != 0.0), unproject_(sheet.map()), firstVertex_(firstVertex),
        plain_(plain), rowIds_(std::size_t(sheet.map().height)) {}

  SubgridCells run() {
    collectNodes();
    sampleNodes();
    out_.gridded.assign(quadCount(), 1);
    if (plain_) {
      chooseGriddedQuads();
      presetPlainSides();
    }
    out_.griddedQuads = std::size_t(std::count(out_.gridded.begin(), out_.gridded.end(), 1));
    collectEdgesAndCells();
    classifyEdges();
    applyPresets();
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
    if (!(use_.grid().at(qi, qj) & kRefined)) return kNone;  // the quad codes know, without a search
    const std::uint32_t quad = std::uint32_t(qj) * std::uint32_t(qw()) + std::uint32_t(qi);
    const auto it = std::lower_bound(quads_.quads.begin(), quads_.quads.end(), quad);
    return (it != quads_.quads.end() && *it == quad) ? std::uint32_t(it - quads_.quads.begin()) : kNone;
  }

  // The index of quad (qi, qj) when it is on the sub-grid, else kNone.
  std::uint32_t griddedIndex(int qi, int qj) const {
    const std::uint32_t g = refinedIndex(qi, qj);
    return (g != kNone && out_.gridded[g]) ? g : kNone;
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
      const int qi = quadI(g), qj = quadJ(g);
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
    setOnContinuousSide(qi, qj, k, (k == 0 ? a : k == 1 ? b : k == 2 ? s_ - a : s_ - b) / double(s_), n);
    return n;
  }

  // Makes n a virtual node on continuous side k of quad (qi, qj), at fraction f from corner k to
  // corner k + 1: on the sheet triangle's edge between them.
  void setOnContinuousSide(int qi, int qj, int k, double f, Node& n) const {
    const int i0 = qi + kCornerDi[k], j0 = qj + kCornerDj[k];
    const int i1 = qi + kCornerDi[(k + 1) % 4], j1 = qj + kCornerDj[(k + 1) % 4];
    const double d0 = sheet_.at(i0, j0), d1 = sheet_.at(i1, j1);
    SV_CHECK_EQ(d0 == farPlane_, d1 == farPlane_);  // a continuous side (see the header comment)
    n.virt = true, n.sampled = false;
    n.far = d0 == farPlane_;
    n.depth = n.far ? farPlane_ : depthAlongEdge(d0, d1, f, perspective_);
    n.rule = n.far ? farPlane_ : depthAlongEdge(unblurred(i0, j0, d0), unblurred(i1, j1, d1), f, perspective_);
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

  // One oracle batch for every node inside a refined quad or between two of them, and with a bias
  // the centres of the sub-cells that hold such a node (lowerSampledBias).
  void sampleNodes() {
    std::vector<std::uint32_t> which;
    std::vector<glm::dvec2> ndc;
    for (std::uint32_t k = 0; k < nodes_.size(); ++k)
      if (nodes_[k].sampled) {
        which.push_back(k);
        ndc.push_back(map_.texelNdc(nodes_[k].texel.x, nodes_[k].texel.y));
      }
    std::vector<std::array<std::uint32_t, 4>> biasCells;
    if (sheet_.rule().bias > 0.0) biasCells = sampledSubCells();
    for (const auto& c : biasCells) {
      const glm::dvec2 t = 0.25 * (nodes_[c[0]].texel + nodes_[c[1]].texel + nodes_[c[2]].texel + nodes_[c[3]].texel);
      ndc.push_back(map_.texelNdc(t.x, t.y));
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
    if (!biasCells.empty()) lowerSampledBias(biasCells, std::span<const float>(depth).subspan(which.size()));
    out_.samples = which.size();
    out_.biasSamples = biasCells.size();
    out_.raysCast += ndc.size();
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nodes_.size(), 2048), [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t k = r.begin(); k != r.end(); ++k)
        nodes_[k].lv = unproject_.lightViewPoint(nodes_[k].texel.x, nodes_[k].texel.y, nodes_[k].depth);
    });
  }

  // The corner nodes (A B C D) of every sub-cell of a refined quad that has a sampled corner.
  std::vector<std::array<std::uint32_t, 4>> sampledSubCells() const {
    std::vector<std::array<std::uint32_t, 4>> cells;
    for (std::size_t g = 0; g < quadCount(); ++g)
      for (int b = 0; b < s_; ++b)
        for (int a = 0; a < s_; ++a) {
          const std::array<std::uint32_t, 4> c = {node(g, a, b), node(g, a + 1, b), node(g, a + 1, b + 1), node(g, a, b + 1)};
          if (std::any_of(c.begin(), c.end(), [&](std::uint32_t k) { return nodes_[k].sampled; })) cells.push_back(c);
        }
    return cells;
  }

  // Each sampled hit node keeps the most bias that a sub-cell holding it needs (subgrid_bias.h,
  // from its `centre` sample); its depth moves towards the light by the rest. Its rule depth (the
  // discontinuity rule's) keeps the full bias, as the texel centres' does.
  void lowerSampledBias(const std::vector<std::array<std::uint32_t, 4>>& cells, std::span<const float> centre) {
    const SheetDepthRule& rule = sheet_.rule();
    std::vector<double> need(cells.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, cells.size(), 1024), [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t c = r.begin(); c != r.end(); ++c) {
        const std::array<double, 4> corners = {nodes_[cells[c][0]].depth, nodes_[cells[c][1]].depth,
                                               nodes_[cells[c][2]].depth, nodes_[cells[c][3]].depth};
        const double mid = rule.ofSample(centre[c], o_.blur);
        need[c] = subCellBias(
            corners, mid, [&] { return foldBound(cells[c], mid); }, rule.bias, s_, perspective_, farPlane_);
      }
    });
    std::vector<double> keep(nodes_.size(), 0.0);
    for (std::size_t c = 0; c < cells.size(); ++c)
      for (std::uint32_t k : cells[c]) keep[k] = std::max(keep[k], need[c]);
    for (std::uint32_t k = 0; k < nodes_.size(); ++k) {
      Node& n = nodes_[k];
      if (n.sampled && !n.far) n.depth = std::max(rule.nearPlane, n.depth - (rule.bias - keep[k]));
    }
  }

  // How far a straight fold inside sub-cell c could lie behind the sheet through its corners, from
  // the lattice lines along its four sides (subgrid_bias.h): a quarter of the change between the
  // steps on either side of the sub-cell (in inverse depth for a spot light, scaled back to depth
  // at `depth`); +inf where a line leaves the lattice or meets a far node.
  double foldBound(const std::array<std::uint32_t, 4>& c, double depth) const {
    const std::int64_t fi = nodes_[c[0]].fi, fj = nodes_[c[0]].fj;
    constexpr double kUnknown = std::numeric_limits<double>::infinity();
    double most = 0.0;
    const std::int64_t lines[4][4] = {{fi, fj, 1, 0}, {fi, fj + 1, 1, 0}, {fi, fj, 0, 1}, {fi + 1, fj, 0, 1}};
    for (const auto& l : lines) {
      double d[4];
      for (int m = 0; m < 4; ++m) {
        const std::uint32_t k = nodeAt(l[0] + (m - 1) * l[2], l[1] + (m - 1) * l[3]);
        if (k == kNone || nodes_[k].far) return kUnknown;
        d[m] = perspective_ ? 1.0 / nodes_[k].depth : nodes_[k].depth;
      }
      const double change = std::abs((d[3] - d[2]) - (d[1] - d[0])) / 4.0;
      most = std::max(most, perspective_ ? change * depth * depth : change);
    }
    return most;
  }

  std::uint32_t newEdge(std::uint32_t p, std::uint32_t q, int axis) {
    FineEdge e;
    e.p = p, e.q = q, e.axis = std::uint8_t(axis);
    edges_.push_back(e);
    return std::uint32_t(edges_.size() - 1);
  }

  // Side k's node m (0 at corner k, S at corner k + 1): (m, 0), (S, m), (S - m, S), (0, S - m).
  std::uint32_t sideNode(std::size_t g, int k, int m) const {
    return k == 0 ? node(g, m, 0) : k == 1 ? node(g, s_, m) : k == 2 ? node(g, s_ - m, s_) : node(g, 0, s_ - m);
  }
  // Side k's sub-edge between its nodes m and m + 1 (its p end is node m on sides 0 and 1).
  std::uint32_t sideSubEdge(std::size_t g, int k, int m) {
    return k == 0 ? hEdge(g, m, 0) : k == 1 ? vEdge(g, s_, m) : k == 2 ? hEdge(g, s_ - m - 1, s_) : vEdge(g, 0, s_ - m - 1);
  }
  int quadI(std::size_t g) const { return int(quads_.quads[g] % std::uint32_t(qw())); }
  int quadJ(std::size_t g) const { return int(quads_.quads[g] / std::uint32_t(qw())); }

  // The plain crossing on boundary side k of quad g: its boundary edge, its fraction along the side
  // from corner k, whether corner k is on the near side, and the side's sub-edge that holds it.
  struct SideCrossing {
    std::size_t edge = 0;
    double f = 0.5;
    bool cornerNear = false;
    int sub = 0;
  };
  SideCrossing sideCrossing(std::size_t g, int k) const {
    const int qi = quadI(g), qj = quadJ(g);
    const SideEdge side = sideEdge(qi, qj, k);
    const std::size_t e = plain_->edges.find(side.i, side.j, side.axis);
    SV_CHECK_LT(e, plain_->edges.edges.size());
    const BoundaryEdge& edge = plain_->edges.edges[e];
    const glm::dvec2 t = Crossing::texel(edge, plain_->refinement.crossings[e].s);
    const double f = k == 0 ? t.x - qi : k == 1 ? t.y - qj : k == 2 ? qi + 1 - t.x : qj + 1 - t.y;
    return {e, f, side.forward == edge.nearAtP, std::clamp(int(std::floor(f * s_)), 0, s_ - 1)};
  }

  // The adaptive choice: quad g stays plain when it has two boundary sides, neither crossing lies on
  // a lattice node, and every node the oracle sampled on its sides and inside it lies on the surface
  // of its plain triangulation (onPlainSurface); a node that does not puts every quad holding it on
  // the sub-grid, so that a side between a plain and a gridded quad agrees with the plain one.
  void chooseGriddedQuads() {
    const TexelFootprint footprint = TexelFootprint::of(map_);
    std::vector<std::vector<std::uint32_t>> offSurface(quadCount());
    std::vector<std::uint8_t> forced(quadCount(), 0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, quadCount(), 64), [&](const tbb::blocked_range<std::size_t>& r) {
      RefinedCell cell;
      std::vector<LocalTri> tris;
      for (std::size_t g = r.begin(); g != r.end(); ++g) {
        const std::uint8_t sides = quads_.sides[g];
        if (std::popcount(unsigned(sides)) != 2 || crossingOnNode(g)) {
          forced[g] = 1;
          continue;
        }
        assembleCell(quadI(g), quadJ(g), sides, sheet_, plain_->edges, plain_->refinement, unproject_, nullptr, 0, cell);
        if (chordBends(g, cell)) {
          forced[g] = 1;
          continue;
        }
        tris.clear();
        CellTriangulator(o_.perfect, tris).run(cell.corners, cell.a, cell.b, sides, farPlane_, farPlane_);
        for (int b = 0; b <= s_; ++b)
          for (int a = 0; a <= s_; ++a) {
            const std::uint32_t k = node(g, a, b);
            if (nodes_[k].sampled && !onPlainSurface(tris, nodes_[k], footprint)) offSurface[g].push_back(k);
          }
      }
    });
    std::vector<std::uint8_t> off(nodes_.size(), 0);
    for (const std::vector<std::uint32_t>& list : offSurface)
      for (std::uint32_t k : list) off[k] = 1;
    for (std::size_t g = 0; g < quadCount(); ++g) {
      bool any = forced[g] != 0;
      for (std::size_t k = 0; k < n1_ * n1_ && !any; ++k) any = off[quadNodes_[g * n1_ * n1_ + k]] != 0;
      out_.gridded[g] = any ? 1 : 0;
    }
    keepPresetSurfaceCornersApart();
  }

  // Whether the outline bends away from quad g's straight wall: its chord point (where the outline
  // crosses the wall's perpendicular bisector) lies off it by more than kChordBendErrors times its
  // own bisection error.
  bool chordBends(std::size_t g, const RefinedCell& cell) const {
    if (!plain_->chords) return false;
    const std::size_t k = plain_->chords->ofQuad[g];
    if (k == ChordPoints::kNone) return false;
    int split[2], n = 0;
    for (int side = 0; side < 4 && n < 2; ++side)
      if (quads_.sides[g] >> side & 1) split[n++] = side;
    const glm::dvec2 x = cell.a[split[0]].texel, y = cell.a[split[1]].texel, m = plain_->chords->texel(k);
    const glm::dvec2 d = y - x;
    const double length = std::hypot(d.x, d.y);
    if (length == 0.0) return false;
    const double off = std::abs(cross2(d, m - x)) / length;
    const BisectionSegment& segment = plain_->chords->segments[k];
    const double error = glm::length(segment.farPoint - segment.nearPoint) * std::ldexp(1.0, -(plain_->steps + 1));
    return off > kChordBendErrors * error;
  }

  // Whether a crossing on one of quad g's boundary sides lies on a lattice node (possible when K <
  // log2 S), where the side's nodes could not be put on one side of it.
  bool crossingOnNode(std::size_t g) const {
    for (int k = 0; k < 4; ++k) {
      if (!(quads_.sides[g] >> k & 1)) continue;
      const double x = sideCrossing(g, k).f * s_;
      if (std::abs(x - std::round(x)) < 1e-9) return true;
    }
    return false;
  }

  // A gridded quad's sub-cell at a corner between two boundary sides towards plain quads could hold
  // two preset surface crossings whose wall would fold (keepSubCellsUnfolded cannot make preset
  // sub-edges continuous): the plain quads across such sides go on the sub-grid too, until none is left.
  void keepPresetSurfaceCornersApart() {
    for (bool changed = true; changed;) {
      changed = false;
      for (std::size_t g = 0; g < quadCount(); ++g) {
        if (!out_.gridded[g]) continue;
        for (int k = 0; k < 4; ++k) {
          const int k2 = (k + 1) % 4;
          const std::uint32_t h = plainNeighbour(g, k), h2 = plainNeighbour(g, k2);
          if (h == kNone || h2 == kNone || !surfaceSide(g, k) || !surfaceSide(g, k2)) continue;
          out_.gridded[h] = out_.gridded[h2] = 1;
          changed = true;
        }
      }
    }
  }

  // The plain refined quad across side k of quad g, or kNone.
  std::uint32_t plainNeighbour(std::size_t g, int k) const {
    const std::uint32_t h = refinedIndex(quadI(g) + kSideDqi[k], quadJ(g) + kSideDqj[k]);
    return (h != kNone && !out_.gridded[h]) ? h : kNone;
  }
  bool surfaceSide(std::size_t g, int k) const {
    if (!(quads_.sides[g] >> k & 1)) return false;
    return plain_->edges.edges[sideCrossing(g, k).edge].surface;
  }

  // Whether node n lies on the surface of a plain quad's triangles `tris`: far where a footprint
  // triangle holding it is far, else within kPlainQuadFootprints footprints of its depth there and,
  // with a sheet bias, not behind it.
  bool onPlainSurface(const std::vector<LocalTri>& tris, const Node& n, const TexelFootprint& footprint) const {
    for (const LocalTri& t : tris) {
      if (!t.footprint) continue;
      const glm::dvec2 p0 = t.v[0]->texel, e1 = t.v[1]->texel - p0, e2 = t.v[2]->texel - p0;
      const double area = cross2(e1, e2);
      if (area == 0.0) continue;
      const double l1 = cross2(n.texel - p0, e2) / area, l2 = cross2(e1, n.texel - p0) / area, l0 = 1.0 - l1 - l2;
      constexpr double kInside = -1e-9;
      if (l0 < kInside || l1 < kInside || l2 < kInside) continue;
      const int farCount = int(t.v[0]->far) + int(t.v[1]->far) + int(t.v[2]->far);
      if (farCount == 3 && n.far) return true;
      if (farCount != 0 || n.far) continue;
      const double d0 = t.v[0]->depth, d1 = t.v[1]->depth, d2 = t.v[2]->depth;
      const double depth = perspective_ ? 1.0 / (l0 / d0 + l1 / d1 + l2 / d2) : l0 * d0 + l1 * d1 + l2 * d2;
      // With a sheet bias B (and no blur, whose sheet is meant to leave the surface) the plain
      // sheet must stay behind the captured surface, the node's rule depth less B: a node whose
      // surface lies behind it (a valley between a steep and a flat surface that the discontinuity
      // rule split) would be acne, a lit point inside the volume.
      const double bias = sheet_.rule().bias;
      if (bias > 0.0 && !o_.blur && n.rule - bias > depth) return false;
      if (std::abs(n.depth - depth) <= kPlainQuadFootprints * footprint.at(std::min(depth, n.depth))) return true;
    }
    return false;
  }

  // The nodes of every side between a gridded quad and a plain refined one are put on the plain
  // quad's boundary (no ray), and the sub-edge holding a boundary side's crossing takes that
  // crossing (applyPresets), so that both quads share every vertex of the side.
  void presetPlainSides() {
    for (std::size_t g = 0; g < quadCount(); ++g) {
      if (!out_.gridded[g]) continue;
      const int qi = quadI(g), qj = quadJ(g);
      for (int k = 0; k < 4; ++k) {
        if (plainNeighbour(g, k) == kNone) continue;
        const bool boundary = quads_.sides[g] >> k & 1;
        SideCrossing x;
        if (boundary) {
          x = sideCrossing(g, k);
          pending_.push_back({std::uint32_t(g), std::uint8_t(k), x});
        }
        for (int m = 1; m < s_; ++m) {
          Node& n = nodes_[sideNode(g, k, m)];
          if (boundary) setOnBoundarySide(qi, qj, k, double(m) / s_, x, n);
          else setOnContinuousSide(qi, qj, k, double(m) / s_, n);
          n.lv = unproject_.lightViewPoint(n.texel.x, n.texel.y, n.depth);
        }
      }
    }
  }

  // Makes n a virtual node on boundary side k of quad (qi, qj), at fraction f from corner k, on the
  // plain quad's boundary: between the corner and the crossing's vertex on its side.
  void setOnBoundarySide(int qi, int qj, int k, double f, const SideCrossing& x, Node& n) const {
    const Crossing& c = plain_->refinement.crossings[x.edge];
    const bool surface = plain_->edges.edges[x.edge].surface;
    const bool before = f < x.f;  // on corner k's side of the crossing
    const int corner = before ? k : (k + 1) % 4;
    const bool nearSide = before == x.cornerNear;
    n.virt = true, n.sampled = false;
    if (!nearSide && !surface) {
      n.far = true, n.depth = n.rule = farPlane_;
      return;
    }
    const int i = qi + kCornerDi[corner], j = qj + kCornerDj[corner];
    const double dc = sheet_.at(i, j), rc = unblurred(i, j, dc);
    const double dx = nearSide ? c.nearDepth : c.farDepth, rx = nearSide ? c.sampleNearDepth() : c.farDepth;
    SV_CHECK(dc != farPlane_);  // the near side's corner is hit, and so is a surface edge's far one
    const double t = before ? f / x.f : (f - x.f) / (1.0 - x.f);
    n.far = false;
    n.depth = before ? depthAlongEdge(dc, dx, t, perspective_) : depthAlongEdge(dx, dc, t, perspective_);
    n.rule = before ? depthAlongEdge(rc, rx, t, perspective_) : depthAlongEdge(rx, rc, t, perspective_);
  }

  // The sub-edges that hold a plain quad's crossing: boundary edges with that crossing.
  void applyPresets() {
    for (const Pending& p : pending_) {
      const std::uint32_t id = sideSubEdge(p.g, p.k, p.x.sub);
      FineEdge& e = edges_[id];
      e.boundary = true;
      e.surface = plain_->edges.edges[p.x.edge].surface;
      e.nearAtP = (p.k < 2) == p.x.cornerNear;
      e.preset = std::uint32_t(presets_.size());
      presets_.push_back({id, p.x.edge, e.nearAtP});
    }
  }

  // The sub-edges (a side's shared with a gridded quad of lower index are that quad's) and sub-cells.
  void collectEdgesAndCells() {
    hEdges_.assign(quadCount() * n1_ * s_, kNone);
    vEdges_.assign(quadCount() * n1_ * s_, kNone);
    edges_.reserve(quadCount() * 2 * n1_ * s_);
    cells_.reserve(quadCount() * std::size_t(s_) * std::size_t(s_));
    for (std::size_t g = 0; g < quadCount(); ++g) {
      if (!out_.gridded[g]) continue;
      const int qi = quadI(g), qj = quadJ(g);
      const std::uint32_t left = griddedIndex(qi - 1, qj), down = griddedIndex(qi, qj - 1);
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

  // The depth step from node `at` to the lattice node (fi, fj) next to it (-1: far there, or off
  // the map). Where the lattice ends (the next quad is not refined) the step is the texel grid's
  // own along the same axis, divided by S: at a texel centre the step to the next texel centre,
  // between two (a side's node) the interpolation of the steps of the side's two corners. Without
  // it a feature one node wide at the lattice's edge (a thin rod a hidden quad's centre node sees,
  // S = 2) showed only its own step back down on its far side and was taken for a steep slope.
  double stepTo(const Node& at, std::int64_t fi, std::int64_t fj) const {
    const std::uint32_t k = nodeAt(fi, fj);
    if (k != kNone) return nodes_[k].far ? -1.0 : std::abs(nodes_[k].rule - at.rule);
    const bool alongI = fi != at.fi;  // the step's axis
    const std::int64_t along = alongI ? at.fi : at.fj, across = alongI ? at.fj : at.fi;
    if (along < 0 || across < 0 || along % s_ != 0) return -1.0;  // (always on a grid line here)
    const int t = int(along / s_), dir = int((alongI ? fi : fj) - along), c0 = int(across / s_);
    const double f = double(across % s_) / s_;
    const int w = map_.width, h = map_.height;
    double step = 0.0;
    for (int c = c0; c <= c0 + (f > 0.0 ? 1 : 0); ++c) {
      const int i0 = alongI ? t : c, j0 = alongI ? c : t, i1 = alongI ? t + dir : c, j1 = alongI ? c : t + dir;
      if (i1 < 0 || j1 < 0 || i1 >= w || j1 >= h || i0 >= w || j0 >= h) return -1.0;
      const double d0 = sheet_.at(i0, j0), d1 = sheet_.at(i1, j1);
      if (d0 == farPlane_ || d1 == farPlane_) return -1.0;
      step += (c == c0 ? 1.0 - f : f) * std::abs(unblurred(i1, j1, d1) - unblurred(i0, j0, d0));
    }
    return step / s_;
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
        for (int m = 0; m < 2; ++m) {  // a plain quad's crossing stays (keepPresetSurfaceCornersApart)
          FineEdge& e = edges_[c.edge[split[m]]];
          if (e.preset != kNone) continue;
          e.boundary = false;
          changed = true;
        }
      }
    }
  }

  // A vertex for every hit node of a gridded quad that has none (the corners keep their sheet vertex).
  void numberNodeVertices() {
    std::vector<std::uint8_t> used(nodes_.size(), 0);
    for (const SubCell& c : cells_)
      for (std::uint32_t k : c.node) used[k] = 1;
    std::uint32_t next = firstVertex_;
    std::vector<std::uint32_t> numbered;
    for (std::uint32_t k = 0; k < nodes_.size(); ++k) {
      Node& n = nodes_[k];
      if (!used[k] || n.far || n.id != kNone) continue;
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
      if (!e.boundary || e.preset != kNone) continue;
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
                                  &centreDepths_, {o_.ends, &out_.snapped});
    if (o_.rimBias) lowerRimVertices(segments);
    out_.raysCast += budget.rays;
    out_.msRays += budget.ms;
    // The crossings' two vertices: texel point, light-view points, world positions.
    const std::size_t base = out_.positions.size();
    out_.positions.resize(base + 2 * segments.size());
    crossingVertices_.resize(2 * (segments.size() + presets_.size()));
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
    presetCrossingVertices(segments.size());
  }

  // moveNearVertexToRim (rim_bias.h) for each crossing, from its sub-edge's near end (its rule
  // depth, with the bias: a sample's, or a virtual node's interpolated one).
  void lowerRimVertices(std::span<const BisectionSegment> segments) {
    std::atomic<std::size_t> moved{0};
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, segments.size(), 512), [&](const tbb::blocked_range<std::size_t>& r) {
      std::size_t n = 0;
      for (std::size_t k = r.begin(); k != r.end(); ++k) {
        const BisectionSegment& g = segments[k];
        Crossing& c = crossings_[k];
        const glm::dvec2 at = g.nearPoint + c.s * (g.farPoint - g.nearPoint);
        n += moveNearVertexToRim(unproject_, c, at, g.nearPoint, g.nearDepth, sheet_.rule());
      }
      moved += n;
    });
    out_.rimCrossings = moved.load();
  }

  // The plain crossings' two vertices (their own, from the plain numbering), after the `bisected`.
  void presetCrossingVertices(std::size_t bisected) {
    for (std::size_t p = 0; p < presets_.size(); ++p) {
      const std::size_t pe = presets_[p].plainEdge;
      edges_[presets_[p].edge].crossing = std::uint32_t(bisected + p);
      const BoundaryEdge& edge = plain_->edges.edges[pe];
      const Crossing& c = plain_->refinement.crossings[pe];
      const glm::dvec2 t = Crossing::texel(edge, c.s);
      for (int side = 0; side < 2; ++side) {
        CellVertex& v = crossingVertices_[2 * (bisected + p) + std::size_t(side)];
        v.texel = t;
        v.depth = side == 0 ? c.nearDepth : c.farDepth;
        v.id = side == 0 ? nearVertex(plain_->crossingBase, pe) : farVertex(plain_->crossingBase, pe);
        v.far = side == 1 && !edge.surface;
        v.lv = unproject_.lightViewPoint(t.x, t.y, v.depth);
      }
    }
  }

  // The sub-cells' triangles, in blocks of quads in parallel, joined in quad order.
  void triangulate() {
    constexpr std::size_t kBlock = 32;
    const std::size_t cellsPerQuad = std::size_t(s_) * std::size_t(s_);
    const std::size_t gridded = cells_.size() / cellsPerQuad;
    const std::size_t blocks = (gridded + kBlock - 1) / kBlock;
    std::vector<std::vector<Tri>> triangles(blocks);
    std::vector<std::vector<CapEdge>> capEdges(blocks);
    std::vector<std::size_t> footprint(blocks, 0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, blocks, 1), [&](const tbb::blocked_range<std::size_t>& r) {
      std::vector<LocalTri> tris;
      for (std::size_t block = r.begin(); block != r.end(); ++block) {
        const std::size_t end = std::min(gridded, (block + 1) * kBlock) * cellsPerQuad;
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

  // The sides with virtual nodes on hit corners: what splitQuadTriangles splits.
  void collectSplits() {
    for (std::size_t g = 0; g < quadCount(); ++g) {
      if (!out_.gridded[g]) continue;
      const int qi = quadI(g), qj = quadJ(g);
      for (int k = 0; k < 4; ++k) {
        const int ni = qi + kSideDqi[k], nj = qj + kSideDqj[k];
        if (use_.grid().at(ni, nj) & kRefined) {
          if (plainNeighbour(g, k) != kNone)
            collectPlainSplits(g, k, std::uint32_t(nj) * std::uint32_t(qw()) + std::uint32_t(ni));
          continue;
        }
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
    auto byQuad = [](const SideSplit& x, const SideSplit& y) { return x.quad < y.quad; };
    std::stable_sort(out_.splits.begin(), out_.splits.end(), byQuad);
    std::stable_sort(out_.plainSplits.begin(), out_.plainSplits.end(), byQuad);
  }

  // The split sides of plain quad `quad` across side k of gridded quad g: the whole side when it is
  // continuous, else corner to crossing and crossing to corner; far pieces have no vertex to split.
  void collectPlainSplits(std::size_t g, int k, std::uint32_t quad) {
    auto piece = [&](std::uint32_t from, std::uint32_t to, int m0, int m1) {
      if (m0 > m1 || nodes_[sideNode(g, k, m0)].far) return;
      SideSplit split;
      split.quad = quad, split.from = from, split.to = to;
      for (int m = m0; m <= m1; ++m) split.points.push_back(nodes_[sideNode(g, k, m)].id);
      out_.plainSplits.push_back(std::move(split));
    };
    const std::uint32_t c0 = nodes_[sideNode(g, k, 0)].id, c1 = nodes_[sideNode(g, k, s_)].id;
    if (!(quads_.sides[g] >> k & 1)) return piece(c0, c1, 1, s_ - 1);
    const SideCrossing x = sideCrossing(g, k);
    const std::uint32_t nearId = nearVertex(plain_->crossingBase, x.edge), farId = farVertex(plain_->crossingBase, x.edge);
    piece(c0, x.cornerNear ? nearId : farId, 1, x.sub);
    piece(x.cornerNear ? farId : nearId, c1, x.sub + 1, s_ - 1);
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
  const bool perspective_;  // a spot light: 1 / depth is linear in texel space
  const TexelUnprojector unproject_;
  const std::uint32_t firstVertex_;
  const PlainRefinement* plain_;  // the adaptive choice's plain refinement, or null
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
  struct Pending {  // a preset found before the sub-edges exist
    std::uint32_t g;
    std::uint8_t k;
    SideCrossing x;
  };
  std::vector<Pending> pending_;
  std::vector<PresetCrossing> presets_;
  SubgridCells out_;
};

}  // namespace

SubgridCells buildSubgridCells(const RefinedQuads& quads, const TexelUse& use, const SheetVertices& vertices,
                               const SheetDepths& sheet, const DepthOracle& oracle, const SubgridOptions& options,
                               std::uint32_t firstVertex, const PlainRefinement* plain) {
  SV_CHECK_GE(options.subdivisions, 2);
  SV_CHECK_GE(options.steps, 1);
  return SubgridBuilder(quads, use, vertices, sheet, oracle, options, firstVertex, plain).run();
}

void splitQuadTriangles(const std::vector<SideSplit>& splits, const std::function<QuadSlots(std::uint32_t)>& slotsOf,
                        VolumeMesh& mesh) {
  std::vector<std::uint32_t> polygon;
  for (std::size_t g = 0; g < splits.size();) {
    std::size_t end = g;
    while (end < splits.size() && splits[end].quad == splits[g].quad) ++end;
    std::size_t applied = 0;
    const QuadSlots slots = slotsOf(splits[g].quad);
    for (std::size_t t = 0; t < slots.count; ++t) {
      const std::size_t slot = slots.first + t;
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
