#include "shadowvol/embree/embree_depth_oracle.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "shadowvol/check.h"
#include "shadowvol/embree/capture_ray.h"
#include "shadowvol/embree/embree_scene.h"

namespace shadowvol {

struct EmbreeDepthOracle::Impl {
  EmbreeDevice device;
  EmbreeScene scene;
  static std::vector<const TriangleMesh*> meshesOf(const Scene& s) {
    std::vector<const TriangleMesh*> meshes;
    for (const auto& o : s.objects) meshes.push_back(&o.mesh);
    return meshes;
  }
  explicit Impl(const Scene& s) : scene(device, meshesOf(s)) {}
};

EmbreeDepthOracle::EmbreeDepthOracle(const Scene& scene) : impl_(std::make_unique<Impl>(scene)) {}
EmbreeDepthOracle::~EmbreeDepthOracle() = default;

DepthOracle EmbreeDepthOracle::oracle() const {
  const Impl* impl = impl_.get();
  return [impl](const DepthMap& map, std::span<const glm::dvec2> ndc, std::span<float> depth) {
    SV_CHECK_EQ(ndc.size(), depth.size());
    const TexelUnprojector unproject(map);
    const float tNear = float(map.nearPlane), tFar = float(map.farPlane);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, ndc.size(), 64), [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t k = r.begin(); k != r.end(); ++k) {
        // Texel coordinates of the point (texel centres at integers), as captureDepthEmbree's rays.
        const double i = (ndc[k].x + 1.0) * 0.5 * map.width - 0.5, j = (ndc[k].y + 1.0) * 0.5 * map.height - 0.5;
        depth[k] = captureRay(impl->scene.get(), unproject.ray(i, j), tNear, tFar, map.capture);
      }
    });
    impl->device.throwIfError();
  };
}

}  // namespace shadowvol
