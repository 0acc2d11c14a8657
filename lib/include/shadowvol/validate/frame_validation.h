// Validation of one rendered frame: the GPU's stencil against Embree's signed crossing
// counts of the explicit volume, z-fail against z-pass, and every shadow test against the exact
// (ray-traced) shadows. GL-free: the caller passes what the GPU produced.
//
// Per-pixel arrays are in image order (row 0 at the top), width x height of the scene's camera.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "shadowvol/cgal/mesh_check.h"
#include "shadowvol/depth_map.h"
#include "shadowvol/embree/ray_queries.h"
#include "shadowvol/scene.h"
#include "shadowvol/validate/error_causes.h"
#include "shadowvol/validate/shadow_leaks.h"
#include "shadowvol/validate/lost_shadows.h"
#include "shadowvol/volume_builder.h"

namespace shadowvol {

/// What the GPU produced for one frame, and how.
struct RenderedFrame {
  int width = 0, height = 0;            ///< must equal the scene camera's size
  std::vector<std::uint8_t> rgba;       ///< the shaded frame, RGBA8 (may be empty)
  std::vector<std::uint8_t> stencil;    ///< hybrid: 8-bit wrapping stencil counts; empty otherwise
  int stencilBits = 8;                  ///< the bits that count: counts are compared modulo 2^stencilBits
  std::vector<std::uint8_t> shadowed;   ///< the method's own shadow test: 1 = in shadow (for PCF:
                                        ///< visibility < 0.5); empty = derive from the stencil
  bool hybrid = true;                   ///< a shadow-volume method (stencil and volume apply)
  bool zPass = false;                   ///< the stencil counted with z-pass and no far cap (zpass.h):
                                        ///< compared with the counts only where the light reaches
  std::optional<VolumeMesh> volume;     ///< hybrid, explicit volume: the mesh drawn, checked and counted
                                        ///< as it is; unset = rebuilt from the depth map and options
                                        ///< (the GPU volume, which mirrors the CPU build)
  std::optional<VolumeMesh> gpuVolume;  ///< the refined GPU volume's own triangles (read back): mesh-checked
                                        ///< as well (`volume` is then the CPU mesh of its crossings)
  /// A point light's refined GPU cube volume: the six face volumes (cube_map.h's order), checked
  /// each and counted each; a pixel's count is that of the face its surface point lies on
  /// (cubeLookup; within kFaceTieTolerance of two faces, either's). `volume` is then unused.
  std::vector<VolumeMesh> faceVolumes, faceGpuVolumes;
  /// A spot or directional light's depth-map method (hybrid, shadow maps): its depth offset away
  /// from the light (the volume's bias, plus the blur offset with blur; a shadow map's constant
  /// bias), to split its errors by cause (error_causes.h). Unset: not split.
  std::optional<double> depthOffset;
  /// The accuracy verdict's leak criterion (shadow_leaks.h): how the method's texels are sized.
  /// N > 0: a depth-map method, N the side of a point light's cube faces (a spot or directional
  /// light's map is validateFrame's `depth`); 0: an exact method (silhouette volumes); unset: not
  /// judged (a frame built by hand, dual-paraboloid maps).
  std::optional<int> leakMapSide;
  /// The method's depth offset for the leak criterion (LeakTexels): world units, and texel widths
  /// x min(tan a, 10) (a shadow map's slope bias).
  double leakOffset = 0.0, leakOffsetSlope = 0.0;
};

/// Defaults of the accuracy verdict (ValidationOptions): every shipped scene meets them with
/// validate's default method and options at 512^2 (the two *-wide-ground scenes with --fit view,
/// which they were made to show; README "Validation").
inline constexpr double kDefaultMaxError = 0.05;        ///< 5 % of the pixels facing the light
inline constexpr double kDefaultMaxMissedShare = 0.5;   ///< half the exact shadow's pixels
inline constexpr std::size_t kMinShadowPixels = 100;    ///< below this the missed share is not judged

struct ValidationOptions {
  bool selfIntersections = false;  ///< CGAL self-intersection check of the volume (slow)
  /// Accuracy verdict: the method's misclassified pixels (missed + false shadow) may be at most
  /// this fraction of the pixels facing the light inside its frustum ...
  double maxError = kDefaultMaxError;
  /// ... and its missed shadow pixels at most this share of the exact shadow's pixels, when the
  /// exact shadow has at least kMinShadowPixels (so an empty volume over a small shadow fails too).
  double maxMissedShare = kDefaultMaxMissedShare;
  /// The exact shadow rays' start: this multiple of the legacy scene offset (shadowRayOffset, 1e-4
  /// of the scene's radius) along the normal, in [0, 1]. 0, the default, is the sharp reference
  /// (only the round-off floor, exactShadows); 1 repeats figures measured before 2026-12-06, whose
  /// reference called lit a band of shadowed points along shadows' outlines
  /// (docs/results/reference-offset).
  double exactOffsetScale = 0.0;
};

/// Agreement of two per-pixel quantities over a set of pixels.
struct Agreement {
  std::size_t pixels = 0;  ///< pixels compared
  std::size_t agree = 0;   ///< including ties
  std::size_t ties = 0;    ///< agreeing only through the tie band (CrossingCounts::zfailMin/Max)
  /// Of the ties, those admitted only by the image-plane band (double_recount.h: a pixel centre
  /// within kImagePlaneTie pixels of a projected edge of the volume, or of a silhouette of the
  /// scene, where the counts split at the other surface's depth are admitted too).
  std::size_t imagePlaneTies = 0;
  /// A pixel where stencil and count disagree (stencil vs count only): where, and the numbers.
  struct Miss {
    int x = 0, row = 0;  ///< row 0 at the top
    int stencil = 0, zfail = 0, zfailMin = 0, zfailMax = 0;
  };
  static constexpr std::size_t kListedMisses = 16;
  std::vector<Miss> firstMisses;  ///< the first kListedMisses disagreeing pixels, rows top first
  double fraction() const { return pixels ? double(agree) / double(pixels) : 1.0; }
};

/// A shadow test against the exact shadows, over visible pixels that face the light inside its
/// frustum (PixelClass Lit or Shadowed).
struct ShadowError {
  std::size_t pixels = 0;       ///< pixels compared
  std::size_t missed = 0;       ///< exact: shadowed, test: lit (light leak)
  std::size_t falseShadow = 0;  ///< exact: lit, test: shadowed (acne, or a shadow too big)
  double missedFraction() const { return pixels ? double(missed) / double(pixels) : 0.0; }
  double falseFraction() const { return pixels ? double(falseShadow) / double(pixels) : 0.0; }
  double errorFraction() const { return pixels ? double(missed + falseShadow) / double(pixels) : 0.0; }
};

struct FrameValidation {
  int width = 0, height = 0;
  // Pixel classes.
  std::size_t visible = 0, background = 0, facingAway = 0, outsideLight = 0, exactLit = 0, exactShadowed = 0;
  std::vector<PixelClass> exact;           ///< per pixel
  // Volume (hybrid only).
  std::optional<MeshCheckReport> meshCheck;
  std::optional<MeshCheckReport> gpuMeshCheck;  ///< RenderedFrame::gpuVolume's checks (same options)
  std::optional<CrossingCounts> counts;
  bool eyeInsideVolume = false;
  /// Pixels whose Embree counts contradicted the eye's side and were recounted in double
  /// (double_recount.h); counts holds the recounted values.
  std::size_t recountedPixels = 0;
  bool stencilOverLitFrustumOnly = false;  ///< stencilVsCount left out the pixels outside the light (z-pass)
  Agreement stencilVsCount;                ///< over visible pixels: stencil == a z-fail count of the
                                           ///< admissible range (ray_queries.h, ties), mod 256; for a
                                           ///< z-pass frame over those inside the light's frustum
                                           ///< (outside, a ray past the far plane may cross the cap
                                           ///< z-pass leaves out, and the light reaches nothing)
  std::optional<Agreement> zfailVsZpass;   ///< over visible pixels, when the eye is outside the volume
  std::optional<ShadowError> stencilError; ///< stencil != 0 as a shadow test
  std::optional<ShadowError> countError;   ///< zfail != 0 as a shadow test
  ShadowError methodError;                 ///< the method's own test (hybrid: the stencil)
  std::optional<ErrorCauses> errorCauses;  ///< methodError's pixels by cause, with RenderedFrame::depthOffset
  std::optional<ShadowLeaks> leaks;        ///< methodError's missed pixels deep in the exact shadow (shadow_leaks.h),
                                           ///< with RenderedFrame::leakMapSide
  LostShadows lostShadows;                 ///< each occluder's shadow judged (lost_shadows.h)
  /// The consistency verdict (hybrid): stencil vs count >= kRequiredAgreement and the mesh checks
  /// pass; always true for the shadow-map baselines. With the quad cap the outward check does not
  /// apply (its far rectangle coincides with the far-plane sheet by design): closed, finite and
  /// non-degenerate are required, and meshChecksNotApplicable says why.
  bool consistent = true;
  /// The accuracy verdict: methodError within ValidationOptions::maxError and maxMissedShare, over
  /// at least one pixel (a frame with no visible pixel facing the light checks nothing: not accurate),
  /// at most kMaxLeakPixels deep missed pixels where the leak criterion judges the frame, and at most
  /// maxMissedShare of each occluder's shadow missed (lost_shadows.h).
  bool accurate = true;
  std::vector<std::string> failures;       ///< one sentence per failed criterion (empty when passed)
  std::string meshChecksNotApplicable;     ///< the checks left out, and why (empty: all apply)
  /// Exit criterion of `shadowvol validate`: consistent and accurate.
  bool passed = true;
};

/// Relative tie band between two cube faces (RenderedFrame::faceVolumes): a surface point whose two
/// largest |coordinates| of the offset from the light differ by at most this much of the larger
/// may have been counted against either face's volume (the GPU picks the face in float).
inline constexpr double kFaceTieTolerance = 1e-5;

/// Agreement required between stencil and count: 99.99 % of visible pixels.
inline constexpr double kRequiredAgreement = 0.9999;

/// Runs every check. `depth` is the depth map the GPU used (read back), `volumeOptions` the options
/// it drew the volume with; the explicit volume is rebuilt from them on the CPU unless the frame
/// carries the mesh drawn (RenderedFrame::volume: needed where the build read the GPU, as the
/// silhouette walk's crossings do).
FrameValidation validateFrame(const Scene& scene, const DepthMap& depth, const VolumeBuildOptions& volumeOptions,
                              const RenderedFrame& frame, const ValidationOptions& options = {});

/// Writes DIR/exact.png, stencil.png, count.png, overlay.png (and frame.png when the frame has
/// colour), rows top first, and overlay.svg (overlay.png with a legend: colours, meanings, pixel
/// counts). Overlay colours: red = light leak (exact shadow, method lit), yellow = false shadow,
/// magenta = stencil != count, cyan = z-fail != z-pass, each ringed 2 pixels wide at half strength
/// so that one wrong pixel shows in a whole frame; other pixels are the frame in grey.
void writeValidationImages(const std::filesystem::path& dir, const FrameValidation& v, const RenderedFrame& frame);

}  // namespace shadowvol
