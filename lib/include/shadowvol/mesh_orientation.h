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
// - In a closed mesh each connected component (a part) is first wound alike, as its first
//   triangle is. Then its winding follows its nesting: a part inside no other encloses a positive
//   signed volume (faces outward), one inside one other a negative one (the cavity of a hollow
//   solid faces into it), and so on by parity; a part whose volume has the other sign is
//   reversed. Part p lies inside part q when each of up to 8 of p's vertices does (a ray's
//   crossings of q, in double): one vertex outside shows that p is no inner shell of q, even where
//   p is pushed partly into q or touches it. Each part is decided on its own, so a mirrored part
//   of an assembly stored inside out is reversed alone, whatever the whole mesh's volume.
//   The tests are bounded (kOrientationContainmentTests triangle tests per mesh); a part left
//   untested is taken as nested in nothing, as most parts are, and counted.
//   A part fully sunk into another (not a cavity) is taken as a cavity; inside a solid it casts no
//   shadow of its own, so its facing changes no frame.
// - A signed volume counts as negative (or positive) only beyond 1e-9 times the sum of its terms'
//   magnitudes (kOrientationVolumeTolerance); a flat part (a double-sided closed sheet, volume 0 up
//   to rounding) keeps the winding of most of its triangles.
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

/// A signed volume below -kOrientationVolumeTolerance * (sum of |terms|) is negative, above
/// +kOrientationVolumeTolerance * (sum of |terms|) positive, else flat.
inline constexpr double kOrientationVolumeTolerance = 1e-9;
/// The most triangle tests the nesting of a closed mesh's parts may take.
inline constexpr std::size_t kOrientationContainmentTests = 50'000'000;

struct OrientationResult {
  std::size_t reversed = 0;            ///< triangles whose winding was reversed
  std::size_t repairedComponents = 0;  ///< parts whose faces disagreed, now wound alike
  std::size_t looseParts = 0;          ///< parts that agreed within themselves and were reversed,
                                       ///< when not all of them were (else insideOut)
  std::size_t partsNotChecked = 0;     ///< parts the nesting budget left untested (taken as nested in none)
  bool insideOut = false;              ///< every part that agreed within itself was reversed
  double volumeBefore = 0.0;           ///< the closed mesh's signed volume as stored
  bool open = false;                   ///< not closed: only its parts' faces were made to agree
  std::string left;                    ///< not closed, edge-manifold or orientable: why (else empty)
};

/// Orients `mesh` in place (the rules above). `world` holds its vertices' positions in double
/// (the volume is measured there; mesh.positions are only compared for welding); world.size() ==
/// mesh.positions.size(). `containmentTests` bounds the nesting tests (tests lower it).
OrientationResult orientOutward(TriangleMesh& mesh, const std::vector<glm::dvec3>& world,
                                std::size_t containmentTests = kOrientationContainmentTests);

}  // namespace shadowvol
