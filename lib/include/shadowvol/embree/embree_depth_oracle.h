// The depth oracle (depth_oracle.h) of a scene, by ray casting with Embree: the same rays and
// capture rule as captureDepthEmbree, at any point of the light's image plane.
#pragma once

#include <memory>

#include "shadowvol/depth_oracle.h"
#include "shadowvol/scene.h"

namespace shadowvol {

/// Owns an Embree device and the scene's BVH (built once); oracle() hands out a DepthOracle that
/// casts one ray per point, in parallel (TBB), each as captureDepthEmbree casts the ray of a texel
/// centre: from the light through the point, limited to the map's [near, far], recorded by the
/// map's capture mode. So at a texel centre it returns the CPU capture's value exactly. The
/// DepthOracle refers to this object: keep it alive while the oracle is in use.
class EmbreeDepthOracle {
 public:
  explicit EmbreeDepthOracle(const Scene& scene);
  ~EmbreeDepthOracle();
  EmbreeDepthOracle(const EmbreeDepthOracle&) = delete;
  EmbreeDepthOracle& operator=(const EmbreeDepthOracle&) = delete;

  DepthOracle oracle() const;
  /// The SurfaceEndOracle (depth_oracle.h) of the same scene and capture rule: one ray per query
  /// (captureHit), then triangleExit (triangle_exit.h) on the triangle it records.
  SurfaceEndOracle surfaceEnds() const;
  /// The NearerSurfaceOracle (depth_oracle.h) of the same scene: findNearerSurfaces and
  /// findOpenRims (nearer_surfaces.h) over the triangles the oracle's rays see (their rims found
  /// once, on the first search).
  NearerSurfaceOracle nearerSurfaces() const;
  /// The CasterFaceOracle (depth_oracle.h) of the same scene: findCasterFaces (caster_faces.h)
  /// over its triangles, the closed ones as entry capture finds them (found once, on the first call).
  CasterFaceOracle casterFaces() const;
  /// The hand-over's oracles (depth_oracle.h; VolumeBuildOptions::withoutCasters): one ray of the
  /// capture per point, and where it records a mesh handed to the prisms (handedToPrisms,
  /// caster_faces.h), one more into an Embree scene of the other meshes (made for the last set of
  /// meshes left out, kept until a map leaves out another set; the set itself kept per light).
  CasterFreeOracles withoutCasters() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace shadowvol
