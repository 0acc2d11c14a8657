// A point light's GPU cube volume (`volume gpu` for a point light; docs/gpu.md "The GPU cube
// volume"): the cells of cube::Grid (shadowvol/cube_grid.h) drawn straight from the six faces'
// light-view depths, without a read-back. The faces' depths (each face's resolved, and with blur
// blurred, R32F map) are copied into the layers of one N x N x 6 array texture
// (glCopyImageSubData: GL 4.3); the seam cells' texel ids sit in a buffer made once per N. Two
// ways to draw, the same surface:
//   - Indexed (the default): volume_cube_list.comp lists each cell's triangles as vertex indices
//     into a buffer sized for the worst case, with the count in an indirect draw command;
//     volume_cube_indexed.vert places the vertices, each once per use in the vertex cache. It
//     leaves out the all-far sheet triangles and their cap images, as buildCubeVolume does, and
//     draws the cap of each whole quadrant of 8 x 8 inner cells as one fan;
//   - AllQuads: one point per cell through volume_cube.geom, which emits a kept cell's triangles
//     all (an all-far one on the sheet and the cap, where the two cancel in the stencil). Used
//     as well where the indexed way's worst case exceeds kMaxCubeIndices.
// Either gives the surface of buildCubeVolume (cube_volume.h), in float, its cap triangulated
// otherwise. Internal to the renderer (Renderer::Impl, renderer_impl.h, owns one per context).
#pragma once

#include <cstddef>
#include <utility>

#include <glm/mat4x4.hpp>

#include "shadowvol/frame.h"
#include "shadowvol/gl/gl_objects.h"
#include "shadowvol/gl/shader_program.h"

namespace shadowvol::gl {

/// The sheet-depth rule's and the diagonal's inputs (volume_common.glsl's uniforms).
struct CubeVolumeRule {
  double nearPlane = 0.0, farPlane = 1.0, bias = 0.0;
  bool perfect = true;
};

/// The indexed way's largest index buffer (512 MiB, as the one-map indexed way's): faces of up to
/// 1,365 texels a side.
inline constexpr std::size_t kMaxCubeIndices = std::size_t(128) << 20;

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
  /// Lists the triangles for the faces stored (the indexed way's compute pass; nothing for the
  /// geometry-shader way). `how`: Indexed or AllQuads (any other is Indexed); returns the way the
  /// next draw takes (AllQuads where Indexed would not fit).
  GpuVolumeDraw list(const CubeVolumeRule& rule, GpuVolumeDraw how);
  /// Draws the volume listed (stencil state and depth clamp are the caller's); `lightToClip` maps
  /// light-relative world positions to the camera's clip space.
  void draw(const glm::dmat4& lightToClip);
  /// The last draw's triangles and the cells that drew any (AllQuads: every cell), read back
  /// (call after the frame's passes: it waits for the draw).
  std::pair<std::size_t, std::size_t> lastCounts() const;

 private:
  void setUniforms(const Program& p, const CubeVolumeRule& rule) const;
  void listIndexed(const CubeVolumeRule& rule);
  void bindDepth() const;
  void unbindDepth() const;
  void drawPoints(const glm::dmat4& lightToClip);

  Program points_, list_, indexed_;
  Texture depth_;
  Buffer seamCells_, command_, indices_;
  VertexArray seamVao_, emptyVao_, indexedVao_;
  Query primitives_;
  int n_ = 0;
  std::size_t capacity_ = 0;  // indices_'s size in indices
  GpuVolumeDraw lastWay_ = GpuVolumeDraw::Auto;
  CubeVolumeRule rule_;  // the last list's
};

}  // namespace shadowvol::gl
