// DepthMap -> VolumeMesh: grid sheet, triangulation, depth blurring, bias and far cap.
// The method is algorithm.md; the rules below are docs/volume.md in short. Spaces: depths are
// light-view distances (world units, DepthMap), the diagonal rule runs in light view, the result
// is in world space.
//
// Sheet vertex of texel (i, j): its light-view depth by sheet_depth.h's rule (the ring and
// invalid texels on the far plane, blur, bias; the GPU path mirrors it), unprojected in double at
// the texel centre: TexelUnprojector's formula, evaluated per row (multiplying by 1 / P00 and
// 1 / P11 where the projection allows it: a few ulps from it).
// Triangles: each quad A B C D (triangulation.h) gives two triangles by its diagonal. With the
// exact cap a triangle whose three vertices are on the far plane is dropped (a quad whose four
// corners are far loses both; a mixed quad may lose one): it would lie in the cap's plane.
// Exact cap: the far-plane footprint of the kept triangles, reversed, flattened losslessly by a
// constrained Delaunay triangulation of its boundary loops (far_cap.h). Where the region's
// boundary pinches (two fans of kept triangles meet at one far vertex, or two far boundary
// vertices are joined by an edge with kept triangles on both sides: a "cut") the vertex is split,
// one copy per fan, so the mesh is a closed 2-manifold; copies coincide in space (stats.splitVertices).
// Far vertices inside a region (the sheet touches the far plane there) stay sheet-only: the
// volume has zero thickness at that point and the cap passes under it (touching, not crossing).
// Quad cap: every triangle kept; the cap closes the border ring (same CDT); pinch rule as above
// (at the grid corners). Its far-plane sheet and cap coincide: for comparison only.
// Refinement (refineSteps > 0, docs/volume.md "Refinement"): quads with a boundary edge
// (boundary_edges.h) are triangulated with walls on the light rays through the edges' crossings
// (silhouette_refinement.h, rays from options.depthOracle), and the exact cap follows the walls'
// far edges; no vertex is then split.
// Work: two row-parallel passes over the grid (TBB): A decides each quad's diagonal and kept
// triangles (one code byte), B writes vertex positions and sheet triangles; boundary vertices, their
// pinch copies and the cap's edges come from the codes alone in between, so the cap is
// triangulated concurrently with pass B. The stages are in lib/src/core/volume/. Scratch: 5 bytes
// per quad (the code and the index of its first triangle), 8 bytes per texel more with blur, 1
// more with refinement, a few rows per task; no allocation per quad. VolumeBuilder keeps the
// scratch and the result's storage from one build to the next.
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "shadowvol/boundary_edges.h"
#include "shadowvol/depth_map.h"
#include "shadowvol/depth_oracle.h"
#include "shadowvol/enum_names.h"
#include "shadowvol/silhouette_refinement.h"
#include "shadowvol/triangulation.h"
#include "shadowvol/volume_mesh.h"

