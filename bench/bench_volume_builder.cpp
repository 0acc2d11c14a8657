// Google Benchmark for buildVolume: 256^2 .. 2048^2, fixed / perfect, blur off / on,
// exact cap, on two analytic depth maps of the same spot-lit scene (a sphere and a box over a
// ground plane):
//   back  - back-face capture: the sphere's and box's far sides; the ground (single-sided, facing
//           the light) is not captured, so most texels are no-hit and the exact cap drops them;
//   front - front-face capture: the ground is seen everywhere, so every quad is kept.
// Next to every figure: the floor, a memcpy of as many bytes as the build reads (the depth map,
// 4 B per texel) plus writes (the mesh: 24 B per vertex, 12 B per triangle), timed in the same run
// on pre-faulted buffers, and ratio = build time / floor.
// reuse:0 times buildVolume (fresh buffers every call, so the kernel faults in and zeroes new
// pages); reuse:1 times VolumeBuilder::build into the same result every iteration (after a first,
// untimed build: no grid-sized allocation, like the floor's pre-faulted buffers).
//
// Run: build-dir/bench/bench_volume_builder --benchmark_counters_tabular=true
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <map>
#include <span>
#include <vector>

#include <benchmark/benchmark.h>

#include <glm/geometric.hpp>

#include "shadowvol/volume_builder.h"

namespace {

using namespace shadowvol;

Light benchLight() {
  Light light;
  light.type = LightType::Spot;
  light.position = {1.5, 9.0, 1.0};
  light.direction = glm::normalize(glm::dvec3(-0.15, -1.0, -0.1));
  light.fovYDegrees = 55.0;
  light.nearPlane = 2.0;
  light.farPlane = 14.0;
  return light;
}

// Light-view depth of the nearest (front) or farthest (back) intersection of the ray
// apex + d * v (d = light-view depth) with a sphere; +inf when missed.
double sphereDepth(const glm::dvec3& apex, const glm::dvec3& v, const glm::dvec3& c, double r, bool back) {
  const glm::dvec3 o = apex - c;
  const double a = glm::dot(v, v), b = 2.0 * glm::dot(o, v), q = glm::dot(o, o) - r * r;
  const double disc = b * b - 4.0 * a * q;
  if (disc < 0.0) return DepthMap::kNoHit;
  const double s = std::sqrt(disc);
  return back ? (-b + s) / (2.0 * a) : (-b - s) / (2.0 * a);
}

// Same for an axis-aligned box (slab method).
double boxDepth(const glm::dvec3& apex, const glm::dvec3& v, const glm::dvec3& lo, const glm::dvec3& hi, bool back) {
  double t0 = -1e300, t1 = 1e300;
  for (int k = 0; k < 3; ++k) {
    const double a = (lo[k] - apex[k]) / v[k], b = (hi[k] - apex[k]) / v[k];
    t0 = std::max(t0, std::min(a, b));
    t1 = std::min(t1, std::max(a, b));
  }
  if (t0 > t1) return DepthMap::kNoHit;
  return back ? t1 : t0;
}

// The captured depth of the benchmark scene along the light ray through texel (i, j) (fractional
// allowed) of map m: the depth maps below and the refinement's depth oracle use the same function.
float sceneDepth(const DepthMap& m, const TexelUnprojector& unproject, double i, double j) {
  const glm::dvec3 apex = benchLight().position;
  const bool back = m.capture == CaptureMode::Back;
  const glm::dvec3 v = unproject.worldPoint(i, j, 1.0) - apex;  // one unit of view depth
  double d = std::min(sphereDepth(apex, v, {0.0, 2.0, 0.0}, 2.0, back),
                      boxDepth(apex, v, {2.0, 0.0, -3.0}, {3.5, 2.5, -1.5}, back));
  if (!back && v.y < 0.0) d = std::min(d, -apex.y / v.y);  // the ground y = 0
  return (d >= m.nearPlane && d <= m.farPlane) ? float(d) : DepthMap::kNoHit;
}

const DepthMap& benchMap(int res, bool back) {
  static std::map<std::pair<int, bool>, DepthMap> cache;
  auto it = cache.find({res, back});
  if (it != cache.end()) return it->second;
  DepthMap m = makeDepthMap(benchLight(), res, res, back ? CaptureMode::Back : CaptureMode::Front);
  const TexelUnprojector unproject(m);
  for (int j = 0; j < res; ++j)
    for (int i = 0; i < res; ++i) m.depth[m.index(i, j)] = sceneDepth(m, unproject, i, j);
  return cache.emplace(std::make_pair(res, back), std::move(m)).first->second;
}

// The analytic scene as a depth oracle (serial: the rays are cheap next to Embree's).
DepthOracle benchOracle() {
  return [](const DepthMap& m, std::span<const glm::dvec2> ndc, std::span<float> depth) {
    const TexelUnprojector unproject(m);
    for (std::size_t k = 0; k < ndc.size(); ++k)
      depth[k] = sceneDepth(m, unproject, (ndc[k].x + 1.0) * 0.5 * m.width - 0.5, (ndc[k].y + 1.0) * 0.5 * m.height - 0.5);
  };
}

void BM_BuildVolume(benchmark::State& state) {
  const int res = int(state.range(0));
  const bool perfect = state.range(1) != 0, blur = state.range(2) != 0, back = state.range(3) != 0;
  const bool reuse = state.range(4) != 0;
  const DepthMap& map = benchMap(res, back);
  VolumeBuildOptions options;
  options.triangulation = perfect ? Triangulation::Perfect : Triangulation::Fixed;
  options.blur = blur;
  options.cap = FarCap::Exact;

  const VolumeBuildResult probe = buildVolume(map, options);
  const std::size_t bytes = map.depth.size() * sizeof(float) +
                            probe.mesh.positions.size() * sizeof(glm::dvec3) +
                            probe.mesh.triangles.size() * sizeof(probe.mesh.triangles[0]);
  std::vector<char> src(bytes, 1), dst(bytes, 0);  // pre-faulted

  VolumeBuilder builder;  // reuse: one builder and one result for every iteration
  VolumeBuildResult reused;
  builder.build(map, options, reused);
  double buildSeconds = 0.0, floorSeconds = 0.0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    if (reuse) {
      builder.build(map, options, reused);
      benchmark::DoNotOptimize(reused.mesh.triangles.data());
    } else {
      VolumeBuildResult r = buildVolume(map, options);
      benchmark::DoNotOptimize(r.mesh.triangles.data());
    }
    const auto t1 = std::chrono::steady_clock::now();
    std::memcpy(dst.data(), src.data(), bytes);
    benchmark::DoNotOptimize(dst.data());
    benchmark::ClobberMemory();
    const auto t2 = std::chrono::steady_clock::now();
    buildSeconds += std::chrono::duration<double>(t1 - t0).count();
    floorSeconds += std::chrono::duration<double>(t2 - t1).count();
  }
  const double n = double(state.iterations());
  state.counters["build_ms"] = 1e3 * buildSeconds / n;
  state.counters["floor_ms"] = 1e3 * floorSeconds / n;
  state.counters["ratio"] = buildSeconds / floorSeconds;
  state.counters["MB"] = double(bytes) / 1e6;
  state.counters["tris"] = double(probe.mesh.triangleCount());
  state.counters["flipped"] = double(probe.stats.flippedQuads) / double(std::max<std::size_t>(probe.stats.quads, 1));
  state.counters["cap_before"] = double(probe.stats.capTrianglesBefore);
  state.counters["cap_after"] = double(probe.stats.capTrianglesAfter);
  state.SetLabel(std::string(back ? "back" : "front") + (perfect ? " perfect" : " fixed") + (blur ? " blur" : "") +
                 (reuse ? " reused" : " fresh"));
}

