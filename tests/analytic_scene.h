// Analytic test scenes for the volume builder and its refinement: boxes (optionally turned about
// the vertical), spheres and a single-sided ground plane y = 0 facing up, captured exactly by the
// rules of depth_capture.h without Embree. The same scene gives the depth map (rays through texel
// centres) and the depth oracle (rays through any point), so refinement can be checked against
// known outlines.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <vector>

#include <glm/geometric.hpp>

#include "shadowvol/check.h"
#include "shadowvol/depth_map.h"
#include "shadowvol/depth_oracle.h"
#include "shadowvol/nearer_surfaces.h"
#include "shadowvol/primitives.h"

namespace shadowvol::test {

struct AnalyticScene {
  struct Box {
    glm::dvec3 centre, half;  ///< world centre and half sizes (before the turn)
    double turnDegrees = 0.0; ///< rotation about +y
  };
  struct Sphere {
    glm::dvec3 centre;
    double radius;
  };
  std::vector<Box> boxes;
  std::vector<Sphere> spheres;
  bool ground = false;  ///< the plane y = 0, single-sided, facing +y

  /// Surfaces met by the ray origin + t * direction (t > 0): (t, back-facing) pairs, unsorted.
  std::vector<std::pair<double, bool>> hits(const glm::dvec3& origin, const glm::dvec3& direction) const {
    std::vector<std::pair<double, bool>> out;
    for (const Box& b : boxes) {
      const double a = -b.turnDegrees * std::numbers::pi / 180.0;  // into the box's frame
      auto turn = [&](const glm::dvec3& v) {
        return glm::dvec3(std::cos(a) * v.x + std::sin(a) * v.z, v.y, -std::sin(a) * v.x + std::cos(a) * v.z);
      };
      const glm::dvec3 o = turn(origin - b.centre), d = turn(direction);
      double t0 = -1e300, t1 = 1e300;
      bool ok = true;
      for (int k = 0; k < 3 && ok; ++k) {
        if (d[k] == 0.0) {
          ok = std::abs(o[k]) < b.half[k];
          continue;
        }
        const double p = (-b.half[k] - o[k]) / d[k], q = (b.half[k] - o[k]) / d[k];
        t0 = std::max(t0, std::min(p, q));
        t1 = std::min(t1, std::max(p, q));
      }
      if (ok && t0 < t1 && t1 > 0.0) {
        out.push_back({t0, false});
        out.push_back({t1, true});
      }
    }
    for (const Sphere& s : spheres) {
      const glm::dvec3 o = origin - s.centre;
      const double a = glm::dot(direction, direction), b = 2.0 * glm::dot(o, direction);
      const double c = glm::dot(o, o) - s.radius * s.radius, disc = b * b - 4.0 * a * c;
      if (disc <= 0.0) continue;
      const double r = std::sqrt(disc);
      out.push_back({(-b - r) / (2.0 * a), false});
      out.push_back({(-b + r) / (2.0 * a), true});
    }
    if (ground && direction.y < 0.0 && origin.y > 0.0) out.push_back({-origin.y / direction.y, false});
    return out;
  }

  /// The depth that `mode` records on the light ray (parameter = light-view depth) within
  /// [near, far]; kNoHit for none. Midpoint: the mean of the first two surfaces, the far plane
  /// standing in for a missing second.
  float capture(const TexelUnprojector::Ray& ray, CaptureMode mode, double nearPlane, double farPlane) const {
    std::vector<std::pair<double, bool>> h = hits(ray.origin, ray.direction);
    std::vector<std::pair<double, bool>> in;
    for (const auto& x : h)
      if (x.first >= nearPlane && x.first <= farPlane) in.push_back(x);
    std::sort(in.begin(), in.end());
    if (mode == CaptureMode::Front) return in.empty() ? DepthMap::kNoHit : float(in.front().first);
    if (mode == CaptureMode::Back) {
      for (const auto& x : in)
        if (x.second) return float(x.first);
      return DepthMap::kNoHit;
    }
    if (in.empty()) return DepthMap::kNoHit;
    return float(0.5 * (in[0].first + (in.size() > 1 ? in[1].first : farPlane)));
  }

  /// The depth map of `light` at W x H by `mode`.
  DepthMap depthMap(const Light& light, int width, int height, CaptureMode mode) const {
    DepthMap m = makeDepthMap(light, width, height, mode);
    const TexelUnprojector unproject(m);
    for (int j = 0; j < height; ++j)
      for (int i = 0; i < width; ++i) m.depth[m.index(i, j)] = capture(unproject.ray(i, j), mode, m.nearPlane, m.farPlane);
    return m;
  }

  /// The boxes and the ground as triangles (the ground a 200 x 200 square; spheres have none), as
  /// the scene file's generated objects are made (makeBox, makePlane: counter-clockwise outside).
  TriangleMesh mesh() const {
    SV_CHECK(spheres.empty());
    TriangleMesh all;
    for (const Box& b : boxes) {
      TriangleMesh m = makeBox(2.0 * b.half.x, 2.0 * b.half.y, 2.0 * b.half.z);
      const double a = b.turnDegrees * std::numbers::pi / 180.0;  // out of the box's frame
      for (glm::vec3& p : m.positions) {
        const glm::dvec3 v(p);
        p = glm::vec3(glm::dvec3(std::cos(a) * v.x + std::sin(a) * v.z, v.y, -std::sin(a) * v.x + std::cos(a) * v.z) +
                      b.centre);
      }
      all.append(m);
    }
    if (ground) all.append(makePlane(200.0, 200.0, 1));
    return all;
  }

  /// The search for hidden surfaces over mesh() (findNearerSurfaces).
  NearerSurfaceOracle nearerSurfaces() const {
    return [m = mesh()](const DepthMap& map, std::span<const float> limit, std::span<const float> rimLimit,
                        std::span<std::uint8_t> flags) {
      TriangleSoup soup = soupOf(m);
      const std::vector<std::uint32_t> rims = openRims(m);
      soup.rims = rims;
      findNearerSurfaces(map, std::span<const TriangleSoup>(&soup, 1), limit, flags);
      if (!rimLimit.empty()) findOpenRims(map, std::span<const TriangleSoup>(&soup, 1), rimLimit, flags);
    };
  }

  /// The oracle of this scene (it must outlive the oracle); counts its queries in `*queries`
  /// (and records the points in `*points`) when given.
  DepthOracle oracle(std::size_t* queries = nullptr, std::vector<glm::dvec2>* points = nullptr) const {
    return [this, queries, points](const DepthMap& m, std::span<const glm::dvec2> ndc, std::span<float> depth) {
      const TexelUnprojector unproject(m);
      for (std::size_t k = 0; k < ndc.size(); ++k) {
        const double i = (ndc[k].x + 1.0) * 0.5 * m.width - 0.5, j = (ndc[k].y + 1.0) * 0.5 * m.height - 0.5;
        depth[k] = capture(unproject.ray(i, j), m.capture, m.nearPlane, m.farPlane);
        if (points) points->push_back({i, j});
      }
      if (queries) *queries += ndc.size();
    };
  }
};

}  // namespace shadowvol::test
