// Orienting a mesh read from a file: faces that agree with their neighbours, and a closed mesh's
// facing outward.
//
// Back capture, silhouette volumes and the lighting all take a triangle's winding as its facing
// (triangle_mesh.h). Meshes from other tools are not always wound so: a whole file inside out
// (the ellipsoid of data/scenes/unseen), or single faces wound against their neighbours (the
// shuffled blob). orientOutward repairs what it can prove wrong and leaves everything else as
// stored:
//
// - Closed means edge-manifold and without border: after welding exactly equal positions
//   (triangle_adjacency.h's rule), every edge of every non-degenerate triangle has exactly one
//   neighbour. A non-orientable surface is left as it is (OrientationResult::left says why).
// - An open mesh (a border, or edges of three or more triangles) has no outside: only each of its
//   connected parts (across edges of exactly two triangles) whose faces disagree is wound as most
//   of its triangles are (as its first triangle on a tie), and nothing more.
// - In a closed mesh, a connected component whose faces disagree (two neighbours run their edge
//   the same way) is wound consistently with its first triangle and then, if its signed volume is
//   negative, reversed: a repaired component is made to face outward on its own.
// - Then, if the whole mesh's signed volume is negative, every triangle is reversed. Components
//   that already agreed within themselves are reversed together, so a hollow solid stored as an
//   outward shell around an inward one keeps its inner shell inward.
// - Last, a component that agreed within itself and still encloses a negative volume is reversed
//   when its first vertex lies inside no other component (a ray's crossings, in double): an inner
//   shell lies wholly inside its outer one, so such a part was stored inside out on its own (a
//   mirrored part of an assembly). One whose vertex lies inside another is left: an inner shell,
//   or a part pushed into another, which one vertex cannot tell apart. The tests are bounded
//   (kOrientationContainmentTests triangle tests per mesh); parts past that are left and counted.
// - A signed volume counts as negative only below -1e-9 times the sum of its terms' magnitudes
//   (kOrientationVolumeTolerance), so a flat or double-sided closed sheet (volume 0 up to
//   rounding) is never reversed by rounding.
//
// Deterministic: components in the order of their first triangle, the volume summed in that order,
// in double about the box centre of `world`.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "shadowvol/triangle_mesh.h"

namespace shadowvol {

/// A signed volume below -kOrientationVolumeTolerance * (sum of |terms|) is negative.
inline constexpr double kOrientationVolumeTolerance = 1e-9;
/// The most triangle tests the containment of negative parts may take per mesh.
inline constexpr std::size_t kOrientationContainmentTests = 50'000'000;

struct OrientationResult {
  std::size_t reversed = 0;            ///< triangles whose winding was reversed
  std::size_t repairedComponents = 0;  ///< components whose faces disagreed, now wound alike
  std::size_t looseParts = 0;          ///< parts inside out on their own (in no other part), reversed
  std::size_t partsNotChecked = 0;     ///< negative parts left as stored: the containment budget ran out
  bool insideOut = false;              ///< the whole mesh was reversed (its signed volume was negative)
  double volumeBefore = 0.0;           ///< the mesh's signed volume before (after the component repair)
  bool open = false;                   ///< not closed: only its parts' faces were made to agree
  std::string left;                    ///< not closed, edge-manifold or orientable: why (else empty)
};

/// Orients `mesh` in place (the rules above). `world` holds its vertices' positions in double
/// (the volume is measured there; mesh.positions are only compared for welding); world.size() ==
/// mesh.positions.size(). `containmentTests` bounds the work of the last rule (tests lower it).
OrientationResult orientOutward(TriangleMesh& mesh, const std::vector<glm::dvec3>& world,
                                std::size_t containmentTests = kOrientationContainmentTests);

}  // namespace shadowvol
