// A flat bounding-volume hierarchy over a mesh's triangles, for rays cast where Embree cannot go:
// the refined GPU volume's bisection rays (shaders/silhouette_rays.comp, docs/gpu.md "Crossings
// from GPU rays") walk it in a compute shader. Built once per scene on the CPU.
//
// Layout (std430-ready, 32 bytes a node): node 0 is the root; an inner node (count 0) has its
// children at `first` and `first + 1`; a leaf holds triangles[first .. first + count) of
// `triangles`, the mesh's triangles (three vertex indices each) in leaf order. Boxes are the
// float bounds of their triangles' vertices, so a ray that hits a triangle in float hits every box
// above it. Built by binned surface-area splits (kBins bins along the longest axis of the
// centroids' bounds), leaves of at most kBvhMaxLeafTriangles (more only at kBvhMaxDepth, where
// splitting stops); deterministic (ties by triangle index).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "shadowvol/triangle_mesh.h"

namespace shadowvol {

struct BvhNode {
  float lo[3];
  std::uint32_t first;  ///< inner: the first child's node index; leaf: the first triangle
  float hi[3];
  std::uint32_t count;  ///< 0: inner node; else the leaf's triangle count
};
static_assert(sizeof(BvhNode) == 32);

struct TriangleBvh {
  std::vector<BvhNode> nodes;                             ///< node 0 the root (none for no triangles)
  std::vector<std::array<std::uint32_t, 3>> triangles;    ///< the mesh's triangles in leaf order
  std::vector<std::uint32_t> order;                       ///< triangles[k] is mesh.triangles[order[k]]
  int depth = 0;                                          ///< the longest root-to-leaf path (nodes)
};

inline constexpr int kBvhMaxLeafTriangles = 4;
inline constexpr int kBvhMaxDepth = 64;  ///< the traversal's stack; the build stops splitting there

/// The hierarchy of `mesh`'s triangles (see the header comment). Degenerate triangles are kept
/// (a ray never hits them). Throws InputError for a mesh of 2^31 or more triangles.
TriangleBvh buildTriangleBvh(const TriangleMesh& mesh);

}  // namespace shadowvol
