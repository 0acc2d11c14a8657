// A light's depth map: W x H depths plus the light's matrices, enough to unproject every texel.
//
// Depth quantity: the distance along the light's view axis, in world units, from the light's
// view origin (a spot light's apex; for a directional light the plane through Light::position
// perpendicular to the direction) to the surface: depth = -z of the point in light view space.
// It is NOT the distance along the ray and NOT the nonlinear NDC/window z.
// A texel whose ray hits nothing in [near, far] holds DepthMap::kNoHit (+infinity).
//
// Texel (i, j): i to the right, j up (row 0 is the bottom row, as in OpenGL textures), stored at
// index j * width + i. Texel centre in light NDC: ((i + 0.5) / W * 2 - 1, (j + 0.5) / H * 2 - 1).
#pragma once

#include <cstdint>
#include <span>
#include <limits>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "shadowvol/enum_names.h"
#include "shadowvol/light.h"

namespace shadowvol {

/// What a texel records (Embree: embree/depth_capture.h; GPU: the light pass): Front the first
/// surface, Back the first back face, Midpoint the mean of the first two surfaces, Entry the first
/// surface in front of the first back face (where the light enters the closed occluder that Back
/// records; no hit where Back has none, so lit receivers facing the light stay unrecorded; a face
/// lit nearly edge-on is passed over, kEntryGrazingCos).
enum class CaptureMode { Front, Back, Midpoint, Entry };
inline constexpr EnumNames<CaptureMode, 4> kCaptureModeNames{{{CaptureMode::Back, "back"},
                                                               {CaptureMode::Front, "front"},
                                                               {CaptureMode::Midpoint, "midpoint"},
                                                               {CaptureMode::Entry, "entry"}}};

/// Whether the map records lit surfaces facing the light (Front, Entry): the sheet then lies on
/// them and takes a bias (defaultBias), and the sub-grid measures what it needs (docs/volume.md).
inline bool recordsLitSurfaces(CaptureMode mode) { return mode == CaptureMode::Front || mode == CaptureMode::Entry; }
/// Whether only a back face makes a texel hit (Back, Entry): the hidden-surface search then looks
/// at back faces only, and the occluders must be closed.
inline bool needsBackFace(CaptureMode mode) { return mode == CaptureMode::Back || mode == CaptureMode::Entry; }
/// Entry capture passes over a face lit nearly edge-on: one whose cosine with the light's ray is
/// below this (1/256: its direct light is under one 8-bit level of the light's, so lit or shadowed
/// it shades the same). It records the back face behind instead, as back capture would. Why: the
/// sheet on such a face lies only bias x cos from it, and the camera cannot tell which side of the
/// sheet the face is (a drafted side lit straight down, at N.L = 0.0025, showed as false shadow);
/// behind a closed mesh's lit face the next surface is its back face, so nothing the face would
/// shadow is lost (docs/results/entry-grazing).
inline constexpr double kEntryGrazingCos = 1.0 / 256.0;
/// Whether the light pass takes two depth layers and resolves them (Midpoint, Entry).
inline bool usesTwoLayers(CaptureMode mode) { return mode == CaptureMode::Midpoint || mode == CaptureMode::Entry; }

const char* toString(CaptureMode mode);
/// Parses "back", "front", "midpoint" or "entry"; returns false for anything else.
bool parseCaptureMode(const std::string& text, CaptureMode& mode);

struct DepthMap {
  static constexpr float kNoHit = std::numeric_limits<float>::infinity();

  int width = 0;
  int height = 0;
  std::vector<float> depth;           ///< width * height, see the header comment
  LightType lightType = LightType::Spot;
  glm::dmat4 lightView{1.0};          ///< world -> light view
  glm::dmat4 lightProjection{1.0};    ///< light view -> light clip
  double nearPlane = 0.0;             ///< light view distance of the near plane
  double farPlane = 0.0;              ///< light view distance of the far plane
  CaptureMode capture = CaptureMode::Back;
  /// World = the coordinates the matrices use + origin (the scene's local origin, Scene::origin);
  /// carried into the volume (VolumeMesh::origin) and the side file.
  glm::dvec3 origin{0.0};
  /// Texels of a guard band on every side (guardedLight, light.h): the light's own window is the
  /// inner (width - 2 guard) x (height - 2 guard) texels. Set by the captures that take a guard and
  /// carried by the side file; 0 for a map of the window alone.
  int guard = 0;

  std::size_t index(int i, int j) const { return std::size_t(j) * std::size_t(width) + std::size_t(i); }
  float at(int i, int j) const { return depth[index(i, j)]; }
  static bool isNoHit(float d) { return d == kNoHit; }

  /// Light NDC (x, y) of the centre of texel (i, j); i, j may be fractional.
  glm::dvec2 texelNdc(double i, double j) const;

  /// Light-view point of texel (i, j) at view depth d (d > 0), computed in double through the
  /// inverse projection. For a perspective light the point lies on the ray through the apex.
  glm::dvec3 lightViewPoint(double i, double j, double d) const;

  /// World point of texel (i, j) at view depth d, in double.
  glm::dvec3 worldPoint(double i, double j, double d) const;

  /// The light-view depth of a world point (-z in light view).
  double viewDepthOf(const glm::dvec3& world) const;

  /// Continuous texel coordinates (i, j) of a world point, texel centres at integers; the light's
  /// window spans [-0.5, W - 0.5] x [-0.5, H - 0.5].
  glm::dvec2 texelOf(const glm::dvec3& world) const;
  /// The same coordinates of a point given in light NDC (x, y in [-1, 1] across the window): the
  /// rule of the depth oracles' rays and of the face prisms' hand-over.
  glm::dvec2 texelOfNdc(glm::dvec2 ndc) const {
    return {(ndc.x + 1.0) * 0.5 * width - 0.5, (ndc.y + 1.0) * 0.5 * height - 0.5};
  }

