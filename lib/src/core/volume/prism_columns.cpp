#include "volume/prism_columns.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "shadowvol/check.h"

namespace shadowvol::volume {

namespace {

// Whether the point at light NDC `ndc` lies in a handed-over texel's square.
bool handedAt(const PrismColumns& c, glm::dvec2 ndc) {
  const DepthMap& m = c.map;
  const glm::dvec2 t = m.texelOfNdc(ndc);
  // Clamped in double before the conversion (a point far outside the window).
  const auto texel = [](double v, int n) { return int(std::lround(std::clamp(v, 0.0, double(n - 1)))); };
  return c.texels[std::size_t(texel(t.y, m.height)) * std::size_t(m.width) + std::size_t(texel(t.x, m.width))] != 0;
}

// The full oracle's depths outside the handed-over squares and the hand-over oracle's inside (the
// caster-free record where a handed-over mesh is recorded), in one call each.
void splitDepths(const DepthOracle& full, const HandOverOracle& handOver, const PrismColumns& c, const DepthMap& map,
                 std::span<const glm::dvec2> ndc, std::span<float> depth) {
  SV_CHECK_EQ(ndc.size(), depth.size());
  std::array<std::vector<glm::dvec2>, 2> points;
  std::array<std::vector<std::size_t>, 2> at;
  for (std::size_t k = 0; k < ndc.size(); ++k) {
    const int s = handedAt(c, ndc[k]) ? 1 : 0;
    points[s].push_back(ndc[k]);
    at[s].push_back(k);
  }
  for (int s = 0; s < 2; ++s) {
    if (points[s].empty()) continue;
    std::vector<float> d(points[s].size());
    if (s) {
      std::vector<std::uint8_t> handed(d.size());
      handOver(map, points[s], d, handed);
    } else {
      full(map, points[s], d);
    }
    for (std::size_t k = 0; k < d.size(); ++k) depth[at[s][k]] = d[k];
  }
}

// Sets the four corner texels of quad q = qj * (W - 1) + qi in `texels`.
void markCorners(std::vector<std::uint8_t>& texels, int w, std::uint32_t q) {
  const std::size_t qi = q % std::uint32_t(w - 1), qj = q / std::uint32_t(w - 1);
  const std::size_t t = qj * std::size_t(w) + qi;
  texels[t] = texels[t + 1] = texels[t + std::size_t(w)] = texels[t + std::size_t(w) + 1] = 1;
}

}  // namespace

PrismColumns findPrismColumns(const DepthMap& map, std::span<const std::uint32_t> refinedQuads,
                              const HandOverOracle& handOver) {
  SV_CHECK(handOver);
  const int w = map.width, h = map.height;
  PrismColumns c;
  c.map = map;
  c.texels.assign(std::size_t(w) * std::size_t(h), 0);
  c.quads.assign(std::size_t(w - 1) * std::size_t(h - 1), 0);
  // The refined quads' corners: where a handed-over mesh is recorded, its caster-free record.
  std::vector<std::uint8_t> corners(c.texels.size(), 0);
  for (const std::uint32_t q : refinedQuads) markCorners(corners, w, q);
  std::vector<glm::dvec2> ndc;
  std::vector<std::size_t> at;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const std::size_t t = std::size_t(j) * std::size_t(w) + std::size_t(i);
      if (!corners[t]) continue;
      ndc.push_back({(i + 0.5) / w * 2.0 - 1.0, (j + 0.5) / h * 2.0 - 1.0});
      at.push_back(t);
    }
  std::vector<float> depth(ndc.size());
  std::vector<std::uint8_t> handed(ndc.size(), 0);
  if (!ndc.empty()) handOver(map, ndc, depth, handed);
  std::vector<std::uint8_t> changed(c.texels.size(), 0);
  c.rays = at.size();
  for (std::size_t k = 0; k < at.size(); ++k) {
    if (!handed[k]) continue;
    changed[at[k]] = 1;
    c.map.depth[at[k]] = depth[k];
    ++c.rays;  // the caster-free ray
  }
  // The quads with such a corner hand their corners over; the other corners keep the map's value.
  for (const std::uint32_t q : refinedQuads) {
    const std::size_t qi = q % std::uint32_t(w - 1), qj = q / std::uint32_t(w - 1);
    const std::size_t t = qj * std::size_t(w) + qi;
    if (changed[t] | changed[t + 1] | changed[t + std::size_t(w)] | changed[t + std::size_t(w) + 1])
      markCorners(c.texels, w, q);
  }
  for (const std::uint8_t t : c.texels) c.texelCount += t;
  for (int qj = 0; qj + 1 < h; ++qj)
    for (int qi = 0; qi + 1 < w; ++qi) {
      const std::size_t t = std::size_t(qj) * std::size_t(w) + std::size_t(qi);
      if (c.texels[t] | c.texels[t + 1] | c.texels[t + std::size_t(w)] | c.texels[t + std::size_t(w) + 1])
        c.quads[std::size_t(qj) * std::size_t(w - 1) + std::size_t(qi)] = 1;
    }
  return c;
}

VolumeBuildOptions handOverColumns(const VolumeBuildOptions& options, std::shared_ptr<const PrismColumns> columns) {
  VolumeBuildOptions o = options;
  const DepthOracle full = options.depthOracle;
  const HandOverOracle without = options.withoutCasters.depth;
  o.depthOracle = [full, without, columns](const DepthMap& map, std::span<const glm::dvec2> ndc,
                                           std::span<float> depth) {
    splitDepths(full, without, *columns, map, ndc, depth);
  };
  if (options.surfaceEnds) {
    const SurfaceEndOracle ends = options.surfaceEnds;
    o.surfaceEnds = [ends, columns](const DepthMap& map, std::span<const glm::dvec2> from,
                                    std::span<const glm::dvec2> to, std::span<double> t,
                                    std::span<std::array<glm::dvec3, 3>> triangle) {
      ends(map, from, to, t, triangle);
      for (std::size_t k = 0; k < from.size(); ++k)
        if (handedAt(*columns, from[k]) || handedAt(*columns, to[k])) {
          t[k] = std::nan("");
          triangle[k].fill(glm::dvec3(std::nan("")));
        }
    };
  }
  if (options.nearerSurfaces) {
    const NearerSurfaceOracle nearer = options.nearerSurfaces, freeNearer = options.withoutCasters.nearerSurfaces;
    o.nearerSurfaces = [nearer, freeNearer, columns](const DepthMap& map, std::span<const float> limit,
                                                     std::span<const float> rimLimit, std::span<std::uint8_t> flags) {
      if (!freeNearer) return nearer(map, limit, rimLimit, flags);
      std::vector<std::uint8_t> free(flags.begin(), flags.end());
      nearer(map, limit, rimLimit, flags);
      freeNearer(map, limit, rimLimit, free);
      for (std::size_t q = 0; q < flags.size(); ++q)
        if (columns->quads[q]) flags[q] = free[q];  // the prisms hold the casters there
    };
  }
  return o;
}

}  // namespace shadowvol::volume
