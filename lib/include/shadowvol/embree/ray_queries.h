// Ray queries that validate the shadow volume (issue 5): primary rays through pixel centres as
// the GL camera samples them, exact shadow rays, and signed crossing counts of the volume.
//
// Every per-pixel array is in image order: index r * width + x with row r = 0 at the TOP (as in
// the PNG files); GL's window row is height - 1 - r. Pixel centres: camera NDC
// ((x + 0.5) / W * 2 - 1, (y_gl + 0.5) / H * 2 - 1), exactly where OpenGL samples.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "shadowvol/camera.h"
#include "shadowvol/depth_map.h"  // TexelUnprojector::Ray
#include "shadowvol/embree/embree_scene.h"
#include "shadowvol/light.h"
#include "shadowvol/scene.h"

namespace shadowvol {

/// What the camera sees at each pixel.
struct CameraHits {
  int width = 0, height = 0;
  std::vector<float> depth;        ///< camera view depth (-z in camera view) of the visible point; +inf = background
  std::vector<glm::dvec3> point;   ///< world position of the visible point (undefined for background)
  std::vector<glm::vec3> normal;   ///< unit geometric normal, turned to face the camera
  struct Triangle {
    unsigned geomID, primID;  ///< Embree's ids of the triangle hit (RTC_INVALID_GEOMETRY_ID for background)
  };
  std::vector<Triangle> triangle;
  bool isBackground(std::size_t k) const { return !(depth[k] < INFINITY); }
};

/// Casts one primary ray per pixel centre, limited to the camera's [near, far] (the GL clip
/// range), through the scene's geometry. Parallel and deterministic.
CameraHits castPrimaryRays(const EmbreeScene& scene, const Camera& camera);

/// The visible depth (CameraHits::depth's meaning: camera view depth within [near, far], +inf =
/// background) along the ray of each of `pixels` (indices, rows top first) moved by each of
/// `offsets` (pixels, as PrimaryRays::ray's dx, dy): offsets.size() depths per pixel, pixel-major.
std::vector<double> visibleDepths(const EmbreeScene& scene, const Camera& camera,
                                  const std::vector<std::size_t>& pixels, const std::vector<glm::dvec2>& offsets);

enum class PixelClass : std::uint8_t {
  Background = 0,    ///< the camera ray hits nothing
  FacingAway = 1,    ///< the surface faces away from the light (n . L <= 0): dark, not a shadow error
  OutsideLight = 2,  ///< outside the light's frustum (or [near, far]): the light does not reach it
  Lit = 3,
  Shadowed = 4,
};

/// The legacy shadow-ray offset's scene part: 1e-4 of the scene's bounding radius. The exact
/// reference no longer uses it by default (sceneOffset 0 below): it called lit a band of shadowed
/// points along shadows' outlines (docs/results/reference-offset). `validate --exact-offset-scale 1`
/// passes it, to repeat figures measured before 2026-12-06.
double shadowRayOffset(const Scene& scene);

/// The offset along the normal at which a shadow ray from p starts:
///   max(min(sceneOffset, 1e-3 * local), 2^-21 * (max|p| + local)),  local = distance from p to the
///   camera (and to a spot light, whichever is smaller).
/// The floor, at least four float spacings (float's spacing at a magnitude m is at most 2^-23 m) of
/// the point's coordinates and of its distance along the camera ray, lifts the start above the
/// round-off of Embree's float hit point, so that the triangles next to the one the point lies on
/// are not hit at a distance of round-off (the floors measured on six scenes:
/// docs/results/reference-offset).
/// The cap keeps a large ground (radius 1e6) from lifting rays from a small object far when a scene
/// part is given.
double shadowRayOffsetAt(double sceneOffset, const glm::dvec3& p, double localScale);

/// Exact shadows: one occlusion ray per visible point towards the light (to the spot light's
/// apex; along -direction for a directional light), started shadowRayOffsetAt(sceneOffset, ...)
/// off the surface along its normal, and passing through the triangle the point lies on (a filter
/// skips it, so round-off in the hit point cannot shadow a point by its own triangle). The
/// default, sceneOffset 0, starts each ray at the floor: the reference every figure since
/// 2026-12-06 uses. Parallel and deterministic. With `occluders`, each Shadowed pixel's nearest
/// occluder along that ray (its geometry ID: the object's index in the scene the BVH was built
/// from) is stored there by one more ray, kNoOccluder elsewhere.
inline constexpr std::uint32_t kNoOccluder = 0xffffffffu;
std::vector<PixelClass> exactShadows(const EmbreeScene& scene, const Scene& description, const CameraHits& hits,
                                     double sceneOffset = 0.0, std::vector<std::uint32_t>* occluders = nullptr);

/// Signed crossing counts of a closed volume along each camera ray.
///  zfail[k]: from the visible point to infinity, +1 for each crossing that leaves the volume
///            (geometric normal along the ray), -1 for each that enters: the GPU's z-fail stencil.
///  zpass[k]: from the eye to the visible point, +1 entering, -1 leaving: the z-pass count.
/// Background pixels (nothing visible) get zfail = zpass = 0.
/// Merge rule: a ray through a shared edge or vertex may report one crossing several times
/// (Embree's robust mode guarantees no crossing is missed, not that it is reported once). Hits
/// whose distances differ by at most kCrossingMergeTolerance (relative) and whose triangles touch
/// (share a vertex, both hits on their triangles' borders: within kCrossingMergeTolerance x t of
/// an edge, onTriangleBorder; directly or through others of the group) form one event whose sign is
/// the sign of the sum of their signs: +1+1 -> +1 (one crossing seen twice), +1-1 -> 0 (the ray
/// grazes a fold without crossing). Other hits are crossings of their own however close: two walls
/// a hair apart, two faces that overlap (the face prisms' far caps around a vertex where the faces
/// fold over as seen from the light), two parts' coincident caps (VolumeMesh::partStarts).
/// Edge-on hits (normal perpendicular to the ray) count 0.
/// Ties with the visible point: where the volume's surface lies on the visible surface (a back
/// capture's sheet on an occluder's back face that the camera sees), the GPU's depth test and the
/// ray parameter decide the order of coincident surfaces by round-off. Events within the tie band
/// |t - t_visible| <= tieTolerance(t_visible) * t_visible count as behind the point in zfail
/// (the camera's reversed-Z GL_GREATER fails on equal depths), and zfailMin / zfailMax give the range of z-fail counts for
/// every split of the band's events (each split is a consistent ordering; the values of successive
/// splits differ by one, so every integer in the range is admissible).
struct CrossingCounts {
  int width = 0, height = 0;
  std::vector<std::int32_t> zfail, zpass;
  std::vector<std::int32_t> zfailMin, zfailMax;  ///< admissible z-fail range (== zfail without ties)
};
inline constexpr double kCrossingMergeTolerance = 1e-6;

/// Relative half-width of the tie band at camera view depth d: 1e-4, or 16 steps of a 24-bit depth
/// buffer at d (2^-24 d (far - near) / (far near) relative), whichever is larger. The renderer's
/// camera buffer is 32-bit float with reversed Z, finer at every depth: the band is conservative.
double tieTolerance(const Camera& camera, double d);

/// `volume` holds one mesh (the merge rule compares its vertex indices).
CrossingCounts countCrossings(const EmbreeScene& volume, const Camera& camera, const CameraHits& hits);

/// One crossing of a pixel ray with the volume: the ray parameter (camera view depth, as
/// CameraHits::depth) and +1 leaving (normal along the ray), -1 entering, 0 edge-on; for the merge
/// rule the vertex indices of the triangle crossed and whether the hit lies on its border
/// (unknown: kUnknownCorners, which touches every other crossing, so that such hits within the
/// tolerance always merge).
struct VolumeCrossing {
  static constexpr std::array<std::uint32_t, 3> kUnknownCorners{0xffffffffu, 0xffffffffu, 0xffffffffu};
  double t;
  int sign;
  std::array<std::uint32_t, 3> corners = kUnknownCorners;
  bool onBorder = true;
  /// Whether the two hits may be one crossing reported twice: either is unknown, or the triangles
  /// share a vertex index and both hits lie on their borders.
  bool touches(const VolumeCrossing& o) const;
};

/// Whether the point of barycentric coordinates (u, v) (weights of b and c) on triangle (a, b, c)
/// lies within kCrossingMergeTolerance x t (world units, t the hit's ray parameter) of one of its
/// edges: a crossing that a ray through a shared edge or vertex may report once per triangle.
/// Measured in world units, so that a sliver's hits (whose barycentric coordinates err most) are
/// judged as a large triangle's are.
bool onTriangleBorder(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, double u, double v, double t);

/// A pixel's counts (see CrossingCounts).
struct PixelCounts {
  int zfail, zpass, zfailMin, zfailMax;
};

/// The counting rule of countCrossings for one pixel, written once: sorts `crossings`, merges
/// hits within kCrossingMergeTolerance into events, and splits them at tVisible with the tie
/// band `band` (world units). Also used by the double-precision recount (validate).
PixelCounts countPixel(std::vector<VolumeCrossing>& crossings, double tVisible, double band);

/// The primary rays of a camera, the camera's inverse matrices computed once: ray(x, row) is the
/// ray of pixel (x, row), row 0 at the top (CameraHits' order), its direction scaled so that the
/// ray parameter is the camera view depth.
class PrimaryRays {
 public:
  explicit PrimaryRays(const Camera& camera);
  TexelUnprojector::Ray ray(int x, int row) const;
  /// The ray through the pixel's centre moved by (dx, dy) pixels (dx to the right, dy up).
  TexelUnprojector::Ray ray(int x, int row, double dx, double dy) const;

 private:
  TexelUnprojector unproject_;
  int height_;
};

}  // namespace shadowvol
