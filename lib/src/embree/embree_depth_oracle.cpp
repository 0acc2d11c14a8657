#include "shadowvol/embree/embree_depth_oracle.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <mutex>
#include <vector>

#include <glm/mat4x4.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "shadowvol/caster_faces.h"
#include "shadowvol/check.h"
#include "shadowvol/embree/capture_ray.h"
#include "shadowvol/embree/embree_scene.h"
#include "shadowvol/nearer_surfaces.h"
#include "shadowvol/triangle_adjacency.h"
#include "shadowvol/triangle_exit.h"

namespace shadowvol {

struct EmbreeDepthOracle::Impl {
  EmbreeDevice device;
  EmbreeScene scene;
  std::vector<TriangleSoup> soups;  // views of the Embree scene's own buffers, geometry by geometry
  // Each soup's rims (TriangleSoup::rims) and whether it is a closed surface (TriangleSoup::closed),
  // found on the first search: at once for a soup closed as stored, else on a welded copy.
  std::once_flag shapeOnce;
  std::vector<std::vector<std::uint32_t>> rims;
  std::vector<TriangleSoup> closedSoups;  // soups with `closed` and `rims` set (entry capture)
  std::vector<TriangleSoup> openSoups;    // soups with `rims` set, `closed` false (the other captures)
  // Entry capture reads `closed` (its faces towards the light count); the others must not.
  std::span<const TriangleSoup> soupsFor(CaptureMode capture) {
    std::call_once(shapeOnce, [this] {
      rims.resize(soups.size());
      closedSoups = openSoups = soups;
      for (std::size_t g = 0; g < soups.size(); ++g) {
        const std::span<const std::uint32_t> i = soups[g].indices;
        // Closed as stored (most closed meshes): no rims, and no copy to weld.
        static_assert(sizeof(std::array<std::uint32_t, 3>) == 3 * sizeof(std::uint32_t));
        if (closedAsStored({reinterpret_cast<const std::array<std::uint32_t, 3>*>(i.data()), i.size() / 3},
                           soups[g].xyz.size() / 3)) {
          closedSoups[g].closed = true;
          continue;
        }
        bool closed = false;
        rims[g] = openRims(meshOf(soups[g]), &closed);
        closedSoups[g].rims = openSoups[g].rims = rims[g];
        closedSoups[g].closed = closed;  // isClosedSurface (the rims' seal may leave none on an open soup)
      }
    });
    return capture == CaptureMode::Entry ? closedSoups : openSoups;
  }
  // The closed soups with their edge neighbours (TriangleSoup::neighbours) for the face prisms,
  // found on the first selection of faces.
  std::once_flag neighboursOnce;
  std::vector<std::vector<std::int32_t>> neighbours;
  std::vector<TriangleSoup> prismSoups;
  std::span<const TriangleSoup> soupsForPrisms() {
    std::call_once(neighboursOnce, [this] {
      const std::span<const TriangleSoup> closed = soupsFor(CaptureMode::Entry);  // `closed` set
      prismSoups.assign(closed.begin(), closed.end());
      neighbours.resize(prismSoups.size());
      for (std::size_t g = 0; g < prismSoups.size(); ++g)
        if (prismSoups[g].closed) {
          neighbours[g] = triangleNeighbours(meshOf(prismSoups[g]));
          prismSoups[g].neighbours = neighbours[g];
        }
    });
    return prismSoups;
  }
  // The hand-over's set for one light (withoutCasters): which soups the prisms hold whole, by
  // geometry ID, and the Embree scene of the others. Kept for the last light asked about (shared
  // with the rays still running on it when another light asks).
  struct HandOverSet {
    glm::dmat4 view{}, projection{};
    double nearPlane = 0.0, farPlane = 0.0;
    int width = 0, height = 0;
    std::vector<std::uint8_t> soupHanded;      // per soup
    std::vector<std::uint8_t> geometryHanded;  // per geometry ID
    std::unique_ptr<EmbreeScene> without;
    bool sameLight(const DepthMap& m) const {
      return view == m.lightView && projection == m.lightProjection && nearPlane == m.nearPlane &&
             farPlane == m.farPlane && width == m.width && height == m.height;
    }
  };
  std::vector<unsigned> soupGeometry;  // per soup: its geometry ID
  std::mutex handOverMutex;
  std::shared_ptr<const HandOverSet> handOver;
  std::shared_ptr<const HandOverSet> handOverFor(const DepthMap& map) {
    const std::lock_guard<std::mutex> lock(handOverMutex);
    if (handOver && handOver->sameLight(map)) return handOver;
    const std::span<const TriangleSoup> closed = soupsFor(CaptureMode::Entry);  // `closed` set
    auto set = std::make_shared<HandOverSet>();
    set->view = map.lightView;
    set->projection = map.lightProjection;
    set->nearPlane = map.nearPlane;
    set->farPlane = map.farPlane;
    set->width = map.width;
    set->height = map.height;
    set->soupHanded.resize(closed.size());
    set->geometryHanded.assign(scene.geometryCount(), 0);
    std::vector<TriangleMesh> kept;
    for (std::size_t g = 0; g < closed.size(); ++g) {
      set->soupHanded[g] = set->geometryHanded[soupGeometry[g]] = handedToPrisms(map, closed[g]);
      if (!set->soupHanded[g]) kept.push_back(meshOf(closed[g]));
    }
    std::vector<const TriangleMesh*> meshes;
    for (const TriangleMesh& m : kept) meshes.push_back(&m);
    set->without = std::make_unique<EmbreeScene>(device, meshes);  // Embree copies the buffers
    handOver = set;
    return handOver;
  }
  static std::vector<const TriangleMesh*> meshesOf(const Scene& s) {
    std::vector<const TriangleMesh*> meshes;
    for (const auto& o : s.objects) meshes.push_back(&o.mesh);
    return meshes;
  }
  explicit Impl(const Scene& s) : scene(device, meshesOf(s)) {
    for (std::size_t g = 0; g < s.objects.size(); ++g) {  // geometry IDs 0, 1, 2, ... in object order
      const TriangleMesh& m = s.objects[g].mesh;
      RTCGeometry geom = rtcGetGeometry(scene.get(), unsigned(g));
      const auto* v = static_cast<const float*>(rtcGetGeometryBufferData(geom, RTC_BUFFER_TYPE_VERTEX, 0));
      const auto* i = static_cast<const std::uint32_t*>(rtcGetGeometryBufferData(geom, RTC_BUFFER_TYPE_INDEX, 0));
      if (v && i && !m.triangles.empty()) soupGeometry.push_back(unsigned(g));
      if (v && i && !m.triangles.empty())
        soups.push_back({std::span<const float>(v, 3 * m.positions.size()), std::span<const std::uint32_t>(i, 3 * m.triangles.size()),
                         false, {}, {}});
    }
  }
};

namespace {

// One ray per point of `ndc`, in parallel, each as captureDepthEmbree casts a texel centre's ray.
void castOracleRays(RTCScene scene, const DepthMap& map, std::span<const glm::dvec2> ndc, std::span<float> depth) {
  SV_CHECK_EQ(ndc.size(), depth.size());
  const TexelUnprojector unproject(map);
  const float tNear = float(map.nearPlane), tFar = float(map.farPlane);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, ndc.size(), 64), [&](const tbb::blocked_range<std::size_t>& r) {
    std::vector<TexelUnprojector::Ray> rays(r.size());
    for (std::size_t k = r.begin(); k != r.end(); ++k) {
      const glm::dvec2 t = map.texelOfNdc(ndc[k]);  // as captureDepthEmbree's rays
      rays[k - r.begin()] = unproject.ray(t.x, t.y);
    }
    captureRays(scene, rays, tNear, tFar, map.capture, depth.subspan(r.begin(), r.size()));
  });
}

}  // namespace

