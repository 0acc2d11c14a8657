// The sheet-depth rule, written once: the light-view depth (world units) of the volume's sheet
// vertex of a texel, from the stored depth (steps 1-3 of volume_builder.h). The builder's row
// kernels, the refinement's wall vertices and the tests call it; shaders/volume_common.glsl
// mirrors it for the GPU volume (the GL agreement tests keep the two in step).
//
//   1. the border ring (i or j on the outermost row or column) and invalid stored depths (kNoHit,
//      or d >= far * (1 - kFarSnap), see depth_blur.h) -> exactly the far plane; else
//   2. with blur: d = blurredDepth(map, i, j) + blurOffset;
//   3. d = clamp(d + bias, near, far), and exactly far if that is within kFarSnap of far.
#pragma once

#include <algorithm>
#include <string>

#include "shadowvol/depth_blur.h"
#include "shadowvol/depth_map.h"
#include "shadowvol/error.h"

namespace shadowvol {

struct SheetDepthRule {
  double nearPlane = 0.0;   ///< light-view distance of the near plane
  double farPlane = 1.0;    ///< light-view distance of the far plane
  double farSnap = 1.0;     ///< farPlane * (1 - kFarSnap): depths at or beyond it are the far plane
  double bias = 0.0;        ///< world units added to every depth (away from the light)
  double blurOffset = 0.0;  ///< world units added to blurred depths (step 2)

  SheetDepthRule() = default;
  SheetDepthRule(const DepthMap& map, double bias, double blurOffset)
      : nearPlane(map.nearPlane), farPlane(map.farPlane), farSnap(map.farPlane * (1.0 - kFarSnap)), bias(bias),
        blurOffset(blurOffset) {}

  /// True for texels of the outermost ring of a W x H map (always the far plane).
  static bool ring(int i, int j, int width, int height) { return i == 0 || j == 0 || i == width - 1 || j == height - 1; }

  /// Steps 1 and 3 for a stored depth off the ring: the far plane when invalid, else the clamped
  /// depth (the far plane when that is within kFarSnap of it). Branch-free, so row loops
  /// vectorise; NaN is never passed (the builder rejects it).
  double fromStored(double stored) const {
    const double c = std::clamp(stored + bias, nearPlane, farPlane);
    return (stored < farSnap && c < farSnap) ? c : farPlane;
  }

  /// Step 3 after step 2, for the blurred depth of a valid texel.
  double fromBlurred(double blurred) const {
    const double d = std::clamp(blurred + blurOffset + bias, nearPlane, farPlane);
    return d < farSnap ? d : farPlane;
  }

  /// The rule without the blur's neighbourhood, for one sample of the surface (a texel's stored
  /// depth, or a refinement ray's): the far plane when invalid, else step 3 after adding the blur
  /// offset when `blur`. Equals fromStored without blur.
  double ofSample(double stored, bool blur) const {
    if (!blur) return fromStored(stored);
    return stored < farSnap ? fromBlurred(stored) : farPlane;
  }

  bool isFar(double sheetDepth) const { return sheetDepth == farPlane; }
};

/// Why a depth offset (the volume's bias, plus the blur offset with blur; a shadow map's constant
/// bias) would leave nothing in shadow, or "" when it does not: every stored depth d lies at or
/// beyond the near plane, so an offset of at least far - near puts every d + offset on the far
/// plane (the volume's sheet is all far plane and the volume empty; a shadow map's comparison
/// never shadows a receiver inside the range).
inline std::string offsetEmptiesRange(double offset, double nearPlane, double farPlane) {
  if (!(offset >= farPlane - nearPlane)) return "";
  return "is at least the light's depth range (far - near = " + std::to_string(farPlane - nearPlane) +
         " world units): every depth plus it lies past the far plane, so nothing would be in shadow";
}

/// The volume's offsets checked by offsetEmptiesRange: the bias alone (blamed: `blurOffset` false),
/// then the bias plus the blur offset with blur (blamed: true). Empty `why` when neither empties
/// the range.
struct EmptyingOffset {
  bool blurOffset = false;
  std::string why;
};
inline EmptyingOffset volumeOffsetEmptiesRange(double bias, double blurOffset, bool blur, double nearPlane,
                                               double farPlane) {
  if (std::string why = offsetEmptiesRange(bias, nearPlane, farPlane); !why.empty()) return {false, why};
  if (!blur) return {};
  if (std::string why = offsetEmptiesRange(bias + blurOffset, nearPlane, farPlane); !why.empty())
    return {true, "plus the bias (" + numberText(bias) + ") " + why};
  return {};
}

/// The whole rule for one texel (ring, blur when `blur`, bias), one texel at a time: the
/// reference that the builder's row loops reproduce bit for bit.
inline double sheetDepthOf(const DepthMap& map, int i, int j, const SheetDepthRule& rule, bool blur) {
  const double stored = map.at(i, j);
  if (SheetDepthRule::ring(i, j, map.width, map.height) || isFarDepth(stored, map.farPlane)) return map.farPlane;
  return blur ? rule.fromBlurred(blurredDepth(map, i, j)) : rule.fromStored(stored);
}

}  // namespace shadowvol
