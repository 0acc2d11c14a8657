// A point light's cube map: six square depth maps, one per face of the axis-aligned cube around
// the light, each the depth map of a 90-degree spot view from the light's position.
//
// Faces in OpenGL's order (face f is GL_TEXTURE_CUBE_MAP_POSITIVE_X + f): +X, -X, +Y, -Y, +Z, -Z.
// Face f looks along its direction D with the up vector U of OpenGL's cube-map table (right
// R = D x U):
//   +X: D +X, U -Y, R -Z     -X: D -X, U -Y, R +Z     +Y: D +Y, U +Z, R +X
//   -Y: D -Y, U -Z, R +X     +Z: D +Z, U -Y, R +X     -Z: D -Z, U -Y, R -X
// so a face's texel (i, j) (depth_map.h: i right, j up, row 0 at the bottom) is the texel that
// OpenGL's cube-map lookup addresses as (s, t) = ((i + 0.5) / N, (j + 0.5) / N): a cube texture
// filled row by row from these maps samples the same depths.
//
// Texel centres: those of each face's map, (i + 0.5) / N * 2 - 1 in the face's NDC; no centre
// lies on a cube edge. Neighbours across an edge: the border texels of two faces that share a
// cube edge pair up one to one along it (the same N, the same distance 1/N in NDC from the
// edge), and each cube corner has one corner texel on each of its three faces. cubeTexelAcross
// gives the pairing; the point light's volume (cube_volume.h) closes its sheet with it.
//
// Depth: each face's map stores its own view depth (-z of its view), which for a point of the
// face's pyramid is the largest |coordinate| of the offset from the light (cubeDepth). The near
// and far planes are the light's, the same for all six faces, so the far surface is the cube
// of half side `far` around the light.
#pragma once

#include <array>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "shadowvol/depth_map.h"
#include "shadowvol/light.h"

namespace shadowvol {

inline constexpr int kCubeFaces = 6;

/// "+x", "-x", "+y", "-y", "+z", "-z".
const char* cubeFaceName(int face);
glm::dvec3 cubeFaceDirection(int face);  ///< D of the table above
glm::dvec3 cubeFaceUp(int face);         ///< U of the table above

/// The spot light of face `face` of a point light: the same position, near and far, direction
/// and up of the table, a 90-degree opening.
Light cubeFaceLight(const Light& point, int face);

/// Face `face`'s spot light widened by `guard` texels on every side for an N x N face: an
/// (N + 2 guard)^2 map of it has the face's texel centres, texel (i, j) of the face being its
/// texel (i + guard, j + guard), and guard more texels of the same size beyond each border
/// (opening 2 atan((N + 2 guard) / N)), its near plane the point light's divided by (N + 2 guard) / N
/// (what lies in the band belongs to a neighbouring face and may lie that much nearer along this
/// face's axis). The refined GPU cube volume's faces (docs/gpu.md).
Light guardedCubeFaceLight(const Light& point, int face, int n, int guard);

/// The direction of face `face`'s texel (i, j) of an N x N cube map, scaled to face depth 1:
/// D + x R + y U with x, y the texel centre's NDC ((i + 0.5) / N * 2 - 1; i, j may be
/// fractional), so light position + d times it is the texel's point at face depth d.
glm::dvec3 cubeTexelDirection(int n, int face, double i, double j);

/// A point light's depth of a world offset from it: the largest |coordinate| (the view depth of
/// the face whose pyramid holds it).
double cubeDepth(const glm::dvec3& offset);

struct CubeTexel {
  int face = 0, i = 0, j = 0;
  bool operator==(const CubeTexel&) const = default;
};

/// Where an offset from the light falls: its face (the axis of the largest |coordinate|; ties
/// go to the lower axis, x before y before z, so every offset has one face), continuous texel
/// coordinates on that face (texel centres at integers, as DepthMap::texelOf) and its depth.
struct CubeLookup {
  int face = 0;
  glm::dvec2 texel{0.0};
  double depth = 0.0;
};
CubeLookup cubeLookup(const glm::dvec3& offset, int n);

/// The texel across the border of face `face` of an N x N cube map: (i, j) is a border texel of
/// the face and (i + di, j + dj) (one of di, dj is +-1, the other 0) lies outside it; the result
/// is the border texel of the neighbouring face at the same place along the shared cube edge.
CubeTexel cubeTexelAcross(int n, int face, int i, int j, int di, int dj);

/// Six N x N depth maps of a point light, faces[f] of cubeFaceLight(light, f).
struct CubeDepthMap {
  std::array<DepthMap, kCubeFaces> faces;
  int size() const { return faces[0].width; }
  CaptureMode capture() const { return faces[0].capture; }
  double nearPlane() const { return faces[0].nearPlane; }
  double farPlane() const { return faces[0].farPlane; }
  glm::dvec3 lightPosition() const;  ///< the apex the faces share (relative to origin)
};

/// Six empty (kNoHit) maps of a point light at N x N; InputError for a size checkDepthMapSize
/// refuses (naming six maps' memory).
CubeDepthMap makeCubeDepthMap(const Light& point, int n, CaptureMode capture);

}  // namespace shadowvol
