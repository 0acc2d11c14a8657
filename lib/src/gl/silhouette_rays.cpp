#include "silhouette_rays.h"

#include <algorithm>
#include <vector>

#include <glm/vec4.hpp>

#include "shadowvol/check.h"
#include "shadowvol/depth_map.h"
#include "shadowvol/error.h"
#include "shadowvol/gl/gl_error.h"
#include "shadowvol/triangle_bvh.h"

namespace shadowvol::gl {

// silhouette_rays.comp's traversal stack holds kStack = 64 nodes: at most one per level.
static_assert(kBvhMaxDepth == 64, "keep silhouette_rays.comp's kStack in step");

SilhouetteRays::SilhouetteRays(const ShaderLibrary& shaders)
    : program_(Program::compute(shaders, {"version_430.glsl", "light_window_depth.glsl", "volume_common.glsl",
                                          "refine_common.glsl", "silhouette_rays.comp"})),
      nodes_(makeBuffer()),
      triangles_(makeBuffer()) {}

void SilhouetteRays::setScene(const Scene* scene) {
  scene_ = scene;
  built_ = false;
  nodeCount_ = 0;
}

void SilhouetteRays::ensureHierarchy() {
  if (built_) return;
  SV_CHECK(scene_ != nullptr);
  const TriangleMesh mesh = scene_->merged();
  // Both buffers must fit one shader storage block (128 MiB on llvmpipe: about 2 million triangles).
  GLint64 limit = 0;
  SV_GL(glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &limit));
  const std::uint64_t cornerBytes = 3 * 16 * std::uint64_t(mesh.triangles.size()), nodeBytes = 2 * 32 * std::uint64_t(mesh.triangles.size());
  if (limit > 0 && std::max(cornerBytes, nodeBytes) > std::uint64_t(limit))
    throw InputError("RenderOptions", "refineCrossings", "rays",
                     MarkedProblem{"the GPU's rays need " + std::to_string(std::max(cornerBytes, nodeBytes) >> 20) + " MiB for the " +
                         std::to_string(mesh.triangles.size()) + " triangles' hierarchy in one buffer, above this "
                         "OpenGL's shader storage block limit of " + std::to_string(limit >> 20) +
                         " MiB: set ${refineCrossings} to gpu-walk or ${volume} to explicit"});
  const TriangleBvh bvh = buildTriangleBvh(mesh);
  // Buffers of at least one element, so an empty scene binds valid ranges (nodeCount 0 stops
  // every ray before it reads them).
  const BvhNode noNode{};
  // The corners in leaf order, as vec4 (std430's stride for vec4): one load each in the shader.
  std::vector<glm::vec4> corners(std::max<std::size_t>(3 * bvh.triangles.size(), 1));
  for (std::size_t k = 0; k < bvh.triangles.size(); ++k)
    for (int c = 0; c < 3; ++c) corners[3 * k + c] = glm::vec4(mesh.positions[bvh.triangles[k][c]], 1.0f);
  SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, nodes_.id()));
  SV_GL(glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(std::max<std::size_t>(bvh.nodes.size(), 1) * sizeof(BvhNode)),
                     bvh.nodes.empty() ? &noNode : bvh.nodes.data(), GL_STATIC_DRAW));
  SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, triangles_.id()));
  SV_GL(glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(corners.size() * sizeof(glm::vec4)), corners.data(),
                     GL_STATIC_DRAW));
  SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0));
  nodeCount_ = bvh.nodes.size();
  built_ = true;
}

void SilhouetteRays::dispatchGrid(const WalkInputs& in, int steps, CaptureMode capture, bool snap,
                                  GLintptr indirectOffset) {
  SV_CHECK(capture != CaptureMode::Midpoint);
  ensureHierarchy();
  SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, triangles_.id()));
  SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, nodes_.id()));
  program_.use();
  program_.set("lightViewToWorld", in.lightViewToWorld);
  program_.set("worldToLightView", in.worldToLightView);
  program_.set("snapCrossings", snap ? 1 : 0);
  program_.set("refineSteps", steps);
  // silhouette_rays.comp's kFrontRule, kBackRule, kEntryRule.
  program_.set("captureRule", capture == CaptureMode::Back ? 1 : capture == CaptureMode::Entry ? 2 : 0);
  program_.set("grazingCos", float(kEntryGrazingCos));
  program_.set("nodeCount", int(std::min<std::size_t>(nodeCount_, 0x7fffffff)));
  SV_GL(glDispatchComputeIndirect(indirectOffset));
  for (GLuint b = 3; b < 5; ++b) SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, b, 0));
}

}  // namespace shadowvol::gl
