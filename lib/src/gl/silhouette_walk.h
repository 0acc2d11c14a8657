// The GPU's silhouette walk (RefineCrossings::GpuWalk): refinement's crossings found on the GPU by
// walking over the scene's triangles (shaders/silhouette_walk.comp) instead of casting bisection
// rays, and handed to the CPU builder as a CrossingSource (walk_crossings.h). Internal to the
// renderer (Renderer::Impl, renderer_impl.h, owns one per context).
#pragma once

#include <cstdint>
#include <span>

#include <glm/mat4x4.hpp>

#include "shadowvol/gl/gl_objects.h"
#include "shadowvol/gl/shader_program.h"
#include "shadowvol/scene.h"
#include "shadowvol/walk_crossings.h"

namespace shadowvol::gl {

/// What one walk reads besides its queries: the scene as the light pass drew it and that pass's
/// triangle record.
struct WalkInputs {
  GLuint sceneVertices = 0;    ///< the renderer's scene VBO (position first, `vertexStride` floats per vertex)
  GLuint sceneIndices = 0;     ///< its index buffer (3 per triangle, Scene::merged() order)
  int vertexStride = 0;
  GLuint triangleIds = 0;      ///< R32UI, light_triangle.frag's record, at the map's size
  int width = 0, height = 0;   ///< the map's size
  glm::mat4 worldToLightView;  ///< V_light, composed in double
  glm::mat4 lightViewToWorld;  ///< its inverse, in double (the GPU's rays, silhouette_rays.h)
};

class SilhouetteWalk {
 public:
  SilhouetteWalk() = default;
  /// Compiles the walk (GL 4.3 compute).
  explicit SilhouetteWalk(const ShaderLibrary& shaders);

  /// The program, for the caller to set volume_common.glsl's uniforms (size, projection) on.
  const Program& program() const { return program_; }

  /// Forgets the scene's triangle neighbours; the next run builds them (triangle_adjacency.h) from
  /// `scene` (kept by the caller until then).
  void setScene(const Scene* scene);

  /// Walks every edge of `edges` and every centre, reads the answers back and turns them into a
  /// Refinement (refinementFromWalks; msRays = the walk's time, with the read-back). The
  /// program's volume_common uniforms must be set for the map. Throws GlError on a GL failure,
  /// InputError for more queries than one dispatch takes or a query outside the map.
  Refinement run(const WalkInputs& in, const DepthMap& map, const BoundaryEdges& edges, const SheetDepthRule& rule,
                 bool blur, std::span<const double> blurredSheetDepths, std::span<const glm::dvec2> centres);

  /// The walk's raw answers to `queries`, in order (the same uniforms needed as for run); a far
  /// edge's walk stops where the depth reaches `hitLimit` (the rule's last hit depth).
  std::vector<WalkResult> answers(const WalkInputs& in, std::span<const WalkQuery> queries, double hitLimit);

  /// The grid queries of the refined GPU volume (silhouette_walk.comp's gridQueries = 1): one
  /// dispatch, indirect from the bound GL_DISPATCH_INDIRECT_BUFFER at `indirectOffset`, over
  /// walk_slots.comp's list; the caller binds the boundary flags (SSBO 5), the counters (SSBO 6),
  /// the list (SSBO 7) and the crossing records (image unit 0) and orders the memory barrier.
  void dispatchGrid(const WalkInputs& in, double hitLimit, GLintptr indirectOffset);

 private:
  void ensureNeighbours();
  void bindInputs(const WalkInputs& in, double hitLimit);  // scene buffers, triangle record, uniforms
  void unbindInputs();
  Program program_;
  const Scene* scene_ = nullptr;
  bool neighboursBuilt_ = false;
  Buffer neighbours_, queries_, results_;
};

}  // namespace shadowvol::gl
