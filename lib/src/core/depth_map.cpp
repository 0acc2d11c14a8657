#include "shadowvol/depth_map.h"

#include <algorithm>
#include <utility>
#include <vector>

#include <glm/matrix.hpp>
#include <glm/vec4.hpp>

#include "shadowvol/check.h"
#include "shadowvol/error.h"
#include "shadowvol/memory_budget.h"

namespace shadowvol {

const char* toString(CaptureMode mode) { return nameIn(kCaptureModeNames, mode); }

bool parseCaptureMode(const std::string& text, CaptureMode& mode) { return parseIn(kCaptureModeNames, text, mode); }

glm::dvec2 DepthMap::texelNdc(double i, double j) const {
  return {(i + 0.5) / double(width) * 2.0 - 1.0, (j + 0.5) / double(height) * 2.0 - 1.0};
}

glm::dvec3 DepthMap::lightViewPoint(double i, double j, double d) const {
  return TexelUnprojector(*this).lightViewPoint(i, j, d);
}

glm::dvec3 DepthMap::worldPoint(double i, double j, double d) const {
  return TexelUnprojector(*this).worldPoint(i, j, d);
}

TexelUnprojector::TexelUnprojector(const DepthMap& map)
    : TexelUnprojector(map.lightView, map.lightProjection, map.width, map.height) {}

TexelUnprojector::TexelUnprojector(const glm::dmat4& view, const glm::dmat4& projection, int width, int height)
    : invProjection_(glm::inverse(projection)),
      invView_(glm::inverse(view)),
      projection_(projection),
      view_(view),
      width_(width),
      height_(height) {}

glm::dvec3 TexelUnprojector::lightViewPoint(double i, double j, double d) const {
  const double x = (i + 0.5) / width_ * 2.0 - 1.0;
  const double y = (j + 0.5) / height_ * 2.0 - 1.0;
  // Clip z and w depend only on view z (column-major: m[col][row]); z_view = -d.
  const double clipZ = projection_[2][2] * -d + projection_[3][2];
  const double clipW = projection_[2][3] * -d + projection_[3][3];
  const glm::dvec4 v = invProjection_ * glm::dvec4(x, y, clipZ / clipW, 1.0);
  glm::dvec3 result = glm::dvec3(v) / v.w;
  result.z = -d;  // exact by construction; removes the inverse's round-off in z
  return result;
}

glm::dvec3 TexelUnprojector::worldPoint(double i, double j, double d) const {
  return glm::dvec3(invView_ * glm::dvec4(lightViewPoint(i, j, d), 1.0));
}

TexelUnprojector::Ray TexelUnprojector::ray(double i, double j) const {
  const glm::dvec3 p1 = worldPoint(i, j, 1.0), p2 = worldPoint(i, j, 2.0);
  return {p1 - (p2 - p1), p2 - p1};
}

double TexelUnprojector::viewDepth(const glm::dvec3& world) const { return -(view_ * glm::dvec4(world, 1.0)).z; }

double DepthMap::viewDepthOf(const glm::dvec3& world) const {
  return -(lightView * glm::dvec4(world, 1.0)).z;
}

glm::dvec2 DepthMap::texelOf(const glm::dvec3& world) const {
  const glm::dvec4 clip = lightProjection * lightView * glm::dvec4(world, 1.0);
  const double x = clip.x / clip.w, y = clip.y / clip.w;
  return {(x + 1.0) * 0.5 * double(width) - 0.5, (y + 1.0) * 0.5 * double(height) - 0.5};
}

std::size_t DepthMap::hitCount() const {
  std::size_t n = 0;
  for (float d : depth) n += isNoHit(d) ? 0 : 1;
  return n;
}

DepthMap makeDepthMap(const Light& light, int width, int height, CaptureMode capture) {
  SV_CHECK_GT(width, 0);
  SV_CHECK_GT(height, 0);
  DepthMap map;
  map.width = width;
  map.height = height;
  map.depth.assign(std::size_t(width) * std::size_t(height), DepthMap::kNoHit);
  map.lightType = light.type;
  map.lightView = lightView(light);
  map.lightProjection = lightProjection(light, double(width) / double(height));
  map.nearPlane = light.nearPlane;
  map.farPlane = light.farPlane;
  map.capture = capture;
  return map;
}

std::uint64_t depthMapBytes(int width, int height, DepthMapUse use) {
  const std::uint64_t texels = std::uint64_t(width) * std::uint64_t(height);
  // depths (4 B) + volume vertices (3 doubles) + ~2 triangles per texel (2 x 3 x 4 B); the map
  // alone: its depths, the read-back copy and a file's row buffers (12 B; `shadowvol depth` at
  // 15000^2 peaked at 0.9 GB, 4 B a texel, 2026-12-05); a shadow map's frame: 24 B (`render
  // --method shadowmap --resolution 14000` peaked at 3,966,700 KB, 20.7 B a texel: a fourteenth
  // probe's, where the volume's 52 refused a 16384² map that fits)
  switch (use) {
    case DepthMapUse::Volume: return texels * (4 + 24 + 24);
    case DepthMapUse::MapOnly: return texels * 12;
    case DepthMapUse::ShadowMap: return texels * 24;
  }
  return texels * (4 + 24 + 24);
}

std::uint64_t volumeBuildBytes(const DepthMap& map) {
  const int w = map.width, h = map.height;
  const std::size_t texels = std::size_t(std::max(w, 0)) * std::size_t(std::max(h, 0));
  if (texels == 0 || map.depth.size() != texels) return depthMapBytes(std::max(w, 0), std::max(h, 0));
  const auto hit = [&](int i, int j) {
    return i >= 0 && j >= 0 && i < w && j < h && map.depth[std::size_t(j) * w + i] != DepthMap::kNoHit;
  };
  // Islands by union-find over the hit texels (path halving; 4 B a texel, freed before the build).
  std::vector<std::uint32_t> parent(texels);
  const auto find = [&](std::uint32_t k) {
    while (parent[k] != k) k = parent[k] = parent[parent[k]];
    return k;
  };
  std::uint64_t islands = 0, border = 0;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      if (!hit(i, j)) continue;
      const auto k = std::uint32_t(std::size_t(j) * w + i);
      parent[k] = k;
      ++islands;
      border += !hit(i - 1, j) || !hit(i + 1, j) || !hit(i, j - 1) || !hit(i, j + 1);
      for (const auto [di, dj] : {std::pair{-1, 0}, std::pair{-1, -1}, std::pair{0, -1}, std::pair{1, -1}})
        if (hit(i + di, j + dj)) {
          const std::uint32_t a = find(k), b = find(std::uint32_t(std::size_t(j + dj) * w + (i + di)));
          if (a != b) {
            parent[std::max(a, b)] = std::min(a, b);
            --islands;
          }
        }
    }
  return depthMapBytes(w, h) + islands * 4096 + border * 64;
}