namespace shadowvol {

enum class FarCap {
  Exact,  ///< drop all-far quads, close each region with a (flattened) far-plane cap (default)
  Quad,   ///< the thesis's cancel rectangle: the full sheet plus one far rectangle facing away
};

inline constexpr EnumNames<FarCap, 2> kFarCapNames{{{FarCap::Exact, "exact"}, {FarCap::Quad, "quad"}}};

const char* toString(FarCap c);
bool parseFarCap(const std::string& text, FarCap& c);

struct VolumeBuildOptions {
  Triangulation triangulation = Triangulation::Perfect;  ///< perfect: fewest staircase artefacts
  bool blur = false;            ///< the thesis's 9-sample depth blur (algorithm.md)
  double blurOffset = 0.0;      ///< world units added to blurred depths (away from the light); 0 = none
  std::optional<double> bias;   ///< world units pushing the sheet away from the light; unset =
                                ///< defaultBias(map) (0 for back capture)
  FarCap cap = FarCap::Exact;   ///< exact cap by default; Quad for comparison with the thesis
  bool flattenCap = true;       ///< Exact only: triangulate the far cap with few triangles (lossless);
                                ///< false = one mirrored cap triangle per kept sheet triangle.
                                ///< The quad cap is always the flattened border-ring cap.
  int refineSteps = 0;          ///< sub-texel silhouette refinement: bisection rays per boundary edge
                                ///< (0 = off, today's grid volume; 1..kMaxRefineSteps); places each
                                ///< wall within 2^-(K+1) texel of where the near surface ends.
                                ///< Needs depthOracle and the exact cap (docs/volume.md, "Refinement")
  DepthOracle depthOracle;      ///< refinement only: the captured depth anywhere in the light's image
                                ///< (depth_oracle.h); unset = no refinement possible
  SurfaceEndOracle surfaceEnds; ///< refinement with depthOracle: where the recorded triangle ends
                                ///< (depth_oracle.h); set = every bisected crossing (edges, chord
                                ///< points, the sub-grid's) is snapped there (crossing_snap.h: on a
                                ///< polygonal mesh the wall stands on the silhouette's own light ray),
                                ///< up to 2 x kSnapRounds more rays each; unset = the bracket's middle
  bool refineSnap = true;       ///< false: no snap even with surfaceEnds (for comparison; --no-snap)
  CrossingSource crossingSource; ///< refinement only: the crossings and centre depths from elsewhere
                                ///< instead of bisection with depthOracle (the renderer's GPU
                                ///< silhouette walk, walk_crossings.h); with it refineSteps > 0 only
                                ///< switches refinement on. Not with refineChords or the sub-grid,
                                ///< whose extra points need depthOracle
  BoundaryEdgeSource boundaryEdgeSource; ///< refinement only: the boundary edges from elsewhere instead
                                ///< of findBoundaryEdges' rule (the refined GPU volume's debug mesh
                                ///< takes the GPU's own flags, so that it has the walls the GPU drew)
  bool refineChords = false;    ///< refinement only: bend the wall of a quad with two boundary edges
                                ///< at one more crossing inside it (refineSteps more rays per such
                                ///< quad), so it follows a curved outline. Off by default: about 15 %
                                ///< less error on real meshes for about 10 % more frame time at 256^2
                                ///< (README "Silhouette refinement")
  int refineSubdivisions = 1;   ///< refinement only: the sub-grid. S > 1 (2, 4 or 8) cuts every quad with a
                                ///< boundary edge into S x S sub-cells, samples the depth at their
                                ///< corners with the oracle and refines each sub-cell as a quad, with
                                ///< max(1, refineSteps - log2 S) rays per boundary sub-edge (the same
                                ///< 2^-(K+1) texel); the contour then follows an outline that bends
                                ///< inside a texel. 1 = off. Not with refineChords, needs flattenCap
                                ///< (docs/volume.md, "Sub-grid"). Adaptive: a quad whose plain
                                ///< refinement (two boundary edges, a straight wall) already lies on
                                ///< the lattice's samples and its own chord point stays plain
  bool refineGridEverywhere = false; ///< sub-grid only: cut every quad with a boundary edge, not only
                                ///< those whose plain refinement misses the lattice's samples (for
                                ///< comparison; more triangles, the same shadow where both agree)
  NearerSurfaceOracle nearerSurfaces; ///< sub-grid only: which quads hide a surface nearer than their
                                ///< corners' samples (depth_oracle.h; EmbreeDepthOracle::nearerSurfaces).
                                ///< Set = those quads go on the sub-grid too, though no boundary edge
                                ///< touches them: an occluder thinner than a texel between the texel
                                ///< centres (docs/volume.md "Hidden surfaces"); unset = they are not
  bool refineHidden = true;     ///< false: no search even with nearerSurfaces (for comparison;
                                ///< --no-hidden-search)
  bool facePrisms = false;      ///< refinement only: add the prisms of the closed casters' faces turned
                                ///< towards the light in the columns of the refined quads (each region
                                ///< of such faces whole), from each face to the far plane, as a second
                                ///< closed part of the mesh
                                ///< (VolumeMesh::partStarts): the mesh's own shadow where the sheet
                                ///< cannot follow it, a thin part's self-shadow (docs/volume.md "Face
                                ///< prisms"). Needs casterFaces. Off by default (README "Face prisms")
  CasterFaceOracle casterFaces; ///< facePrisms only: the faces (depth_oracle.h; EmbreeDepthOracle::casterFaces)
  CasterFreeOracles withoutCasters; ///< facePrisms only: the hand-over's oracles (depth_oracle.h;
                                ///< EmbreeDepthOracle::withoutCasters). depth set = the sheet hands the
                                ///< prisms' columns over to them: in the refined quads where a closed
                                ///< mesh they hold whole is recorded, it records the scene without it
                                ///< and the prisms hold its shadow (docs/volume.md "Face prisms");
                                ///< unset = the sheet keeps the casters and the prisms only add shadow.
                                ///< With facePrisms, refused with crossingSource or boundaryEdgeSource;
                                ///< with blur the sheet keeps the casters (the blur would carry the
                                ///< recaptured depths on)
};

/// Largest VolumeBuildOptions::refineSteps: 2^-16 of a texel is far below anything a float depth
/// or a camera pixel resolves, and keeps every crossing's texel coordinate exact in double.
inline constexpr int kMaxRefineSteps = 16;

/// The refineSteps chosen from measurements (README "Silhouette refinement": the error against K
/// on 15 scenes); what the sweep's refined methods and the builder benchmark use.
inline constexpr int kRecommendedRefineSteps = 6;

/// The refineSubdivisions chosen from measurements (README "Silhouette refinement", "Sub-grid").
inline constexpr int kRecommendedRefineSubdivisions = 4;

/// Bisection rays per boundary sub-edge of the sub-grid: max(1, K - log2 S), which keeps the walls
/// within 2^-(K+1) texel of the outline (a sub-edge is 1/S texel long).
inline int refineSubEdgeSteps(int refineSteps, int subdivisions) {
  return std::max(1, refineSteps - std::countr_zero(unsigned(subdivisions)));
}

/// Largest VolumeBuildOptions::refineSubdivisions.
inline constexpr int kMaxRefineSubdivisions = 8;
/// Most lattice nodes a sub-grid may hold (refined quads x (S + 1)^2; about 100 bytes each while
/// it is built): a larger one is refused before it is built.
inline constexpr std::uint64_t kMaxSubgridNodes = std::uint64_t(1) << 25;

/// Counts and times of one build (times in milliseconds, wall clock).
struct VolumeBuildStats {
  std::size_t quads = 0;              ///< (W - 1) * (H - 1); 0 when W or H < 2
  std::size_t droppedQuads = 0;       ///< quads that lost both triangles (all four corners far)
  std::size_t flippedQuads = 0;       ///< quads that took the A-C diagonal (0 for fixed; all-far
                                      ///< quads are not evaluated and count as not flipped)
  std::size_t capTrianglesBefore = 0; ///< cap triangles without flattening (= kept sheet triangles;
                                      ///< with refinement, those that are not walls)
  std::size_t capTrianglesAfter = 0;  ///< cap triangles in the result
  std::size_t splitVertices = 0;      ///< extra vertex copies at pinches and cuts (see above)
  std::size_t boundaryEdges = 0;      ///< refinement: grid edges across a discontinuity (split by a wall;
                                      ///< with the sub-grid they choose the quads it cuts, and its
                                      ///< boundary sub-edges get the walls)
  std::size_t farBoundaryEdges = 0;   ///< of which one end is on the far plane (the other end hit)
  std::size_t refinedCells = 0;       ///< refinement: quads with a boundary edge (triangulated with walls),
                                      ///< and the hidden quads
  std::size_t ambiguousCells = 0;     ///< refinement: refined quads (sub-cells with the sub-grid) with 3 or 4 boundary edges, decided
                                      ///< by one more ray at the quad's centre
  std::size_t chordPoints = 0;        ///< refinement: crossings inside quads with two boundary edges
                                      ///< (with the adaptive sub-grid: cast to choose, not vertices)
  std::size_t raysCast = 0;           ///< refinement: depth-oracle queries (refineSteps per boundary
                                      ///< edge and per chord point, plus one per ambiguous cell; with the
                                      ///< sub-grid its samples, steps per boundary sub-edge and centres)
  std::size_t snappedCrossings = 0;   ///< refinement with surfaceEnds: crossings snapped to where their
                                      ///< triangle ends (the others stay in their bracket's middle)
  std::size_t crossingFallbacks = 0;  ///< refinement with a crossing source: edges it found no crossing
                                      ///< on (walk_crossings.h: a wall in the middle of the edge)
  std::size_t subgridQuads = 0;       ///< sub-grid: refined quads cut into sub-cells (the others stay plain)
  std::size_t subgridSamples = 0;     ///< sub-grid: lattice nodes sampled by the oracle
  std::size_t subgridBoundaryEdges = 0; ///< sub-grid: boundary sub-edges (each with a wall)
  std::size_t subgridFarBoundaryEdges = 0; ///< of which one end is on the far plane
  std::size_t subgridSplitTriangles = 0; ///< sub-grid: triangles of unrefined and plain refined quads split at its side nodes
  std::size_t hiddenQuads = 0;        ///< sub-grid with nearerSurfaces: quads without a boundary edge put on
                                      ///< it for a hidden surface (counted in refinedCells and subgridQuads)
  std::size_t rimQuads = 0;           ///< of the hiddenQuads, those put on it for an open mesh's rim alone
                                      ///< (a hole or a sheet's edge between the texel centres)
  std::size_t creaseQuads = 0;        ///< sub-grid with a bias: quads without a boundary edge put on it for
                                      ///< a crease (docs/volume.md "Sub-grid", step 8; counted as hiddenQuads are)
  std::size_t thinQuads = 0;          ///< sub-grid with back capture: quads without a boundary edge put on it for
                                      ///< a part thinner than the sheet bends there (docs/volume.md "Sub-grid",
                                      ///< step 10; counted as hiddenQuads are)
  std::size_t thinRays = 0;           ///< the first-surface rays that measured those parts (in raysCast)
  std::size_t plainBends = 0;         ///< adaptive sub-grid: plain quads whose wall bends at its chord point
                                      ///< (docs/volume.md "Sub-grid", step 6; no ray of its own)
  std::size_t subgridBiasSamples = 0; ///< sub-grid with a bias: rays at sub-cell centres that set its nodes' bias
  std::size_t rimCrossings = 0;       ///< sub-grid with front capture's bias: snapped crossings whose near vertex
                                      ///< moved towards the rim (the plain refinement's, some then cut, and the
                                      ///< sub-grid's; docs/volume.md "Sub-grid", step 9)
  std::size_t prismFaces = 0;         ///< face prisms: casters' faces taken (docs/volume.md "Face prisms")
  std::size_t prismWalls = 0;         ///< face prisms: border edges of those faces, a wall each
  std::size_t prismTriangles = 0;     ///< face prisms: the part's triangles (in the mesh's count)
  std::size_t prismColumnTexels = 0;  ///< face prisms with withoutCasters: texels handed over (the
                                      ///< refined quads' corners' rays in raysCast; docs/volume.md
                                      ///< "Face prisms"; the hand-over's time in msPrisms)
  double biasUsed = 0.0;              ///< world units
  double msBlur = 0.0;                ///< the blur pass (ms); 0 without blur (offsets and clamp are
                                      ///< then part of the sheet passes)
  double msSheet = 0.0;               ///< diagonals, vertices, sheet triangles, pinch splits (ms)
  double msRefine = 0.0;              ///< refinement: boundary edges, oracle rays and walls (ms)
  double msRays = 0.0;                ///< refinement: the oracle calls alone (ms; part of msRefine)
  double msHidden = 0.0;              ///< sub-grid: the search for hidden surfaces (ms; part of msRefine)
  double msPrisms = 0.0;              ///< face prisms: the faces' selection and their part (ms; part of msRefine)
  double msCap = 0.0;                 ///< boundary runs, cap edges and cap triangulation (ms); the
                                      ///< triangulation runs during the sheet's last pass, so
                                      ///< msBlur + msSheet + msCap can exceed msTotal
  double msTotal = 0.0;               ///< whole call including input validation (ms)
};

struct VolumeBuildResult {
  VolumeMesh mesh;
  VolumeBuildStats stats;
};

/// The default bias (world units) of a depth map, from its metadata only (size, matrices,
/// near/far, capture mode; never its depths, so the GPU can compute it without read-back):
///   back, midpoint: 0 (the sheet lies behind the lit surfaces already);
///   front: F + 4 * far * 2^-23, F the texel footprint at the far plane (the larger of the
///   light-view distances between the far-plane points of neighbouring texel centres at the
///   map's centre; for a directional light 2 * halfExtent / W), i.e. the depth change across
///   one texel of a receiver tilted 45 degrees, plus 4 float ulps of the depth at the far plane.
double defaultBias(const DepthMap& map);

/// The same value from the light and the map size alone, without allocating a depth map:
/// defaultBias(makeDepthMap(light, width, height, capture)); a point light's is its faces'.
double defaultBias(const Light& light, int width, int height, CaptureMode capture);

/// The smallest side of a depth map whose volume can hold anything: the outermost ring of texels
/// always lies on the far plane, so a map 2 texels across is all ring and its volume empty. The
/// command line refuses smaller maps; the library builds their empty volumes.
inline constexpr int kMinVolumeMapSide = 3;

/// The options' depth offsets checked for a light range [nearPlane, farPlane]: InputError ("volume
/// options", "bias" or "blur offset") when the bias or the blur offset is not finite, or when the
/// given bias, plus the blur offset with blur, is at least far - near (offsetEmptiesRange in
/// sheet_depth.h: every texel would lie on the far plane and the volume be empty). The default
/// bias is not checked. Called by every volume build (one map's or a cube's).
void checkVolumeOffsets(const VolumeBuildOptions& options, double nearPlane, double farPlane);

/// The rules for options a user gives (the command line's flags, the Python module's arguments),
/// beyond what every build checks: bias and blur offset finite and >= 0 (the library itself takes
/// a negative offset, which pulls the sheet toward the light, into the lit surfaces it was captured
/// from), a blur offset only with blur, refine steps in 0..kMaxRefineSteps, chord points, the
/// sub-grid and refineSnap = false only with refine steps, chord points and the sub-grid not
/// together, the sub-grid everywhere only with the sub-grid, refinement only with the exact cap,
/// an unflattened cap only with the exact cap. InputError("volume options", field, value, why).
void checkUserVolumeOptions(const VolumeBuildOptions& options);

/// Builds shadow volumes again and again (one per frame, say) without grid-sized allocations: the
/// builder keeps its scratch buffers (about 5 bytes per texel) and build() reuses the storage
/// already in `result`. After the first build at a given size only per-row bookkeeping and the
/// cap's small buffers are allocated, so no fresh memory is faulted in (docs/volume.md: at 2048^2
/// the benchmark's back map took 36.8 ms fresh and 16.7 ms reused). Same result as buildVolume;
/// one build at a time per builder (it is movable, not copyable). On an exception `result` is
/// left empty.
class VolumeBuilder {
 public:
  VolumeBuilder();
  ~VolumeBuilder();
  VolumeBuilder(VolumeBuilder&&) noexcept;
  VolumeBuilder& operator=(VolumeBuilder&&) noexcept;

