// The refined GPU volume's crossings by bisection rays cast on the GPU (shaders/silhouette_rays.comp,
// docs/gpu.md "Crossings from GPU rays"): the CPU builder's bisection, rule for rule, with each ray
// traced through a hierarchy of the scene's triangles (triangle_bvh.h) instead of Embree's.
// Internal to the renderer (Renderer::Impl, renderer_impl.h, owns one per context).
#pragma once

#include "shadowvol/gl/gl_objects.h"
#include "shadowvol/gl/shader_program.h"
#include "shadowvol/scene.h"
#include "silhouette_walk.h"

namespace shadowvol::gl {

class SilhouetteRays {
 public:
  SilhouetteRays() = default;
  /// Compiles the rays' program (GL 4.3 compute).
  explicit SilhouetteRays(const ShaderLibrary& shaders);
  /// The program, for the caller to set volume_common.glsl's and refine_common.glsl's uniforms on.
  const Program& program() const { return program_; }
  /// Forgets the hierarchy; the next dispatch builds it from `scene` (kept by the caller until then).
  void setScene(const Scene* scene);
  /// One dispatch, indirect from the bound GL_DISPATCH_INDIRECT_BUFFER at `indirectOffset`, over
  /// walk_slots.comp's list, `steps` rays per boundary edge by `capture`'s rule (back or front);
  /// the caller binds the boundary flags (SSBO 5), the counters (SSBO 6), the list (SSBO 7) and
  /// the crossing records (image unit 0) and orders the memory barrier. Of `in` it reads
  /// lightViewToWorld and worldToLightView (the triangles are the hierarchy's own copy).
  /// With `snap`, each crossing is then snapped as crossing_snap.h does (VolumeBuildOptions::refineSnap).
  void dispatchGrid(const WalkInputs& in, int steps, CaptureMode capture, bool snap, GLintptr indirectOffset);

 private:
  void ensureHierarchy();
  Program program_;
  const Scene* scene_ = nullptr;
  bool built_ = false;
  std::size_t nodeCount_ = 0;
  Buffer nodes_, triangles_;
};

}  // namespace shadowvol::gl
