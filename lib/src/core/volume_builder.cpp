#include "shadowvol/volume_builder.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>

#include <tbb/task_group.h>
#include <glm/geometric.hpp>

#include "shadowvol/boundary_edges.h"
#include "shadowvol/check.h"
#include "shadowvol/cube_map.h"
#include "shadowvol/depth_map_io.h"
#include "shadowvol/error.h"
#include "shadowvol/far_cap.h"
#include "shadowvol/scene.h"
#include "shadowvol/sheet_depth.h"
#include "shadowvol/silhouette_refinement.h"
#include "volume/build_buffers.h"
#include "volume/cap_boundary.h"
#include "volume/cap_triangles.h"
#include "volume/face_prisms.h"
#include "volume/prism_columns.h"
#include "volume/crease_quads.h"
#include "volume/thin_quads.h"
#include "volume/grid_unprojector.h"
#include "volume/hidden_quads.h"
#include "volume/quad_codes.h"
#include "volume/refined_cells.h"
#include "volume/rim_bias.h"
#include "volume/sheet_depths.h"
#include "volume/sheet_emit.h"
#include "volume/sheet_vertices.h"
#include "volume/subgrid_cells.h"
#include "volume/unused_vertices.h"

namespace shadowvol {

const char* toString(FarCap c) { return nameIn(kFarCapNames, c); }

bool parseFarCap(const std::string& text, FarCap& c) { return parseIn(kFarCapNames, text, c); }

namespace {

// defaultBias from the map's metadata: light view and projection, size, far plane, capture.
double defaultBiasOf(const glm::dmat4& view, const glm::dmat4& projection, int width, int height, double farPlane,
                     CaptureMode capture) {
  if (!recordsLitSurfaces(capture)) return 0.0;
  // Texel footprint at the far plane (the largest over the map for a spot light; constant for a
  // directional one): the depth change across one texel of a receiver tilted 45 degrees.
  const TexelUnprojector unproject(view, projection, width, height);
  const double w2 = 0.5 * (width - 1), h2 = 0.5 * (height - 1);
  const glm::dvec3 c = unproject.lightViewPoint(w2, h2, farPlane);
  const double footprint = std::max(glm::length(unproject.lightViewPoint(w2 + 1.0, h2, farPlane) - c),
                                    glm::length(unproject.lightViewPoint(w2, h2 + 1.0, farPlane) - c));
  // Float depth precision: 4 ulps of a float at the far plane (2^-23 relative per ulp).
  const double precision = 4.0 * farPlane * std::ldexp(1.0, -23);
  return footprint + precision;
}

}  // namespace

double defaultBias(const DepthMap& map) {
  return defaultBiasOf(map.lightView, map.lightProjection, map.width, map.height, map.farPlane, map.capture);
}

double defaultBias(const Light& light, int width, int height, CaptureMode capture) {
  if (light.type == LightType::Point)  // its faces' (all six alike: defaultCubeBias)
    return defaultBias(cubeFaceLight(light, 0), width, height, capture);
  return defaultBiasOf(lightView(light), lightProjection(light, double(width) / double(height)), width, height,
                       light.farPlane, capture);
}

void checkVolumeOffsets(const VolumeBuildOptions& options, double nearPlane, double farPlane) {
  auto finite = [](const char* name, double v) {
    if (!std::isfinite(v)) {
      std::ostringstream value;
      value << v;
      throw InputError("volume options", name, value.str(), "must be a finite number of world units");
    }
  };
  finite("blur offset", options.blurOffset);
  if (options.bias) finite("bias", *options.bias);
  const double bias = options.bias.value_or(0.0);
  const EmptyingOffset e = volumeOffsetEmptiesRange(bias, options.blurOffset, options.blur, nearPlane, farPlane);
  if (!e.why.empty())
    throw InputError("volume options", e.blurOffset ? "blur offset" : "bias",
                     numberText(e.blurOffset ? options.blurOffset : bias), e.why);
}

namespace {

// The sub-grid's S: 1 (off), 2, 4 or 8.
void checkRefineSubdivisions(int s) {
  if (s < 1 || s > kMaxRefineSubdivisions || (s & (s - 1)) != 0)
    throw InputError("volume options", "refine subdivisions", std::to_string(s), "must be 1 (off), 2, 4 or 8");
}

}  // namespace

void checkUserVolumeOptions(const VolumeBuildOptions& o) {
  // The problems name other options as ${field} marks (error.h): each front end spells them.
  auto refuseValue = [](const char* field, const std::string& value, const std::string& why) {
    throw InputError("volume options", field, value, MarkedProblem{why});
  };
  auto refuse = [](const char* field, const std::string& value, const std::string& why) {  // a combination
    throw OptionConflict("volume options", field, value, MarkedProblem{why});
  };
  if (!std::isfinite(o.blurOffset) || o.blurOffset < 0.0)
    refuseValue("blur offset", numberText(o.blurOffset),
                "must be finite and >= 0 (a negative offset pulls the sheet toward the light, into the lit surfaces "
                "it was captured from)");
  if (o.blurOffset != 0.0 && !o.blur) refuse("blur offset", numberText(o.blurOffset), "needs ${blur}");
  if (o.bias && (!std::isfinite(*o.bias) || *o.bias < 0.0))
    refuseValue("bias", numberText(*o.bias), "must be finite and >= 0");
  if (o.refineSteps < 0 || o.refineSteps > kMaxRefineSteps)
    refuseValue("refine steps", std::to_string(o.refineSteps),
                "must be between 0 (off) and " + std::to_string(kMaxRefineSteps));
  checkRefineSubdivisions(o.refineSubdivisions);
  if (o.refineSteps > 0 && o.cap != FarCap::Exact)
    refuse("refine steps", std::to_string(o.refineSteps),
           "needs the exact cap (${cap} exact: the quad cap keeps the far-plane sheet that refinement replaces by walls)");
  const char* needsRefine = "needs refinement (${refine steps} of at least 1)";
  if (o.refineChords && o.refineSteps == 0) refuse("refine chords", "", needsRefine);
  if (o.refineSubdivisions > 1 && o.refineSteps == 0)
    refuse("refine subdivisions", std::to_string(o.refineSubdivisions), needsRefine);
  if (o.refineSubdivisions > 1 && o.refineChords)
    refuse("refine subdivisions", std::to_string(o.refineSubdivisions),
           "not with ${refine chords}: they are alternatives (the sub-grid bends the wall in every sub-cell)");
  if (o.refineGridEverywhere && o.refineSubdivisions == 1)
    refuse("refine grid everywhere", "", "needs ${refine subdivisions} of 2, 4 or 8");
  if (!o.refineSnap && o.refineSteps == 0) refuse("refine snap", "", needsRefine);
  if (!o.refineHidden && o.refineSubdivisions <= 1)
    refuse("refine hidden", "", "is the sub-grid's search: it needs ${refine subdivisions} of 2, 4 or 8");
  if (o.facePrisms && o.refineSteps == 0) refuse("face prisms", "", needsRefine);
  if (!o.flattenCap && o.cap != FarCap::Exact)
    refuse("flatten cap", "", "keeps the exact cap unflattened; the quad cap has one far rectangle, nothing to flatten");
}

namespace {

// Cheap checks of the map's metadata and of the options, before anything else.
// A map filled by hand (a caller's own renderer) gets the checks a depth file's light gets, so that
// matrices or planes that would put vertices at NaN are refused instead (a probe's NaN view gave a
// mesh of NaN); a map of one row or column has no quad and builds an empty volume.
void validateMapAndOptions(const DepthMap& map, const VolumeBuildOptions& options) {
  if (map.width < 1 || map.height < 1 || map.width > kMaxDepthMapSide || map.height > kMaxDepthMapSide)
    throw InputError("DepthMap", "width x height", std::to_string(map.width) + "x" + std::to_string(map.height),
                     "each side must be 1 to " + std::to_string(kMaxDepthMapSide) + " texels");
  if (map.depth.size() != std::size_t(map.width) * std::size_t(map.height))
    throw InputError("DepthMap", "depth", std::to_string(map.depth.size()) + " values",
                     "expected width x height = " + std::to_string(map.width) + " x " + std::to_string(map.height));
  if (map.width >= 2 && map.height >= 2) {
    checkDepthMapLight(map, "DepthMap", kDepthMapMembers, true);
  } else {  // no quad, an empty volume: still no NaN planes or origin carried into it (a second reader's)
    if (!(std::isfinite(map.nearPlane) && map.nearPlane >= 0.0))
      throw InputError("DepthMap", "nearPlane", numberText(map.nearPlane), "near must be finite and >= 0");
    if (!(map.farPlane > map.nearPlane && map.farPlane < 1e30))
      throw InputError("DepthMap", "farPlane", numberText(map.farPlane), "far must be greater than near and below 1e30");
    for (int k = 0; k < 3; ++k)
      if (!(std::abs(map.origin[k]) <= kMaxSceneMagnitude))
        throw InputError("DepthMap", "origin", numberText(map.origin[k]), "expected 3 finite numbers within +-1e12");
  }
  checkVolumeOffsets(options, map.nearPlane, map.farPlane);
  if (options.refineSteps < 0 || options.refineSteps > kMaxRefineSteps)
    throw InputError("volume options", "refine steps", std::to_string(options.refineSteps),
                     "must be between 0 (off) and " + std::to_string(kMaxRefineSteps));
  if (options.refineSteps > 0 && !options.depthOracle && !options.crossingSource)
    throw InputError("volume options", "refine steps", std::to_string(options.refineSteps),
                     "refinement casts rays into the scene: it needs a depth oracle (an Embree scene on the "
                     "command line)");
  if (options.crossingSource && (options.refineChords || options.refineSubdivisions > 1) && !options.depthOracle)
    throw OptionConflict("volume options", options.refineChords ? "refine chords" : "refine subdivisions",
                     options.refineChords ? "true" : std::to_string(options.refineSubdivisions),
                     "chord points and the sub-grid sample points that only a depth oracle answers; the crossing "
                     "source gives the boundary edges' crossings alone");
  const int s = options.refineSubdivisions;
  checkRefineSubdivisions(s);
  if (s > 1 && options.refineSteps == 0)
    throw OptionConflict("volume options", "refine subdivisions", std::to_string(s),
                     "the sub-grid is part of refinement: it needs refine steps of at least 1");
  if (s > 1 && options.refineChords)
    throw OptionConflict("volume options", "refine chords", "true",
                     "chord points and the sub-grid are alternatives: the sub-grid bends the wall at every sub-cell");
  if (s == 1 && options.refineGridEverywhere)
    throw OptionConflict("volume options", "refine grid everywhere", "true",
                     "it chooses where the sub-grid goes: it needs refine subdivisions of 2, 4 or 8");
  if (s > 1 && !options.flattenCap)
    throw OptionConflict("volume options", "flatten cap", "false",
                     "the sub-grid needs the flattened cap (the mirrored cap does not follow its sub-cells)");
  if (options.facePrisms && options.refineSteps == 0)
    throw OptionConflict("volume options", "face prisms", "true",
                         "the face prisms stand in the refined quads' columns: they need refine steps of at least 1");
  if (options.facePrisms && options.withoutCasters.depth && (options.crossingSource || options.boundaryEdgeSource))
    throw OptionConflict("volume options", "without casters", "set",
                         "the hand-over to the face prisms recaptures the map and asks the rays again: it cannot "
                         "take crossings or boundary edges from elsewhere");
  if (options.facePrisms && !options.casterFaces)
    throw InputError("volume options", "face prisms", "true",
                     "the prisms are made of the scene's faces: they need a caster-face oracle (an Embree scene on "
                     "the command line)");
  if (options.refineSteps > 0 && options.cap != FarCap::Exact)
    throw OptionConflict("volume options", "cap", toString(options.cap),
                     "refinement needs the exact cap: the quad cap keeps the far-plane sheet whose quads "
                     "refinement replaces by walls");
}

// The texel grid's boundary edges, and those of them with one end on the far plane, into `stats`.
void countBoundaryEdges(const BoundaryEdges& edges, VolumeBuildStats& stats) {
  stats.boundaryEdges = edges.edges.size();
  stats.farBoundaryEdges = std::size_t(
      std::count_if(edges.edges.begin(), edges.edges.end(), [](const BoundaryEdge& e) { return !e.surface; }));
}

// The snap of refinement's bisected crossings, when the options bring a surface-end oracle.
const SurfaceEndOracle* snapOf(const VolumeBuildOptions& options) {
  return options.refineSnap && options.surfaceEnds && options.depthOracle ? &options.surfaceEnds : nullptr;
}

// Whether snapped crossings' near vertices keep only the bias the rim needs (volume/rim_bias.h):
// with the sub-grid (which the GPU volume has not: the plain refined volume stays the GPU's),
// front or entry capture's bias and no blur (back capture's rim touches the lit faces, docs/volume.md
// "Refinement").
bool rimBiasOf(const VolumeBuildOptions& options, const volume::SheetDepths& sheet) {
  return options.refineSubdivisions > 1 && recordsLitSurfaces(sheet.map().capture) && sheet.rule().bias > 0.0 &&
         !options.blur;
}

// Refinement's rays: the boundary edges' crossings (and, with `centres`, the ambiguous quads'
// centre depths), then, with refineChords or `chordTest` (the adaptive sub-grid's choice, which
// only measures with them), the chord points of the quads with two boundary edges; their counts go
// to `stats`.
void castRefinementRays(const volume::SheetDepths& sheet, const BoundaryEdges& edges, const volume::RefinedQuads& quads,
                        bool centres, bool chordTest, std::span<const double> blurred,
                        const VolumeBuildOptions& options, Refinement& refinement, volume::ChordPoints& chords,
                        VolumeBuildStats& stats) {
  const DepthMap& map = sheet.map();
  const std::span<const glm::dvec2> centreList =
      centres ? std::span<const glm::dvec2>(quads.centres) : std::span<const glm::dvec2>();
  if (options.crossingSource) {
    refinement = options.crossingSource(map, edges, sheet.rule(), options.blur, blurred, centreList);
    SV_CHECK_EQ(refinement.crossings.size(), edges.edges.size());
    SV_CHECK_EQ(refinement.centreDepths.size(), centreList.size());
    // Kept apart from the edge's ends as bisected ones are (bisectSegments): a source's crossing on
    // an end is two cap corners at one point, on which the far cap's triangulation crashed (a
    // probe's finding, when the GPU's rays could put a walked bracket's middle there).
    const double safe = floatSafeTexels(map);
    for (Crossing& c : refinement.crossings) keepApartFromEnds(c, 1.0, safe);
  } else {
    refinement = refineBoundaryEdges(map, edges, sheet.rule(), options.blur, blurred, options.depthOracle,
                                     options.refineSteps, centreList, {snapOf(options)});
  }
  stats.crossingFallbacks = refinement.fallbacks;
  stats.snappedCrossings = refinement.snapped;
  countBoundaryEdges(edges, stats);
  stats.ambiguousCells = centres ? quads.centres.size() : 0;
  stats.raysCast = refinement.raysCast;
  stats.msRays = refinement.msRays;
  if (options.refineChords || chordTest) {
    chords = volume::planChordPoints(quads, sheet, edges, refinement);
    RayBudget budget;
    chords.crossings = bisectSegments(map, chords.segments, sheet.rule(), options.blur, options.depthOracle,
                                      options.refineSteps, budget, {}, nullptr, {snapOf(options), &stats.snappedCrossings});
    stats.chordPoints = chords.segments.size();  // with the adaptive sub-grid: its choice, and the plain quads' bends
    stats.raysCast += budget.rays;
    stats.msRays += budget.ms;
  }
  // After the chord points, which bisect from the crossings' samples (the discontinuity rule's);
  // the chord points themselves are the adaptive sub-grid's plain quads' vertices.
  if (rimBiasOf(options, sheet)) {
    stats.rimCrossings = volume::lowerPlainRimVertices(sheet, edges, refinement.crossings);
    if (chordTest) stats.rimCrossings += volume::lowerSegmentRimVertices(sheet, chords.segments, chords.crossings);
  }
}

// The sub-grid (refineSubdivisions > 1): its triangles, cap edges and vertices from firstVertex
// on, with its counts in `stats` (added to the plain refinement's, when `plain` is given: the
// adaptive sub-grid). Refuses a lattice too large to hold before building it.
volume::SubgridCells subgridCells(const volume::RefinedQuads& quads, const volume::TexelUse& use,
                                  const volume::SheetVertices& vertices, const volume::SheetDepths& sheet,
                                  const BoundaryEdges& edges, const VolumeBuildOptions& options,
                                  std::uint32_t firstVertex, const volume::PlainRefinement* plain,
                                  VolumeBuildStats& stats) {
  const int s = options.refineSubdivisions;
  const std::uint64_t nodes = std::uint64_t(quads.quads.size()) * std::uint64_t((s + 1) * (s + 1));
  if (nodes > kMaxSubgridNodes)
    throw InputError("volume options", "refine subdivisions", std::to_string(s),
                     "the sub-grid of the " + std::to_string(quads.quads.size()) +
                         " quads with a boundary edge would "
                         "hold up to " +
                         std::to_string(nodes) + " nodes, more than " + std::to_string(kMaxSubgridNodes) +
                         ": use fewer subdivisions or a smaller map");
  volume::SubgridOptions o;
  o.subdivisions = s;
  o.steps = refineSubEdgeSteps(options.refineSteps, s);
  o.blur = options.blur;
  o.perfect = options.triangulation == Triangulation::Perfect;
  o.exact = options.cap == FarCap::Exact;
  o.ends = snapOf(options);
  o.rimBias = rimBiasOf(options, sheet);
  volume::SubgridCells sub =
      volume::buildSubgridCells(quads, use, vertices, sheet, options.depthOracle, o, firstVertex, plain);
  // Vertex indices stay below kNone: the sheet, the sub-grid's and one centroid per split side at most.
  const std::uint64_t total =
      std::uint64_t(firstVertex) + sub.positions.size() + sub.splits.size() + sub.plainSplits.size();
  if (total >= std::uint64_t(volume::kNone))
    throw InputError("volume options", "refine subdivisions", std::to_string(s),
                     "the volume would have " + std::to_string(total) + " vertices, more than 32-bit indices address");
  countBoundaryEdges(edges, stats);
  stats.ambiguousCells = sub.ambiguousCells;
  stats.subgridQuads = sub.griddedQuads;
  stats.subgridSamples = sub.samples;
  stats.subgridBiasSamples = sub.biasSamples;
  stats.subgridBoundaryEdges = sub.boundaryEdges;
  stats.subgridFarBoundaryEdges = sub.farBoundaryEdges;
  stats.raysCast += sub.raysCast;
  stats.snappedCrossings += sub.snapped;
  stats.rimCrossings += sub.rimCrossings;
  stats.msRays += sub.msRays;
  return sub;
}

// The refined quads that the adaptive sub-grid left plain (gridded[q] == 0), in quad order.
volume::RefinedQuads plainQuadsOf(const volume::RefinedQuads& quads, const std::vector<std::uint8_t>& gridded) {
  volume::RefinedQuads plain;
  for (std::size_t q = 0; q < quads.quads.size(); ++q) {
    if (gridded[q]) continue;
    plain.quads.push_back(quads.quads[q]);
    plain.sides.push_back(quads.sides[q]);
  }
  return plain;  // two boundary sides each: no centres
}

// The chord points of the plain quads (plainQuadsOf's order): the same points and vertex slots,
// ofQuad reduced to the quads left plain, used where they bend the wall by more than the floor.
volume::ChordPoints plainChordsOf(const volume::ChordPoints& chords, const std::vector<std::uint8_t>& gridded,
                                  int steps) {
  volume::ChordPoints plain;
  plain.segments = chords.segments;
  plain.crossings = chords.crossings;
  plain.bendFloor = volume::kPlainChordBendFloor;
  plain.steps = steps;
  for (std::size_t q = 0; q < chords.ofQuad.size(); ++q)
    if (!gridded[q]) plain.ofQuad.push_back(chords.ofQuad[q]);
  return plain;
}

// What refinement finds before the vertices are laid out: the boundary edges, the quads they
// touch (and the hidden quads), the crossings and the chord points (all empty without refinement).
struct RefinementFound {
  BoundaryEdges edges;
  volume::RefinedQuads quads;
  Refinement refinement;
  volume::ChordPoints chords;
  std::size_t hiddenQuads = 0, rimQuads = 0, creaseQuads = 0, thinQuads = 0, thinRays = 0;
  double msHidden = 0.0;
};

// Whether the sub-grid searches for hidden surfaces (VolumeBuildOptions::nearerSurfaces).
bool searchesHidden(const VolumeBuildOptions& options) {
  return options.refineSubdivisions > 1 && options.refineHidden && options.nearerSurfaces && options.depthOracle;
}

// Stage 1r: the boundary edges (the options' source, else findBoundaryEdges' rule), their bits per
// texel in splitBits (resized to the map), the hidden quads (stage 1h) and the quads they all touch.
RefinementFound findRefinement(const volume::SheetDepths& sheet, const VolumeBuildOptions& options,
                               std::span<const double> blurred, volume::Scratch<std::uint8_t>& splitBits) {
  const DepthMap& map = sheet.map();
  volume::sizeBuffer(splitBits, std::size_t(map.width) * map.height);
  RefinementFound found;
  found.edges = options.boundaryEdgeSource
                    ? options.boundaryEdgeSource(map, sheet.rule(), options.blur, blurred, splitBits.data())
                    : findBoundaryEdges(map, sheet.rule(), options.blur, blurred, splitBits.data());
  SV_CHECK_EQ(found.edges.rowStart.size(), std::size_t(map.height) + 1);
  std::vector<std::uint32_t> hidden;
  if (searchesHidden(options)) {
    const auto t0 = volume::Clock::now();
    hidden = volume::findHiddenQuads(sheet, options.nearerSurfaces, options.refineSubdivisions, splitBits.data(),
                                     &found.rimQuads);
    found.msHidden = volume::msSince(t0);
  }
  found.hiddenQuads = hidden.size();
  if (options.refineSubdivisions > 1) {  // after the search: a quad it flagged is not a crease quad
    const std::vector<std::uint32_t> creases =
        volume::findCreaseQuads(sheet, options.refineSubdivisions, splitBits.data());
    found.creaseQuads = creases.size();
    std::size_t n = hidden.size();
    hidden.insert(hidden.end(), creases.begin(), creases.end());
    std::inplace_merge(hidden.begin(), hidden.begin() + std::ptrdiff_t(n), hidden.end());
    // Back capture: parts thinner than the sheet bends (stage 1t), after the creases (front capture's).
    const std::vector<std::uint32_t> thin =
        volume::findThinQuads(sheet, options.depthOracle, splitBits.data(), &found.thinRays);
    found.thinQuads = thin.size();
    n = hidden.size();
    hidden.insert(hidden.end(), thin.begin(), thin.end());
    std::inplace_merge(hidden.begin(), hidden.begin() + std::ptrdiff_t(n), hidden.end());
  }
  found.quads = volume::findRefinedQuads(found.edges, map.width, map.height, hidden);
  return found;
}

// Where the vertex numbering of each kind begins after the sheet's: the plain crossings (two per
// boundary edge), the chord points (two each), the sub-grid's (after the plain crossings and chord
// points with the adaptive sub-grid, else after the sheet's).
struct VertexBases {
  std::uint32_t crossing = 0, chord = 0, subgrid = 0;
};

VertexBases vertexBasesOf(const volume::SheetVertices& vertices, const RefinementFound& found, bool adaptive) {
  VertexBases base;
  base.crossing = std::uint32_t(vertices.count());
  base.chord = std::uint32_t(base.crossing + 2 * found.edges.edges.size());
  base.subgrid = adaptive ? std::uint32_t(base.chord + 2 * found.chords.segments.size()) : base.crossing;
  return base;
}

// Stage 2's counts and those of the quads stage 1r found, into `stats`.
void recordQuadStats(const volume::QuadCodes& codes, const RefinementFound& found, VolumeBuildStats& stats) {
  stats.flippedQuads = codes.flipped;
  stats.droppedQuads = codes.dropped;
  stats.refinedCells = codes.refined;
  stats.hiddenQuads = found.hiddenQuads;
  stats.rimQuads = found.rimQuads;
  stats.creaseQuads = found.creaseQuads;
  stats.thinQuads = found.thinQuads;
  stats.msHidden = found.msHidden;
}

// Stages 3r and 4r: the refined quads' triangles and walls (plain refinement, the sub-grid, or the
// adaptive sub-grid's mix of both) and the far edges that bound the cap.
struct RefinedStage {
  volume::RefinedCells cells;
  volume::SubgridCells sub;
  volume::RefinedQuads plainQuads;  // the adaptive sub-grid's plain quads
  std::vector<CapEdge> capEdges;
};

// Stage 5's buffers: the vertices of the sheet and the refined quads (or the pinch copies), the
// triangles of both, with room for the sub-grid's split centroids and (about) the flattened cap, so
// that appending them rarely reallocates. perimeter: the map's width + height.
void sizeMeshBuffers(bool subgrid, const VertexBases& base, const volume::SheetVertices& vertices,
                     const volume::CapBoundary& boundary, const RefinementFound& found, std::uint64_t sheetTriangles,
                     const RefinedStage& refined, int perimeter, VolumeMesh& mesh) {
  using volume::sizeBuffer;
  const volume::SubgridCells& sub = refined.sub;
  if (subgrid)
    sizeBuffer(mesh.positions, base.subgrid + sub.positions.size(),
               base.subgrid + sub.positions.size() + sub.splits.size() + sub.plainSplits.size());
  else
    sizeBuffer(mesh.positions,
               vertices.count() + boundary.copies + 2 * found.edges.edges.size() + 2 * found.chords.segments.size());
  const std::uint64_t triangles = sheetTriangles + refined.cells.triangles.size();
  sizeBuffer(mesh.triangles, triangles, triangles + triangles / 4 + 4 * std::size_t(perimeter) + 64);
}

RefinedStage buildRefinedCells(const RefinementFound& found, const volume::TexelUse& use,
                               const volume::SheetVertices& vertices, const volume::SheetDepths& sheet,
                               const VolumeBuildOptions& options, const VertexBases& base, VolumeBuildStats& stats) {
  const bool subgrid = options.refineSubdivisions > 1;
  const bool adaptive = subgrid && !options.refineGridEverywhere;
  const bool perfect = options.triangulation == Triangulation::Perfect;
  const bool exact = options.cap == FarCap::Exact;
  RefinedStage r;
  if (!subgrid) {
    const volume::ChordPoints* chordPoints = options.refineChords ? &found.chords : nullptr;  // as vertices
    r.cells = volume::triangulateRefinedCells(found.quads, use, vertices, sheet, found.edges, found.refinement,
                                              chordPoints, perfect, exact, base.crossing, base.chord);
    r.capEdges = r.cells.capEdges;
    return r;
  }
  const volume::PlainRefinement plain{found.edges, found.refinement, base.crossing, &found.chords, options.refineSteps};
  r.sub = subgridCells(found.quads, use, vertices, sheet, found.edges, options, base.subgrid,
                       adaptive ? &plain : nullptr, stats);
  if (adaptive) {
    r.plainQuads = plainQuadsOf(found.quads, r.sub.gridded);
    // The plain quads' walls bend at the chord points their choice measured (within two bisection
    // errors of the straight wall, or the quad would have been cut): no more rays.
    const volume::ChordPoints chords = plainChordsOf(found.chords, r.sub.gridded, options.refineSteps);
    r.cells = volume::triangulateRefinedCells(r.plainQuads, use, vertices, sheet, found.edges, found.refinement,
                                              &chords, perfect, exact, base.crossing, base.chord);
    stats.plainBends = r.cells.bends;
    r.capEdges = std::move(r.cells.capEdges);
  }
  r.cells.triangles.insert(r.cells.triangles.end(), r.sub.triangles.begin(), r.sub.triangles.end());
  r.capEdges.insert(r.capEdges.end(), r.sub.capEdges.begin(), r.sub.capEdges.end());
  return r;
}

// Stage 5r, after the sheet is emitted: the refined quads' vertices (crossings, chord points, the
// sub-grid's) and triangles into the mesh, and the sheet triangles beside the sub-grid split at its
// side nodes. quadTri: each quad's first sheet triangle (emitSheet).
void emitRefinedCells(const DepthMap& map, const RefinementFound& found, const RefinedStage& r,
                      const VolumeBuildOptions& options, const VertexBases& base, std::uint64_t sheetTriangles,
                      const volume::Scratch<std::uint32_t>& quadTri, VolumeMesh& mesh, VolumeBuildStats& stats) {
  using volume::QuadSlots;
  const bool subgrid = options.refineSubdivisions > 1;
  const bool adaptive = subgrid && !options.refineGridEverywhere;
  if (subgrid)
    std::copy(r.sub.positions.begin(), r.sub.positions.end(), mesh.positions.begin() + std::ptrdiff_t(base.subgrid));
  if (!subgrid || adaptive) {  // the adaptive sub-grid's plain quads bend at their chord points
    const volume::ChordPoints* chordPoints = options.refineChords || adaptive ? &found.chords : nullptr;
    volume::emitCrossingVertices(map, found.edges, found.refinement, chordPoints, base.crossing, base.chord, mesh);
  }
  std::copy(r.cells.triangles.begin(), r.cells.triangles.end(),
            mesh.triangles.begin() + std::ptrdiff_t(sheetTriangles));
  if (!subgrid) return;
  // One centroid vertex per split triangle.
  volume::splitQuadTriangles(
      r.sub.splits,
      [&](std::uint32_t quad) {
        return QuadSlots{quadTri[quad], 2};
      },
      mesh);
  const std::vector<std::uint32_t>& plain = r.plainQuads.quads;
  volume::splitQuadTriangles(
      r.sub.plainSplits,
      [&](std::uint32_t quad) {
        const auto p = std::size_t(std::lower_bound(plain.begin(), plain.end(), quad) - plain.begin());
        SV_CHECK(p < plain.size() && plain[p] == quad);
        const std::vector<std::uint32_t>& first = r.cells.firstTriangle;
        return QuadSlots{sheetTriangles + first[p], first[p + 1] - first[p]};
      },
      mesh);
  stats.subgridSplitTriangles = mesh.positions.size() - (base.subgrid + r.sub.positions.size());
}

// Stage 7f: the casters' faces towards the light in the columns of the refined quads and of the quads
// handed over to them (prismQuads, stage 0p), with the lit regions they lie in (the oracle's
// selection, caster_faces.h), and their prisms, appended as the mesh's second part.
void appendPrismPart(const DepthMap& map, const volume::RefinedQuads& quads, std::span<const std::uint8_t> prismQuads,
                     const VolumeBuildOptions& options, VolumeMesh& mesh, VolumeBuildStats& stats) {
  const auto t0 = volume::Clock::now();
  std::vector<std::uint8_t> flags(prismQuads.begin(), prismQuads.end());
  if (prismQuads.empty()) flags.assign(stats.quads, 0);
  SV_CHECK_EQ(flags.size(), stats.quads);
  for (const std::uint32_t q : quads.quads) flags[q] = 1;  // the build's refined quads too (a thin part's)
  const std::vector<std::array<glm::dvec3, 3>> faces = options.casterFaces(map, flags);
  const volume::FacePrismCounts c = volume::appendFacePrisms(map, faces, mesh);
  stats.prismFaces = c.faces;
  stats.prismWalls = c.walls;
  stats.prismTriangles = c.triangles;
  stats.msPrisms = volume::msSince(t0);
  stats.msRefine += stats.msPrisms;
}

}  // namespace

// Grid-sized scratch kept by a VolumeBuilder between builds.
struct VolumeBuilder::Scratch {
  volume::Scratch<double> blurred;          // sheet depths when materialised
  volume::Scratch<std::uint8_t> code;       // one code byte per quad
  volume::Scratch<std::uint32_t> quadTri;   // index of each kept quad's first triangle
  volume::Scratch<std::uint8_t> splitBits;  // refinement: boundary edges per texel
};

VolumeBuilder::VolumeBuilder() : scratch_(std::make_unique<Scratch>()) {}
VolumeBuilder::~VolumeBuilder() = default;
VolumeBuilder::VolumeBuilder(VolumeBuilder&&) noexcept = default;
VolumeBuilder& VolumeBuilder::operator=(VolumeBuilder&&) noexcept = default;

VolumeBuildResult buildVolume(const DepthMap& map, const VolumeBuildOptions& options) {
  VolumeBuilder builder;
  VolumeBuildResult result;
  builder.build(map, options, result);
  return result;
}

void VolumeBuilder::build(const DepthMap& map, const VolumeBuildOptions& options, VolumeBuildResult& result) {
  result.mesh.positions.clear();
  result.mesh.triangles.clear();
  result.mesh.partStarts.clear();
  result.mesh.origin = map.origin;
  result.stats = {};
  // A map of many small islands needs nine times a plain one's memory: refused before the build's
  // clock starts (it reads the map only where the worst case could pass half the memory).
  if (map.depth.size() == std::size_t(std::max(map.width, 0)) * std::size_t(std::max(map.height, 0)))
    checkVolumeFitsMemory(map);
  try {
    buildInto(map, options, result);
  } catch (...) {
    result.mesh.positions.clear();
    result.mesh.triangles.clear();
    result.mesh.partStarts.clear();
    result.stats = {};
    throw;
  }
}

void VolumeBuilder::buildInto(const DepthMap& map, const VolumeBuildOptions& options, VolumeBuildResult& result) {
  using namespace volume;
  // Not with the blur: it would carry the recaptured depths into the quads beside the prisms' columns.
  if (!(options.refineSteps > 0 && options.facePrisms && options.withoutCasters.depth && !options.blur &&
        map.width >= 2 && map.height >= 2)) {
    buildStages(map, options, {}, result);
    return;
  }
  // 0p. The sheet hands the prisms' columns over (volume/prism_columns.h): the refined quads of the
  // map as captured, then the build from the map recaptured there (where a caster is handed over).
  const auto tStart = Clock::now();
  validateMapAndOptions(map, options);
  validateDepths(map);  // before any ray (stage 2 checks the recaptured map again)
  std::shared_ptr<const PrismColumns> columns;
  std::size_t firstRays = 0;
  {
    const SheetDepths sheet(map, SheetDepthRule(map, options.bias.value_or(defaultBias(map)), options.blurOffset));
    const RefinementFound found = findRefinement(sheet, options, {}, scratch_->splitBits);
    firstRays = found.thinRays;
    columns = std::make_shared<const PrismColumns>(findPrismColumns(map, found.quads.quads, options.withoutCasters.depth));
  }
  const double msHandOver = msSince(tStart);
  if (columns->texelCount == 0) buildStages(map, options, {}, result);  // no caster to hand over
  else buildStages(columns->map, handOverColumns(options, columns), columns->quads, result);
  VolumeBuildStats& stats = result.stats;
  stats.prismColumnTexels = columns->texelCount;
  stats.raysCast += firstRays + columns->rays;
  stats.msPrisms += msHandOver;
  stats.msRefine += msHandOver;
  stats.msTotal = msSince(tStart);
}

void VolumeBuilder::buildStages(const DepthMap& map, const VolumeBuildOptions& options,
                                std::span<const std::uint8_t> prismQuads, VolumeBuildResult& result) {
  using namespace volume;
  const auto tStart = Clock::now();
  validateMapAndOptions(map, options);
  VolumeBuildStats& stats = result.stats;
  const double bias = options.bias.value_or(defaultBias(map));
  stats.biasUsed = bias;
  const int w = map.width, h = map.height;
  if (w < 2 || h < 2) {
    validateDepths(map);
    stats.msTotal = msSince(tStart);
    return;  // no quad: an empty volume
  }
  const std::size_t texels = std::size_t(w) * h;
  // Sheet + pinch copies + cap vertices, or sheet + two per boundary edge (at most two edges per
  // texel) + two per chord point (at most one per quad) + cap vertices.
  SV_CHECK_LT(8 * std::uint64_t(texels), std::uint64_t(kNone));
  stats.quads = std::size_t(w - 1) * (h - 1);
  const bool exact = options.cap == FarCap::Exact;
  const bool refine = options.refineSteps > 0;
  const bool subgrid = refine && options.refineSubdivisions > 1;
  const bool adaptive = subgrid && !options.refineGridEverywhere;  // plain refinement where it fits
  const bool perfect = options.triangulation == Triangulation::Perfect;

  // 1. Sheet depths: materialised for the blur (computed per row where needed otherwise).
  auto t0 = Clock::now();
  SheetDepths sheet(map, SheetDepthRule(map, bias, options.blurOffset));
  if (options.blur) {
    sheet.materialiseBlurred(scratch_->blurred);
    stats.msBlur = msSince(t0);
  }

  // 1r. Refinement: the boundary edges and the quads they touch.
  t0 = Clock::now();
  const std::span<const double> blurred =
      options.blur ? std::span<const double>(scratch_->blurred.data(), texels) : std::span<const double>();
  RefinementFound found = refine ? findRefinement(sheet, options, blurred, scratch_->splitBits) : RefinementFound{};
  double msRefine = msSince(t0);

  // 2. Quad codes: diagonals and kept triangles (refined quads marked). Every stored depth is
  // checked here, before any ray is cast.
  t0 = Clock::now();
  const GridUnprojector unproject(map);
  const QuadCodes codes = computeQuadCodes(
      sheet, unproject, {exact, perfect, refine ? scratch_->splitBits.data() : nullptr,
                        found.hiddenQuads + found.creaseQuads + found.thinQuads > 0},
      scratch_->code);
  const QuadGrid grid{w - 1, h - 1, scratch_->code.data()};
  recordQuadStats(codes, found, stats);
  double msSheet = msSince(t0);

  // 2r. Refinement: the crossings (the oracle's rays).
  if (refine && (!subgrid || adaptive)) {
    const auto tr = Clock::now();
    castRefinementRays(sheet, found.edges, found.quads, !subgrid, adaptive, blurred, options, found.refinement,
                       found.chords, stats);
    msRefine += msSince(tr);
  }
  stats.thinRays = found.thinRays;  // stage 1t's, cast before the crossings
  stats.raysCast += found.thinRays;
  t0 = Clock::now();

  const double refineBefore = msRefine;  // refinement time spent before this point
  // 3. Vertices, and 4. the cap's boundary: pinch and cut copies and cap edges of the grid sheet,
  // or the refined quads' triangles and walls, whose far edges bound the cap.
  const TexelUse use(grid, codes);
  const SheetVertices vertices = countSheetVertices(use, !refine);
  const VertexBases base = vertexBasesOf(vertices, found, adaptive);
  CapBoundary boundary;
  RefinedStage refined;
  double msEdges = 0.0;
  if (refine) {
    const auto tc = Clock::now();
    refined = buildRefinedCells(found, use, vertices, sheet, options, base, stats);
    boundary.edges = std::move(refined.capEdges);
    msRefine += msSince(tc);
  } else {
    const auto tRuns = Clock::now();
    boundary = findCapBoundary(use, vertices, sheet);
    msEdges = msSince(tRuns);
  }
  stats.splitVertices = boundary.copies;

  // The flattened cap needs only the edges: triangulated while the sheet is emitted.
  const bool flatCap = !exact || options.flattenCap;
  std::vector<std::array<std::uint32_t, 3>> cap;
  double msCapTask = 0.0;
  tbb::task_group capTask;
  if (flatCap)
    capTask.run([&] {
      const auto tc = Clock::now();
      cap = triangulateCapLoops(boundary.edges);
      msCapTask = msSince(tc);
    });

  // 5. The sheet: positions and triangles, then the pinch copies or the refined quads' crossing
  // vertices and triangles. Room for the cap too (a flattened cap has about as many triangles as
  // boundary edges), so that appending it rarely reallocates.
  VolumeMesh& mesh = result.mesh;
  const SubgridCells& sub = refined.sub;
  const std::uint64_t sheetTriangles = codes.sheetTriangles();
  sizeMeshBuffers(subgrid, base, vertices, boundary, found, sheetTriangles, refined, w + h, mesh);
  sizeBuffer(scratch_->quadTri, stats.quads);
  try {
    emitSheet(sheet, unproject, use, codes, vertices, mesh, scratch_->quadTri);
  } catch (...) {
    capTask.wait();
    throw;
  }
  if (refine) {
    const auto tc = Clock::now();
    emitRefinedCells(map, found, refined, options, base, sheetTriangles, scratch_->quadTri, mesh, stats);
    msRefine += msSince(tc);
  } else {
    emitPinchCopies(grid, boundary, scratch_->quadTri, mesh);
  }
  stats.msSheet = msSheet + msSince(t0) - msEdges - (msRefine - refineBefore);
  stats.msRefine = msRefine;

  // 6. The far cap.
  t0 = Clock::now();
  stats.capTrianglesBefore = sheetTriangles + refined.cells.footprint.size() + sub.footprintTriangles;
  if (flatCap) {
    capTask.wait();
    appendFlatCap(cap, mesh);
    stats.capTrianglesAfter = cap.size();
  } else {
    const ChordPoints* chords = refine && options.refineChords ? &found.chords : nullptr;
    const RefinedFootprint fp{refined.cells, found.edges, found.refinement, chords, base.crossing, base.chord};
    stats.capTrianglesAfter =
        appendMirroredCap(grid, scratch_->quadTri, boundary.edges, unproject, map, refine ? &fp : nullptr, mesh);
  }
  stats.msCap = msSince(t0) + msEdges + msCapTask;  // the cap's own work, partly run during the sheet
  if (adaptive) {                                   // drop the plain crossings of edges between two gridded quads
    const auto tc = Clock::now();
    dropUnusedVertices(mesh, base.crossing);
    stats.msRefine += msSince(tc);
  }
  // 7f. The face prisms in the refined quads' columns: a part of their own, after the sheet's.
  if (refine && options.facePrisms) appendPrismPart(map, found.quads, prismQuads, options, mesh, stats);
  stats.msTotal = msSince(tStart);
}

}  // namespace shadowvol