BENCHMARK(BM_BuildVolume)
    ->ArgNames({"res", "perfect", "blur", "back", "reuse"})
    ->ArgsProduct({{256, 512, 1024, 2048}, {0, 1}, {0, 1}, {1, 0}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Silhouette refinement: a reused builder, perfect triangulation, exact cap, K = refine steps (0 =
// off, the same build as BM_BuildVolume's reused one; kRecommendedRefineSteps, the sweep's), and
// the sub-grid (grid = refineSubdivisions, 1 = off). The analytic oracle costs far less than
// Embree's rays, so rays_ms is reported apart: what refinement adds to the build itself is
// build_ms - rays_ms - the K = 0 build_ms.
void BM_RefineVolume(benchmark::State& state) {
  const int res = int(state.range(0));
  const bool back = state.range(1) != 0;
  const int steps = int(state.range(2));
  const int grid = int(state.range(3));
  const DepthMap& map = benchMap(res, back);
  VolumeBuildOptions options;
  options.refineSteps = steps;
  options.refineSubdivisions = grid;
  options.depthOracle = benchOracle();
  VolumeBuilder builder;
  VolumeBuildResult result;
  builder.build(map, options, result);
  double seconds = 0.0, rays = 0.0, refine = 0.0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    builder.build(map, options, result);
    benchmark::DoNotOptimize(result.mesh.triangles.data());
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    rays += result.stats.msRays;
    refine += result.stats.msRefine;
  }
  const double n = double(state.iterations());
  state.counters["build_ms"] = 1e3 * seconds / n;
  state.counters["refine_ms"] = refine / n;
  state.counters["rays_ms"] = rays / n;
  state.counters["edges"] = double(result.stats.boundaryEdges);
  state.counters["rays"] = double(result.stats.raysCast);
  state.counters["tris"] = double(result.mesh.triangleCount());
  state.SetLabel(std::string(back ? "back" : "front") + " refine " + std::to_string(steps) + " grid " +
                 std::to_string(grid));
}

BENCHMARK(BM_RefineVolume)
    ->ArgNames({"res", "back", "refine", "grid"})
    ->ArgsProduct({{128, 256, 512, 1024}, {1, 0}, {0, kRecommendedRefineSteps}, {1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
// The sub-grid (refineSubdivisions) at the sweep's steps.
BENCHMARK(BM_RefineVolume)
    ->ArgNames({"res", "back", "refine", "grid"})
    ->ArgsProduct({{128, 256, 512, 1024}, {1, 0}, {kRecommendedRefineSteps}, {2, kRecommendedRefineSubdivisions}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
