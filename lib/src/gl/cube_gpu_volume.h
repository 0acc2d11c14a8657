// A point light's GPU cube volume (`volume gpu` for a point light; docs/gpu.md "The GPU cube
// volume"): the cells of cube::Grid (shadowvol/cube_grid.h) drawn straight from the six faces'
// light-view depths by shaders/volume_cube.vert and .geom, without a read-back. The faces' depths
// (each face's resolved, and with blur blurred, R32F map) are copied into the layers of one
// N x N x 6 array texture (glCopyImageSubData: GL 4.3); the seam cells' texel ids sit in a vertex
// buffer made once per N. The triangles are buildCubeVolume's (cube_volume.h) before its far-cap
// flattening, with the all-far triangles drawn on the sheet and the cap where they cancel.
// Internal to the renderer (renderer.cpp owns one per context).
#pragma once

#include <cstddef>

#include <glm/mat4x4.hpp>

#include "shadowvol/gl/gl_objects.h"
#include "shadowvol/gl/shader_program.h"

namespace shadowvol::gl {

/// The sheet-depth rule's and the diagonal's inputs (volume_common.glsl's uniforms).
struct CubeVolumeRule {
  double nearPlane = 0.0, farPlane = 1.0, bias = 0.0;
  bool perfect = true;
};

class CubeGpuVolume {
 public:
  CubeGpuVolume() = default;
  explicit CubeGpuVolume(const ShaderLibrary& shaders);

  /// Makes the array texture and the seam cells for N x N faces (kept while N stays).
  void resize(int n);
  /// Copies face f's N x N R32F light-view depths into layer f.
  void storeFace(int face, const Texture& depth);
  /// The cells of the faces stored: 6 (N-1)^2 + 12 (N-1) + 8.
  std::size_t cells() const;
  /// Draws the volume (stencil state and depth clamp are the caller's); `lightToClip` maps
  /// light-relative world positions to the camera's clip space. Counts the triangles emitted in
  /// `primitivesQuery` (GL_PRIMITIVES_GENERATED).
  void draw(const glm::dmat4& lightToClip, const CubeVolumeRule& rule, GLuint primitivesQuery) const;

 private:
  Program program_;
  Texture depth_;
  Buffer seamCells_;
  VertexArray seamVao_, emptyVao_;
  int n_ = 0;
};

}  // namespace shadowvol::gl
