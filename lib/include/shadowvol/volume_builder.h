// DepthMap -> VolumeMesh: grid sheet, triangulation, depth blurring, bias and far cap.
// The method is algorithm.md; options and their defaults are documented field by field.
#pragma once

#include <optional>
#include <string>

#include "shadowvol/depth_map.h"
#include "shadowvol/triangulation.h"
#include "shadowvol/volume_mesh.h"

namespace shadowvol {

enum class FarCap {
  Exact,  ///< drop all-far quads, close each region with a (flattened) far-plane cap (default)
  Quad,   ///< the thesis's cancel rectangle: the full sheet plus one far rectangle facing away
};

const char* toString(FarCap c);
bool parseFarCap(const std::string& text, FarCap& c);

struct VolumeBuildOptions {
  Triangulation triangulation = Triangulation::Perfect;  ///< perfect: fewest staircase artefacts
  bool blur = false;            ///< the thesis's 9-sample depth blur (algorithm.md)
  double blurOffset = 0.0;      ///< world units added to blurred depths (away from the light); 0 = none
  std::optional<double> bias;   ///< world units pushing the sheet away from the light; unset =
                                ///< defaultBias(map) (0 for back capture)
  FarCap cap = FarCap::Exact;   ///< exact cap by default; Quad for comparison with the thesis
  bool flattenCap = true;       ///< Exact only: triangulate the far cap with few triangles (lossless)
};

/// Counts and times of one build (times in milliseconds, wall clock).
struct VolumeBuildStats {
  std::size_t quads = 0;              ///< (W - 1) * (H - 1)
  std::size_t droppedQuads = 0;       ///< all-far quads removed by the exact cap
  std::size_t flippedQuads = 0;       ///< quads that took the A-C diagonal
  std::size_t capTrianglesBefore = 0; ///< cap triangles before flattening (two per kept quad)
  std::size_t capTrianglesAfter = 0;  ///< cap triangles after flattening
  std::size_t splitVertices = 0;      ///< vertices duplicated where regions touch at a point
  double biasUsed = 0.0;              ///< world units
  double msBlur = 0.0, msSheet = 0.0, msCap = 0.0, msTotal = 0.0;
};

struct VolumeBuildResult {
  VolumeMesh mesh;
  VolumeBuildStats stats;
};

/// The documented default bias for a depth map (0 for back capture; see README "Bias").
double defaultBias(const DepthMap& map);

/// Builds the shadow volume of a depth map. Throws InputError if the map holds NaN or negative
/// depths. The result is closed and consistently oriented (see README "Volume mesh").
VolumeBuildResult buildVolume(const DepthMap& map, const VolumeBuildOptions& options = {});

}  // namespace shadowvol