EmbreeDepthOracle::EmbreeDepthOracle(const Scene& scene) : impl_(std::make_unique<Impl>(scene)) {}
EmbreeDepthOracle::~EmbreeDepthOracle() = default;

DepthOracle EmbreeDepthOracle::oracle() const {
  const Impl* impl = impl_.get();
  return [impl](const DepthMap& map, std::span<const glm::dvec2> ndc, std::span<float> depth) {
    castOracleRays(impl->scene.get(), map, ndc, depth);
    impl->device.throwIfError();
  };
}

CasterFreeOracles EmbreeDepthOracle::withoutCasters() const {
  Impl* impl = impl_.get();
  CasterFreeOracles o;
  o.depth = [impl](const DepthMap& map, std::span<const glm::dvec2> ndc, std::span<float> depth,
                   std::span<std::uint8_t> handed) {
    SV_CHECK_EQ(ndc.size(), depth.size());
    SV_CHECK_EQ(ndc.size(), handed.size());
    std::fill(handed.begin(), handed.end(), std::uint8_t(0));
    if (map.capture == CaptureMode::Midpoint) {  // no single surface recorded: nothing handed over
      castOracleRays(impl->scene.get(), map, ndc, depth);
      impl->device.throwIfError();
      return;
    }
    const std::shared_ptr<const Impl::HandOverSet> set = impl->handOverFor(map);
    const TexelUnprojector unproject(map);
    const float tNear = float(map.nearPlane), tFar = float(map.farPlane);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, ndc.size(), 64), [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t k = r.begin(); k != r.end(); ++k) {
        const glm::dvec2 t = map.texelOfNdc(ndc[k]);
        const TexelUnprojector::Ray ray = unproject.ray(t.x, t.y);
        const CapturedHit hit = captureHit(impl->scene.get(), ray, tNear, tFar, map.capture);
        depth[k] = hit.depth;
        if (hit.geomID == RTC_INVALID_GEOMETRY_ID || !set->geometryHanded[hit.geomID]) continue;
        handed[k] = 1;
        depth[k] = captureRay(set->without->get(), ray, tNear, tFar, map.capture);
      }
    });
    impl->device.throwIfError();
  };
  o.nearerSurfaces = [impl](const DepthMap& map, std::span<const float> limit, std::span<const float> rimLimit,
                            std::span<std::uint8_t> flags) {
    const std::span<const TriangleSoup> soups = impl->soupsFor(map.capture);
    const std::shared_ptr<const Impl::HandOverSet> set = impl->handOverFor(map);  // soupsFor's order either way
    std::vector<TriangleSoup> kept;
    for (std::size_t g = 0; g < soups.size(); ++g)
      if (!set->soupHanded[g]) kept.push_back(soups[g]);
    findNearerSurfaces(map, kept, limit, flags);
    if (!rimLimit.empty()) findOpenRims(map, kept, rimLimit, flags);
  };
  return o;
}

