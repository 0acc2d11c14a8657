// The refined GPU volume (--volume gpu --refine K, docs/gpu.md "The refined GPU volume"): the
// explicit builder's refined walls made on the GPU from the light pass's depth and triangle record,
// without a read-back of the map. Four steps of compute passes (GL 4.3):
//   1. boundary_edges.comp: every texel's boundary flags (boundary_edges.h's rule);
//   2. boundary_unfold.comp: the unfolding rounds (kMaxUnfoldRounds), every dispatch indirect and
//      given work groups only by a surface edge or the round before (no read-back);
//   3. walk_slots.comp lists the boundary edges and ambiguous quads to walk and the quads to refine;
//      silhouette_walk.comp with grid queries (or silhouette_rays.comp's bisection rays,
//      RefineCrossings::GpuRays), dispatched indirectly over the first list: each boundary edge's
//      crossing and each ambiguous quad's centre depth, as walk_crossings.h's refinementFromWalks
//      (or silhouette_refinement.h's bisection) makes them, into a W x H x 3 RGBA32F array texture
//      (layers: axis 0, axis 1, centre);
//   4. volume_refined.comp, dispatched indirectly over the refined quads, lists their triangles as
//      vertex indices into the indexed GPU volume's buffer, where the renderer's listing pass
//      (volume_index.frag with skipRefined) lists the other quads; volume_refined.vert places all.
// Internal to the renderer (Renderer::Impl, renderer_impl.h, owns one per context and sets the volume_common.glsl
// uniforms on every program before a frame).
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "shadowvol/boundary_edges.h"
#include "shadowvol/sheet_depth.h"
#include "shadowvol/silhouette_refinement.h"
#include "shadowvol/volume_mesh.h"
#include "shadowvol/gl/gl_objects.h"
#include "shadowvol/gl/shader_program.h"
#include "silhouette_walk.h"

namespace shadowvol::gl {

/// The crossings pass's counts of one refined GPU volume (its rays' or its walk's).
struct RefinedGpuCounts {
  std::uint32_t boundaryEdges = 0, fallbacks = 0;
};

/// The debug path: the CPU builder's Refinement for `edges` (the renderer passes the GPU's own,
/// boundaryEdgesFromFlags of the same flags, so every edge is found) from the GPU's flags and
/// records (readFlags, readRecords): an edge the GPU also found takes its crossing (s from the record's texel coordinates, its near and far depths); one
/// it did not gets the fallback of walk_crossings.h (the middle of the edge with the ends'
/// depths), counted in `fallbacks`. Centres: the record's depth where the GPU's flags give the quad
/// 3 or 4 boundary sides (it walked there), else the far plane, counted in `fallbacks` too.
Refinement refinementFromGpuRecords(const DepthMap& map, const BoundaryEdges& edges, const SheetDepthRule& rule,
                                    bool blur, std::span<const double> blurredSheetDepths,
                                    std::span<const glm::dvec2> centres, std::span<const std::uint32_t> flags,
                                    std::span<const glm::vec4> records);

/// The debug path's other half: the GPU's own triangles (the index list read back) as a mesh, each vertex index
/// placed as volume_refined.vert places it but in double (texels by sheetDepthOf of the read-back
/// map, crossings from the records), unused indices left out, the triangles in sorted order
/// (VolumeMesh::sortTriangles: the GPU's listing order varies between runs). For the mesh checks
/// (closed, outward, welded) of what the GPU drew.
VolumeMesh decodeRefinedGpuVolume(const DepthMap& map, const SheetDepthRule& rule, bool blur,
                                  std::span<const std::uint32_t> indices, std::span<const glm::vec4> records);

class RefinedGpuVolume {
 public:
  RefinedGpuVolume() = default;
  explicit RefinedGpuVolume(const ShaderLibrary& shaders);

  /// The programs that read volume_common.glsl's and refine_common.glsl's uniforms (the walk's and
  /// the rays' programs are their owners', SilhouetteWalk's and SilhouetteRays').
  std::vector<const Program*> programs() const { return {&boundary_, &unfold_, &slots_, &list_, &draw_}; }
  /// The listing pass's program (its drawCap uniform decides the cap).
  const Program& listProgram() const { return list_; }
  /// The boundary flags buffer (W H words, refine_common.glsl's bits) of the last findCrossings.
  GLuint flags() const { return flags_.id(); }

  /// Steps 1-3 for a W x H map (width, height). Textures: the final sheet depths on unit 0
  /// (lightDepth), with blur the unblurred on unit 3 (rawDepth). Step 3's crossings come from
  /// `crossings`, called with the buffers and the records bound as SilhouetteWalk::dispatchGrid
  /// (or SilhouetteRays::dispatchGrid) takes them and the byte offset of its indirect dispatch.
  void findCrossings(int width, int height, const TexelFootprint& footprint,
                     const std::function<void(GLintptr indirectOffset)>& crossings);

  /// Step 4: the refined quads' triangles appended as vertex indices to the buffers bound at SSBO
  /// 0 (index count, quad count) and 1 (indices, `capacity` of them), as volume_index.frag appends
  /// the other quads' (the caller runs both, reads the count back and draws with drawProgram).
  /// Textures as for findCrossings; binds the crossing records on unit 2 and leaves them bound.
  void dispatchCells(std::int64_t capacity);
  /// The vertex program of the whole list (volume_refined.vert); the records on unit 2.
  const Program& drawProgram() const { return draw_; }
  /// The counts of the last findCrossings: boundary edges refined (walked or bisected), fallbacks.
  RefinedGpuCounts walkCounts() const;

  /// Debug read-backs of the last findCrossings (tests, validation): every texel's boundary flags
  /// (refine_common.glsl's bits) and the crossing records, layer-major (layer k at k W H + j W + i).
  std::vector<std::uint32_t> readFlags() const;
  std::vector<glm::vec4> readRecords() const;

 private:
  void ensureSize(int w, int h);
  Program boundary_, unfold_, slots_, list_, draw_;
  Buffer flags_, counters_, rounds_, walkSlots_, refinedQuads_;
  Texture records_;
  int w_ = 0, h_ = 0;
};

}  // namespace shadowvol::gl