void checkVolumeFitsMemory(std::span<const DepthMap> maps) {
  std::uint64_t worst = 0;  // every other texel of every other row an island of its own
  for (const DepthMap& m : maps) {
    const std::uint64_t w = std::uint64_t(std::max(m.width, 0)), h = std::uint64_t(std::max(m.height, 0));
    worst += depthMapBytes(m.width, m.height) + (w + 1) / 2 * ((h + 1) / 2) * 4096 + w * h * 64;
  }
  const std::uint64_t physical = physicalMemoryBytes();
  if (maps.empty() || physical == 0 || worst <= physical / 2) return;
  std::uint64_t need = 0;
  for (const DepthMap& m : maps) need += volumeBuildBytes(m);
  const DepthMap& first = maps.front();
  checkFitsMemory(need, "depth map", "texels",
                  (maps.size() > 1 ? std::to_string(maps.size()) + " maps of " : std::string()) +
                      std::to_string(first.width) + "x" + std::to_string(first.height) +
                      " (a volume's walls and cap loops for each island of hit texels)");
}

void checkVolumeFitsMemory(const DepthMap& map) { checkVolumeFitsMemory(std::span<const DepthMap>(&map, 1)); }

namespace {

std::string sizeText(int width, int height) {
  return width == height ? std::to_string(width) : std::to_string(width) + "x" + std::to_string(height);
}

}  // namespace

void checkDepthMapSize(int width, int height, const std::string& source, const std::string& field,
                       DepthMapUse use) {
  const std::string value = sizeText(width, height);
  if (width < 2 || height < 2) throw InputError(source, field, value, "the resolution must be at least 2");
  if (width > kMaxDepthMapSide || height > kMaxDepthMapSide)
    throw InputError(source, field, value, "above the limit of " + std::to_string(kMaxDepthMapSide) + " texels a side");
  checkFitsMemory(depthMapBytes(width, height, use), source, field, value);
}

void checkWindowMapSize(int width, int height, const std::string& source, const std::string& field, DepthMapUse use) {
  checkDepthMapSize(width, height, source, field, use);
  if (use == DepthMapUse::Volume) checkGuardedDepthMapSize(width, height, kVolumeGuardTexels, source, field, use);
}

void checkGuardTexels(std::int64_t guard, const std::string& source, const std::string& field) {
  if (guard < 0 || guard > kMaxGuardTexels)
    throw InputError(source, field, std::to_string(guard),
                     "must be from 0 to " + std::to_string(kMaxGuardTexels) + " texels a side");
}

void checkDepthMapGuard(std::int64_t guard, int width, int height, const std::string& source, const std::string& field) {
  checkGuardTexels(guard, source, field);
  if (2 * guard + 2 > std::min(width, height))
    throw InputError(source, field, std::to_string(guard),
                     "leaves less than 2 x 2 texels of the window inside the " + sizeText(width, height) + " map");
}

void checkGuardedDepthMapSize(int width, int height, int guard, const std::string& source, const std::string& field,
                              DepthMapUse use) {
  if (guard == 0) return;
  const std::string value = sizeText(width, height);
  const std::int64_t w = std::int64_t(width) + 2 * std::int64_t(guard), h = std::int64_t(height) + 2 * std::int64_t(guard);
  const std::string band = "with its guard band of " + std::to_string(guard) + " texels a side (the map is " +
                           std::to_string(w) + "x" + std::to_string(h) + " texels)";
  if (w > kMaxDepthMapSide || h > kMaxDepthMapSide)
    throw InputError(source, field, value,
                     band + ", above the limit of " + std::to_string(kMaxDepthMapSide) + " texels a side: take at most " +
                         std::to_string(kMaxDepthMapSide - 2 * guard));
  checkFitsMemory(depthMapBytes(int(w), int(h), use), source, field, value);
}

}  // namespace shadowvol
