#include "volume/thin_quads.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/vec2.hpp>

#include "shadowvol/boundary_edges.h"
#include "volume/chord_offsets.h"
#include "volume/quad_codes.h"

namespace shadowvol::volume {
namespace {

// How far texel (i, j)'s sample lies off the chord of its neighbours, either way, the most over the
// four directions (0 without a neighbour pair on the map, off the ring and hit).
double offChord(const SheetDepths& sheet, int i, int j, bool perspective) {
  double most = 0.0;
  forEachChord(sheet, i, j, perspective, [&](int, double behind) { most = std::max(most, std::abs(behind)); });
  return most;
}

}  // namespace

std::vector<std::uint32_t> findThinQuads(const SheetDepths& sheet, const DepthOracle& oracle, std::uint8_t* splitBits,
                                         std::size_t* rays) {
  const DepthMap& map = sheet.map();
  const SheetDepthRule& rule = sheet.rule();
  std::vector<std::uint32_t> thin;
  if (map.capture != CaptureMode::Back || rule.bias > 0.0 || !oracle) return thin;
  const int w = map.width, h = map.height, qw = w - 1, qh = h - 1;
  const bool perspective = map.lightProjection[2][3] != 0.0;
  const TexelFootprint footprint = TexelFootprint::of(map);
  // The quads this stage may flag: no boundary side, not flagged yet.
  const auto eligible = [&](int qi, int qj) {
    if (qi < 0 || qj < 0 || qi >= qw || qj >= qh) return false;
    const std::uint8_t* lower = splitBits + std::size_t(qj) * w;
    return ((lower[qi] & (3 | kHiddenQuadBit)) | (lower[qi + 1] & 2) | (lower[qi + w] & 1)) == 0;
  };
  // Their corners off a chord by more than the floor, and the first surface on those corners' rays
  // (the part's lit face).
  std::vector<std::size_t> texel;
  std::vector<double> off;
  std::vector<glm::dvec2> ndc;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      if (!(eligible(i - 1, j - 1) || eligible(i, j - 1) || eligible(i - 1, j) || eligible(i, j))) continue;
      const double d = offChord(sheet, i, j, perspective);
      if (!(d > kThinChordFloor * footprint.at(rule.fromStored(map.at(i, j))))) continue;
      texel.push_back(std::size_t(j) * std::size_t(w) + std::size_t(i));
      off.push_back(d);
      ndc.emplace_back((i + 0.5) / w * 2.0 - 1.0, (j + 0.5) / h * 2.0 - 1.0);
    }
  // The map's description with front capture, without its depths (the oracle reads none).
  DepthMap front;
  front.width = map.width, front.height = map.height, front.lightType = map.lightType;
  front.lightView = map.lightView, front.lightProjection = map.lightProjection;
  front.nearPlane = map.nearPlane, front.farPlane = map.farPlane, front.origin = map.origin;
  front.capture = CaptureMode::Front;
  std::vector<float> first(ndc.size());
  if (!ndc.empty()) oracle(front, ndc, first);
  if (rays) *rays = ndc.size();
  std::vector<std::uint8_t> thinAt(std::size_t(w) * std::size_t(h), 0);
  for (std::size_t k = 0; k < texel.size(); ++k) {
    const double back = rule.fromStored(map.depth[texel[k]]);
    thinAt[texel[k]] = std::isfinite(first[k]) && back - double(first[k]) < off[k];
  }
  for (int qj = 0; qj < qh; ++qj) {
    std::uint8_t* lower = splitBits + std::size_t(qj) * w;
    const std::uint8_t* t0 = thinAt.data() + std::size_t(qj) * w;
    const std::uint8_t* t1 = t0 + w;
    for (int qi = 0; qi < qw; ++qi) {
      if (!eligible(qi, qj) || !(t0[qi] | t0[qi + 1] | t1[qi] | t1[qi + 1])) continue;
      lower[qi] |= kHiddenQuadBit;
      thin.push_back(std::uint32_t(qj) * std::uint32_t(qw) + std::uint32_t(qi));
    }
  }
  return thin;
}

}  // namespace shadowvol::volume
