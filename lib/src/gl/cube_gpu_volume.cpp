#include "cube_gpu_volume.h"

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

std::size_t innerQuads(int n) { return std::size_t(kCubeFaces) * std::size_t(n - 1) * std::size_t(n - 1); }

// Face f's D, R, U of cube_map.h's table, as volume_cube.geom's uniform arrays.
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
    : program_(shaders, {"version_330.glsl", "volume_cube.vert"},
               {"version_330.glsl", "light_window_depth.glsl", "volume_common.glsl", "volume_cube.geom"},
               {"depth_only.frag"}),
      seamVao_(makeVertexArray()),
      emptyVao_(makeVertexArray()) {}

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

void CubeGpuVolume::draw(const glm::dmat4& lightToClip, const CubeVolumeRule& rule, GLuint primitivesQuery) const {
  SV_CHECK_GE(n_, 2);
  program_.use();
  program_.set("cubeDepth", 0);
  program_.set("cubeSize", n_);
  program_.set("farPlane", float(rule.farPlane));
  program_.set("nearPlane", float(rule.nearPlane));
  program_.set("farSnap", float(rule.farPlane * (1.0 - kFarSnap)));
  program_.set("bias", float(rule.bias));
  program_.set("perfect", rule.perfect ? 1 : 0);
  program_.set("drawCap", 1);
  program_.set("planarTolerance", float(kPlanarTolerance));
  program_.set("lightToClip", glm::mat4(lightToClip));
  setFaceBases(program_);
  SV_GL(glActiveTexture(GL_TEXTURE0));
  SV_GL(glBindTexture(GL_TEXTURE_2D_ARRAY, depth_.id()));
  SV_GL(glBeginQuery(GL_PRIMITIVES_GENERATED, primitivesQuery));
  program_.set("seamCells", 0);
  SV_GL(glBindVertexArray(emptyVao_.id()));
  SV_GL(glDrawArrays(GL_POINTS, 0, GLsizei(innerQuads(n_))));
  program_.set("seamCells", 1);
  SV_GL(glBindVertexArray(seamVao_.id()));
  SV_GL(glDrawArrays(GL_POINTS, 0, GLsizei(cells() - innerQuads(n_))));
  SV_GL(glEndQuery(GL_PRIMITIVES_GENERATED));
  SV_GL(glBindVertexArray(0));
  SV_GL(glBindTexture(GL_TEXTURE_2D_ARRAY, 0));
}

}  // namespace shadowvol::gl
