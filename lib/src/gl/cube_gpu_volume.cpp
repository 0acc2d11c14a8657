#include "cube_gpu_volume.h"

#include <algorithm>
#include <array>
#include <vector>

#include <glm/gtc/type_ptr.hpp>

#include "shadowvol/check.h"
#include "shadowvol/cube_grid.h"
#include "shadowvol/cube_map.h"
#include "shadowvol/depth_blur.h"
#include "shadowvol/gl/gl_error.h"
#include "shadowvol/triangulation.h"

namespace shadowvol::gl {
namespace {

std::size_t innerQuads(int n) { return cube::innerQuadCount(n); }

// Face f's D, R, U of cube_map.h's table, as cube_common.glsl's uniform arrays.
void setFaceBases(const Program& p) {
  std::array<glm::vec3, kCubeFaces> d{}, r{}, u{};
  for (int f = 0; f < kCubeFaces; ++f) {
    d[f] = glm::vec3(cubeFaceDirection(f));
    u[f] = glm::vec3(cubeFaceUp(f));
    r[f] = glm::vec3(glm::cross(cubeFaceDirection(f), cubeFaceUp(f)));
  }
  SV_GL(glUniform3fv(p.location("faceDirection"), kCubeFaces, glm::value_ptr(d[0])));
  SV_GL(glUniform3fv(p.location("faceRight"), kCubeFaces, glm::value_ptr(r[0])));
  SV_GL(glUniform3fv(p.location("faceUp"), kCubeFaces, glm::value_ptr(u[0])));
}

}  // namespace

CubeGpuVolume::CubeGpuVolume(const ShaderLibrary& shaders)
    : points_(shaders, {"version_330.glsl", "light_window_depth.glsl", "volume_common.glsl", "cube_common.glsl", "volume_cube.vert"},
              {"version_330.glsl", "light_window_depth.glsl", "volume_common.glsl", "cube_common.glsl", "volume_cube.geom"},
              {"depth_only.frag"}),
      list_(Program::compute(shaders, {"version_430.glsl", "light_window_depth.glsl", "volume_common.glsl",
                                       "cube_common.glsl", "volume_cube_list.comp"})),
      indexed_(shaders, {"version_430.glsl", "light_window_depth.glsl", "volume_common.glsl", "cube_common.glsl",
                         "volume_cube_indexed.vert"},
               {"depth_only.frag"}),
      command_(makeBuffer()),
      indices_(makeBuffer()),
      seamVao_(makeVertexArray()),
      emptyVao_(makeVertexArray()),
      indexedVao_(makeVertexArray()),
      primitives_(makeQuery()) {
  SV_GL(glBindVertexArray(indexedVao_.id()));
  SV_GL(glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.id()));
  SV_GL(glBindVertexArray(0));
}

void CubeGpuVolume::resize(int n) {
  SV_CHECK_GE(n, 2);
  if (n == n_) return;
  depth_ = makeTexture();
  SV_GL(glBindTexture(GL_TEXTURE_2D_ARRAY, depth_.id()));
  SV_GL(glTexStorage3D(GL_TEXTURE_2D_ARRAY, 1, GL_R32F, n, n, kCubeFaces));
  SV_GL(glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST));
  SV_GL(glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST));
  SV_GL(glBindTexture(GL_TEXTURE_2D_ARRAY, 0));
  // The cells across the cube's edges and corners, as cube::Grid lists them after the inner quads.
  const cube::Grid grid(n);
  std::vector<glm::ivec4> seams;
  seams.reserve(grid.size() - innerQuads(n));
  for (std::size_t c = innerQuads(n); c < grid.size(); ++c) {
    const cube::Cell cell = grid[c];
    seams.emplace_back(int(cell.v[0]), int(cell.v[1]), cell.triangle ? -1 : int(cell.v[2]), int(cell.v[3]));
  }
  seamCells_ = makeBuffer();
  SV_GL(glBindVertexArray(seamVao_.id()));
  SV_GL(glBindBuffer(GL_ARRAY_BUFFER, seamCells_.id()));
  SV_GL(glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(seams.size() * sizeof(glm::ivec4)), seams.data(), GL_STATIC_DRAW));
  SV_GL(glEnableVertexAttribArray(0));
  SV_GL(glVertexAttribIPointer(0, 4, GL_INT, sizeof(glm::ivec4), nullptr));
  SV_GL(glBindVertexArray(0));
  SV_GL(glBindBuffer(GL_ARRAY_BUFFER, 0));
  n_ = n;
}

void CubeGpuVolume::storeFace(int face, const Texture& depth) {
  SV_CHECK(n_ >= 2 && face >= 0 && face < kCubeFaces);
  SV_GL(glCopyImageSubData(depth.id(), GL_TEXTURE_2D, 0, 0, 0, 0, depth_.id(), GL_TEXTURE_2D_ARRAY, 0, 0, 0, face,
                           n_, n_, 1));
}

std::size_t CubeGpuVolume::cells() const { return n_ < 2 ? 0 : innerQuads(n_) + 12u * std::size_t(n_ - 1) + 8u; }

void CubeGpuVolume::setUniforms(const Program& p, const CubeVolumeRule& rule) const {
  p.use();
  p.set("cubeDepth", 0);
  p.set("cubeSize", n_);
  p.set("farPlane", float(rule.farPlane));
  p.set("nearPlane", float(rule.nearPlane));
  p.set("farSnap", float(rule.farPlane * (1.0 - kFarSnap)));
  p.set("bias", float(rule.bias));
  p.set("perfect", rule.perfect ? 1 : 0);
  p.set("drawCap", 1);
  p.set("planarTolerance", float(kPlanarTolerance));
  setFaceBases(p);
}