  void build(const DepthMap& map, const VolumeBuildOptions& options, VolumeBuildResult& result);

 private:
  struct Scratch;
  void buildInto(const DepthMap& map, const VolumeBuildOptions& options, VolumeBuildResult& result);
  // The stages after the checks; prismQuads: the face prisms' quads when the sheet handed them over
  // (empty: the refined quads).
  void buildStages(const DepthMap& map, const VolumeBuildOptions& options, std::span<const std::uint8_t> prismQuads,
                   VolumeBuildResult& result);
  std::unique_ptr<Scratch> scratch_;
};

/// Builds the shadow volume of a depth map (see the header comment). Throws InputError naming
/// the texel and value if the map holds a NaN or negative depth, if bias / blurOffset fail
/// checkVolumeOffsets, or if refineSteps is out of range, lacks a depth oracle or comes with the quad cap. The exact-cap result is a closed, consistently oriented 2-manifold with outward normals,
/// welded (coincident vertices only at documented splits), without zero-area triangles or
/// non-finite coordinates; empty (no triangles) when no texel is hit. Multithreaded (TBB),
/// deterministic (the same input gives the same mesh, whatever the thread count).
VolumeBuildResult buildVolume(const DepthMap& map, const VolumeBuildOptions& options = {});

}  // namespace shadowvol
