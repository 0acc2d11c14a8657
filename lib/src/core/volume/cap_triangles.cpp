#include "volume/cap_triangles.h"

namespace shadowvol::volume {

void appendFlatCap(const std::vector<std::array<std::uint32_t, 3>>& cap, VolumeMesh& mesh) {
  for (const Tri& c : cap) mesh.triangles.push_back({c[0], c[2], c[1]});
}

std::size_t appendMirroredCap(const QuadGrid& grid, const Scratch<std::uint32_t>& quadTri,
                              const std::vector<CapEdge>& edges, const GridUnprojector& unproject, const DepthMap& map,
                              const RefinedFootprint* refined, VolumeMesh& mesh) {
  const int qw = grid.qw, qh = grid.qh, w = qw + 1;
  const double farPlane = map.farPlane;
  std::vector<std::uint8_t> onBoundary(mesh.positions.size(), 0);
  for (const CapEdge& e : edges) onBoundary[e.from] = onBoundary[e.to] = 1;
  std::vector<std::uint32_t> capVertex(std::size_t(w) * (qh + 1), kNone);
  auto texelVertex = [&](int i, int j) {
    std::uint32_t& v = capVertex[std::size_t(j) * w + i];
    if (v == kNone) {
      v = std::uint32_t(mesh.positions.size());
      mesh.positions.push_back(unproject.worldPoint(i, j, farPlane));
    }
    return v;
  };
  std::size_t added = 0;
  for (int qj = 0; qj < qh; ++qj)
    for (int qi = 0; qi < qw; ++qi) {
      const std::size_t qIndex = std::size_t(qj) * qw + qi;
      const std::uint8_t q = grid.code[qIndex];
      const int f = q & kFlip;
      for (int t = 0; t < 2; ++t) {
        if (!(q & keepBit(t))) continue;
        const Tri sheet = mesh.triangles[quadTri[qIndex] + ((t == 1 && (q & kKeep0)) ? 1u : 0u)];
        Tri cap{};
        for (int k = 0; k < 3; ++k) {
          const int corner = kTriCorners[f][t][k];
          cap[k] = onBoundary[sheet[k]] ? sheet[k] : texelVertex(qi + kCornerDi[corner], qj + kCornerDj[corner]);
        }
        mesh.triangles.push_back({cap[0], cap[2], cap[1]});
        ++added;
      }
    }
  if (!refined) return added;
  const TexelUnprojector exact(map);
  std::vector<std::uint32_t> crossingVertex(refined->edges.edges.size(), kNone);
  std::vector<std::uint32_t> chordVertex(refined->chords ? refined->chords->segments.size() : 0, kNone);
  auto farPoint = [&](std::uint32_t& v, glm::dvec2 t) {  // a far-plane vertex under texel point t, once
    if (v == kNone) {
      v = std::uint32_t(mesh.positions.size());
      mesh.positions.push_back(exact.worldPoint(t.x, t.y, farPlane));
    }
    return v;
  };
  auto pointVertex = [&](const CapPoint& p) {
    switch (p.kind) {
      case CapPoint::Kind::Texel: return texelVertex(int(p.index % std::uint32_t(w)), int(p.index / std::uint32_t(w)));
      case CapPoint::Kind::Edge: {
        const BoundaryEdge& e = refined->edges.edges[p.index];
        if (!e.surface) return farVertex(refined->crossingBase, p.index);  // on the cap's boundary
        return farPoint(crossingVertex[p.index], Crossing::texel(e, refined->refinement.crossings[p.index].s));
      }
      case CapPoint::Kind::Chord: break;
    }
    if (!refined->chords->segments[p.index].surface) return farVertex(refined->chordBase, p.index);
    return farPoint(chordVertex[p.index], refined->chords->texel(p.index));
  };
  for (const auto& tri : refined->cells.footprint) {
    const Tri cap{pointVertex(tri[0]), pointVertex(tri[1]), pointVertex(tri[2])};
    mesh.triangles.push_back({cap[0], cap[2], cap[1]});
    ++added;
  }
  return added;
}

}  // namespace shadowvol::volume