SurfaceEndOracle EmbreeDepthOracle::surfaceEnds() const {
  const Impl* impl = impl_.get();
  return [impl](const DepthMap& map, std::span<const glm::dvec2> from, std::span<const glm::dvec2> to,
                std::span<double> t, std::span<std::array<glm::dvec3, 3>> triangle) {
    SV_CHECK_EQ(from.size(), to.size());
    SV_CHECK_EQ(from.size(), t.size());
    SV_CHECK_EQ(from.size(), triangle.size());
    const TexelUnprojector unproject(map);
    const float tNear = float(map.nearPlane), tFar = float(map.farPlane);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, from.size(), 64), [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t k = r.begin(); k != r.end(); ++k) {
        const glm::dvec2 a = map.texelOfNdc(from[k]), b = map.texelOfNdc(to[k]);
        const CapturedHit hit = captureHit(impl->scene.get(), unproject.ray(a.x, a.y), tNear, tFar, map.capture);
        t[k] = std::nan("");
        triangle[k].fill(glm::dvec3(std::nan("")));
        if (hit.geomID != RTC_INVALID_GEOMETRY_ID) {
          RTCGeometry geom = rtcGetGeometry(impl->scene.get(), hit.geomID);
          const auto* index = static_cast<const unsigned*>(rtcGetGeometryBufferData(geom, RTC_BUFFER_TYPE_INDEX, 0));
          const auto* vertex = static_cast<const float*>(rtcGetGeometryBufferData(geom, RTC_BUFFER_TYPE_VERTEX, 0));
          std::array<glm::dvec3, 3> corners;
          for (int c = 0; c < 3; ++c) {
            const float* v = vertex + 3 * std::size_t(index[3 * std::size_t(hit.primID) + std::size_t(c)]);
            corners[std::size_t(c)] = glm::dvec3(v[0], v[1], v[2]);
          }
          t[k] = triangleExit(map, corners, a, b);
          if (!std::isnan(t[k])) triangle[k] = corners;
        }
      }
    });
    impl->device.throwIfError();
  };
}

NearerSurfaceOracle EmbreeDepthOracle::nearerSurfaces() const {
  Impl* impl = impl_.get();
  return [impl](const DepthMap& map, std::span<const float> limit, std::span<const float> rimLimit,
                std::span<std::uint8_t> flags) {
    const std::span<const TriangleSoup> soups = impl->soupsFor(map.capture);
    findNearerSurfaces(map, soups, limit, flags);
    if (!rimLimit.empty()) findOpenRims(map, soups, rimLimit, flags);
  };
}

CasterFaceOracle EmbreeDepthOracle::casterFaces() const {
  Impl* impl = impl_.get();
  return [impl](const DepthMap& map, std::span<const std::uint8_t> quads) {
    return findCasterFaces(map, impl->soupsForPrisms(), quads);
  };
}

}  // namespace shadowvol
