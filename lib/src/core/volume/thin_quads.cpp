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

// A texel off its neighbours' chords by more than the floor: its column and how far off (either way,
// the most over the four directions).
struct OffChord {
  int i = 0;
  double off = 0.0;
};

}  // namespace

std::vector<std::uint32_t> findThinQuads(const SheetDepths& sheet, const DepthOracle& oracle, std::uint8_t* splitBits,
                                         std::size_t* rays) {
  const DepthMap& map = sheet.map();
  const SheetDepthRule& rule = sheet.rule();
  std::vector<std::uint32_t> thin;
  if (map.capture != CaptureMode::Back || rule.bias > 0.0 || !oracle) return thin;
  const int w = map.width, h = map.height, qw = w - 1, qh = h - 1;
  if (w < 3 || h < 3) {  // every texel on the ring: none sampled
    if (rays) *rays = 0;
    return thin;
  }
  const bool perspective = map.lightProjection[2][3] != 0.0;
  const TexelFootprint footprint = TexelFootprint::of(map);
  // The quads this stage may flag: no boundary side, not flagged yet.
  const auto eligible = [&](int qi, int qj) {
    if (qi < 0 || qj < 0 || qi >= qw || qj >= qh) return false;
    const std::uint8_t* lower = splitBits + std::size_t(qj) * w;
    return ((lower[qi] & (3 | kHiddenQuadBit)) | (lower[qi + 1] & 2) | (lower[qi + w] & 1)) == 0;
  };
  // Their corners off a chord by more than the floor, row by row in parallel (forEachSampledRow).
  std::vector<std::vector<OffChord>> offRows(static_cast<std::size_t>(h));
  forEachSampledRow(sheet, [&](int j, const double* up, const double* row, const double* down) {
    for (int i = 1; i < w - 1; ++i) {
      if (row[i] == std::numeric_limits<double>::infinity()) continue;
      if (!(eligible(i - 1, j - 1) || eligible(i, j - 1) || eligible(i - 1, j) || eligible(i, j))) continue;
      double most = 0.0;
      forEachChordInRows(up, row, down, i, perspective,
                         [&](int, double behind) { most = std::max(most, std::abs(behind)); });
      if (most > kThinChordFloor * footprint.at(row[i])) offRows[std::size_t(j)].push_back({i, most});
    }
  });
  // The first surface on those corners' rays (the part's lit face), in row-major order.
  std::vector<std::size_t> texel;
  std::vector<double> off;
  std::vector<glm::dvec2> ndc;
  for (int j = 1; j < h - 1; ++j)
    for (const OffChord& c : offRows[std::size_t(j)]) {
      texel.push_back(std::size_t(j) * std::size_t(w) + std::size_t(c.i));
      off.push_back(c.off);
      ndc.emplace_back((c.i + 0.5) / w * 2.0 - 1.0, (j + 0.5) / h * 2.0 - 1.0);
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
  // The eligible quads with a thin corner (flagging one changes no other quad's eligibility).
  for (std::size_t k = 0; k < texel.size(); ++k) {
    const double back = rule.fromStored(map.depth[texel[k]]);
    if (!(std::isfinite(first[k]) && back - double(first[k]) < off[k])) continue;
    const int i = int(texel[k] % std::size_t(w)), j = int(texel[k] / std::size_t(w));
    for (int qj = j - 1; qj <= j; ++qj)
      for (int qi = i - 1; qi <= i; ++qi)
        if (eligible(qi, qj)) thin.push_back(std::uint32_t(qj) * std::uint32_t(qw) + std::uint32_t(qi));
  }
  std::sort(thin.begin(), thin.end());
  thin.erase(std::unique(thin.begin(), thin.end()), thin.end());
  for (std::uint32_t q : thin)
    splitBits[std::size_t(q / std::uint32_t(qw)) * w + q % std::uint32_t(qw)] |= kHiddenQuadBit;
  return thin;
}

}  // namespace shadowvol::volume