  std::size_t hitCount() const;  ///< texels that are not kNoHit
};

/// Texel -> world unprojection with the inverse matrices computed once (double precision).
/// Gives the same points as DepthMap::worldPoint; use it in loops over texels.
class TexelUnprojector {
 public:
  explicit TexelUnprojector(const DepthMap& map);
  /// The same for any view + projection over a W x H pixel grid (a camera: pixel (x, y) with
  /// y = 0 the bottom row, centres as for texels).
  TexelUnprojector(const glm::dmat4& view, const glm::dmat4& projection, int width, int height);
  /// World point of texel (i, j) (fractional allowed) at light-view depth d > 0.
  glm::dvec3 worldPoint(double i, double j, double d) const;
  /// Light-view point of texel (i, j) at light-view depth d > 0.
  glm::dvec3 lightViewPoint(double i, double j, double d) const;

  /// The world-space ray through texel (i, j): origin at the view's origin (a perspective apex,
  /// or the orthographic view plane), direction with a view-space z of exactly -1, so the ray
  /// parameter t is the view depth.
  struct Ray {
    glm::dvec3 origin, direction;
  };
  Ray ray(double i, double j) const;
  /// Light-view depth of a world point (the ray parameter t above): -(view * p).z.
  double viewDepth(const glm::dvec3& world) const;

 private:
  glm::dmat4 invProjection_, invView_, projection_, view_;
  double width_, height_;
};

/// Makes an empty depth map (all kNoHit) for the light at W x H; aspect is W / H.
DepthMap makeDepthMap(const Light& light, int width, int height, CaptureMode capture);

/// What a map is made for, for the memory it needs: a shadow volume built from it (its vertices
/// and triangles too), the map alone (a depth file, Python's capture_depth), or a shadow map in a
/// rendered frame (its GL texture and read-back too).
enum class DepthMapUse { Volume, MapOnly, ShadowMap };

/// Bytes a W x H depth map and its derived buffers would need, to refuse absurd resolutions
/// before allocating. Limits of the command line: see maxResolution in README.
std::uint64_t depthMapBytes(int width, int height, DepthMapUse use = DepthMapUse::Volume);

/// Bytes a volume built from `map` may need, from its content (the map exists: its depths are
/// read, nothing of the size of a volume is allocated): depthMapBytes(Volume) plus 4 KiB per island
/// of hit texels (8-connected: the quads join diagonal neighbours) and 64 B per hit texel beside a
/// texel without a hit or the map's edge. Each island is a loop of walls and a hole in the exact
/// cap's triangulation: a map of isolated one-texel hits needed about 475 B a texel, nine times
/// what depthMapBytes assumes (a fourteenth probe's grating; measured on 1000² maps of isolated
/// texels, 2 x 2 and 3 x 3 blocks, stripes and a checkerboard, each below this bound: README,
/// the resolution limits, and docs/results/probe14/memory.sh).
std::uint64_t volumeBuildBytes(const DepthMap& map);

/// Refuses to build a volume from `map` when volumeBuildBytes needs more than half of this
/// machine's memory: InputError naming the map's size and what it needs. The map is read only when
/// its worst case (every other texel of every other row an island) could pass that, above about
/// 3,000² on 24 GiB; the check runs before the build's clock starts.
void checkVolumeFitsMemory(const DepthMap& map);

/// The same for the maps of one volume together (a point light's six cube faces).
void checkVolumeFitsMemory(std::span<const DepthMap> maps);

/// Largest side N a caller or command asks for (texels over the light's window).
inline constexpr int kMaxWindowSide = 16384;

/// Largest side of a depth map (texels): the window's and a volume map's guard band (light.h).
inline constexpr int kMaxDepthMapSide = kMaxWindowSide + 2 * kVolumeGuardTexels;

/// Refuses, before anything is allocated, a W x H map with a side below 2 or above
/// kMaxDepthMapSide, or whose buffers (depthMapBytes for `use`) need more than half of this
/// machine's memory: InputError naming `source` and `field` with the value and the memory it would need.
void checkDepthMapSize(int width, int height, const std::string& source, const std::string& field,
                       DepthMapUse use = DepthMapUse::Volume);

/// A light window of W x H texels asked for `use`: checkDepthMapSize, and for a volume the map with
/// its guard band (kVolumeGuardTexels, light.h) by checkGuardedDepthMapSize. The command line's
/// --resolution and Python's resolution.
void checkWindowMapSize(int width, int height, const std::string& source, const std::string& field, DepthMapUse use);

/// Refuses a guard band (texels a side) outside 0..kMaxGuardTexels (light.h): InputError naming
/// `source` and `field`. The captures' `guard` and checkDepthMapGuard.
void checkGuardTexels(std::int64_t guard, const std::string& source, const std::string& field);

/// Refuses a DepthMap::guard outside 0..kMaxGuardTexels (light.h) or one that leaves less than
/// 2 x 2 texels of the window inside a W x H map: InputError naming `source` and `field`.
void checkDepthMapGuard(std::int64_t guard, int width, int height, const std::string& source, const std::string& field);

/// The same for the map of a W x H window with a guard band of `guard` texels a side
/// (guardedLight, light.h), (W + 2 guard) x (H + 2 guard), naming the band in the message; nothing
/// for guard 0. Check the W x H first (checkDepthMapSize).
void checkGuardedDepthMapSize(int width, int height, int guard, const std::string& source, const std::string& field,
                              DepthMapUse use = DepthMapUse::Volume);

}  // namespace shadowvol
