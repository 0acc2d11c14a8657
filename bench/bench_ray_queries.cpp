// Crossing-count rays against plain nearest-hit rays (issue 5): the same camera rays through the
// same shadow volume, in the same run. Goal: counting at least half as fast as plain rays.
//
//   ./build/bench/bench_ray_queries
//
// Scene: the built-in default scene; volume from a 512^2 back capture, perfect triangulation,
// exact cap; 640 x 480 camera rays. Every pixel casts one ray in both benchmarks (background
// pixels are given a visible depth at the camera's far plane so the counting pass casts them too).
#include <benchmark/benchmark.h>

#include "shadowvol/embree/depth_capture.h"
#include "shadowvol/embree/ray_queries.h"
#include "shadowvol/volume_builder.h"

namespace {

using namespace shadowvol;

struct Fixture {
  Scene scene = defaultScene();
  EmbreeDevice device;
  TriangleMesh volume;
  std::unique_ptr<EmbreeScene> volumeRt;
  CameraHits hits;
  Camera unbounded;  // the camera with [near, far] opened up so plain rays go as far as counting rays

  Fixture() {
    const DepthMap map = captureDepthEmbree(scene, 512, 512, CaptureMode::Back);
    volume = buildVolume(map).mesh.toTriangleMesh();
    volumeRt = std::make_unique<EmbreeScene>(device, std::vector<const TriangleMesh*>{&volume});
    std::vector<const TriangleMesh*> meshes;
    for (const auto& o : scene.objects) meshes.push_back(&o.mesh);
    hits = castPrimaryRays(EmbreeScene(device, meshes), scene.camera);
    for (auto& d : hits.depth)
      if (!(d < INFINITY)) d = float(scene.camera.farPlane);
    unbounded = scene.camera;
    unbounded.nearPlane = 1e-6;
    unbounded.farPlane = 1e30;
  }
};

Fixture& fixture() {
  static Fixture f;
  return f;
}

void BM_PlainNearestHit(benchmark::State& state) {
  Fixture& f = fixture();
  for (auto _ : state) benchmark::DoNotOptimize(castPrimaryRays(*f.volumeRt, f.unbounded));
  state.SetItemsProcessed(state.iterations() * f.hits.depth.size());
  state.counters["volumeTriangles"] = double(f.volume.triangleCount());
}

void BM_CrossingCounts(benchmark::State& state) {
  Fixture& f = fixture();
  for (auto _ : state) benchmark::DoNotOptimize(countCrossings(*f.volumeRt, f.scene.camera, f.hits));
  state.SetItemsProcessed(state.iterations() * f.hits.depth.size());
  state.counters["volumeTriangles"] = double(f.volume.triangleCount());
}

BENCHMARK(BM_PlainNearestHit)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);
BENCHMARK(BM_CrossingCounts)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

}  // namespace

BENCHMARK_MAIN();