GpuVolumeDraw CubeGpuVolume::list(const CubeVolumeRule& rule, GpuVolumeDraw how) {
  SV_CHECK_GE(n_, 2);
  rule_ = rule;
  lastWay_ = how != GpuVolumeDraw::AllQuads && 12u * cells() <= kMaxCubeIndices ? GpuVolumeDraw::Indexed
                                                                                 : GpuVolumeDraw::AllQuads;
  if (lastWay_ == GpuVolumeDraw::Indexed) {
    bindDepth();
    listIndexed(rule);
    unbindDepth();
  }
  return lastWay_;
}

void CubeGpuVolume::draw(const glm::dmat4& lightToClip) {
  SV_CHECK(lastWay_ == GpuVolumeDraw::Indexed || lastWay_ == GpuVolumeDraw::AllQuads);
  bindDepth();
  if (lastWay_ == GpuVolumeDraw::Indexed) {
    setUniforms(indexed_, rule_);
    indexed_.set("lightToClip", glm::mat4(lightToClip));
    SV_GL(glBindVertexArray(indexedVao_.id()));
    SV_GL(glBindBuffer(GL_DRAW_INDIRECT_BUFFER, command_.id()));
    SV_GL(glDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT, nullptr));
    SV_GL(glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0));
  } else {
    drawPoints(lightToClip);
  }
  SV_GL(glBindVertexArray(0));
  unbindDepth();
}

void CubeGpuVolume::bindDepth() const {
  SV_GL(glActiveTexture(GL_TEXTURE0));
  SV_GL(glBindTexture(GL_TEXTURE_2D_ARRAY, depth_.id()));
  SV_GL(glBindSampler(0, 0));
}

void CubeGpuVolume::unbindDepth() const { SV_GL(glBindTexture(GL_TEXTURE_2D_ARRAY, 0)); }

void CubeGpuVolume::drawPoints(const glm::dmat4& lightToClip) {
  setUniforms(points_, rule_);
  points_.set("lightToClip", glm::mat4(lightToClip));
  SV_GL(glBeginQuery(GL_PRIMITIVES_GENERATED, primitives_.id()));
  points_.set("seamCells", 0);
  SV_GL(glBindVertexArray(emptyVao_.id()));
  SV_GL(glDrawArrays(GL_POINTS, 0, GLsizei(innerQuads(n_))));
  points_.set("seamCells", 1);
  SV_GL(glBindVertexArray(seamVao_.id()));
  SV_GL(glDrawArrays(GL_POINTS, 0, GLsizei(cells() - innerQuads(n_))));
  SV_GL(glEndQuery(GL_PRIMITIVES_GENERATED));
}

void CubeGpuVolume::listIndexed(const CubeVolumeRule& rule) {
  const std::size_t worst = 12u * cells();
  if (capacity_ != worst) {
    SV_GL(glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.id()));
    SV_GL(glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(worst * sizeof(GLuint)), nullptr, GL_DYNAMIC_DRAW));
    SV_GL(glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0));
    capacity_ = worst;
  }
  // DrawElementsIndirectCommand {count 0, one instance, first 0, base vertex 0, base instance 0}
  // and the cells kept.
  const std::array<GLuint, 6> command{0, 1, 0, 0, 0, 0};
  SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, command_.id()));
  SV_GL(glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(sizeof command), command.data(), GL_DYNAMIC_DRAW));
  SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0));
  setUniforms(list_, rule);
  list_.set("cellCount", int(cells()));
  SV_GL(glUniform1ui(list_.location("capacity"), GLuint(capacity_)));
  SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, command_.id()));
  SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, indices_.id()));
  SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, seamCells_.id()));
  // The inner quads in blocks of 16 x 16 per work group (at most 1,024 a side: N <= 16,384), then
  // the seam cells, 256 a group (at most 768 groups).
  const GLuint blocks = GLuint((n_ - 1 + 15) / 16);
  list_.set("blockMode", 1);
  SV_GL(glDispatchCompute(blocks, blocks, GLuint(kCubeFaces)));
  SV_GL(glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT));
  list_.set("blockMode", 0);
  SV_GL(glDispatchCompute(GLuint((cells() - innerQuads(n_) + 255) / 256), 1, 1));
  SV_GL(glMemoryBarrier(GL_ELEMENT_ARRAY_BARRIER_BIT | GL_COMMAND_BARRIER_BIT));
  for (GLuint b = 0; b < 3; ++b) SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, b, 0));
}

std::pair<std::size_t, std::size_t> CubeGpuVolume::lastCounts() const {
  if (lastWay_ == GpuVolumeDraw::AllQuads) {
    GLuint64 triangles = 0;
    SV_GL(glGetQueryObjectui64v(primitives_.id(), GL_QUERY_RESULT, &triangles));
    return {std::size_t(triangles), cells()};
  }
  SV_CHECK(lastWay_ == GpuVolumeDraw::Indexed);
  std::array<GLuint, 6> command{};
  SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, command_.id()));
  SV_GL(glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(sizeof command), command.data()));
  SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0));
  return {std::size_t(command[0] / 3), std::size_t(command[5])};
}

}  // namespace shadowvol::gl
