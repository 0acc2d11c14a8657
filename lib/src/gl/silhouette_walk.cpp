#include "silhouette_walk.h"

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

#include "shadowvol/check.h"
#include "shadowvol/error.h"
#include "shadowvol/gl/gl_error.h"
#include "shadowvol/triangle_adjacency.h"

namespace shadowvol::gl {

namespace {
constexpr int kLocalSize = 64;  // silhouette_walk.comp's local_size_x
constexpr int kMaxRestarts = 4;  // silhouette_walk.comp: walks resumed past a fold, per edge
constexpr std::size_t kMaxQueries = std::size_t(65535) * kLocalSize;  // one row of work groups
}  // namespace

SilhouetteWalk::SilhouetteWalk(const ShaderLibrary& shaders)
    : program_(Program::compute(shaders, {"version_430.glsl", "light_window_depth.glsl", "volume_common.glsl",
                                          "refine_common.glsl", "silhouette_walk.comp"})),
      neighbours_(makeBuffer()),
      queries_(makeBuffer()),
      results_(makeBuffer()) {}

void SilhouetteWalk::setScene(const Scene* scene) {
  scene_ = scene;
  neighboursBuilt_ = false;
}

void SilhouetteWalk::ensureNeighbours() {
  if (neighboursBuilt_) return;
  SV_CHECK(scene_ != nullptr);
  const std::vector<std::int32_t> n = triangleNeighbours(scene_->merged());
  SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, neighbours_.id()));
  // A buffer of at least one element, so an empty scene binds a valid range.
  const std::int32_t none = kNoNeighbour;
  SV_GL(glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(std::max<std::size_t>(n.size(), 1) * sizeof(std::int32_t)),
                     n.empty() ? &none : n.data(), GL_STATIC_DRAW));
  neighboursBuilt_ = true;
}

std::vector<WalkResult> SilhouetteWalk::answers(const WalkInputs& in, std::span<const WalkQuery> queries,
                                                double hitLimit) {
  ensureNeighbours();
  std::vector<WalkResult> out(queries.size());
  if (queries.size() > kMaxQueries)
    throw InputError("silhouette walk", "boundary edges", std::to_string(queries.size()),
                     "more walks than one dispatch takes (" + std::to_string(kMaxQueries) + ")");
  if (queries.empty()) return out;
  const int size[2] = {in.width, in.height};
  for (std::size_t k = 0; k < queries.size(); ++k) {  // every texel a query reads lies in the map
    const WalkQuery& q = queries[k];
    const bool edge = q.kind == WalkQuery::kEdge;
    const int di = edge ? ((q.flags & 1u) == 0u) : 1, dj = edge ? ((q.flags & 1u) != 0u) : 1;
    if ((q.kind != WalkQuery::kEdge && q.kind != WalkQuery::kCentre) || q.i < 0 || q.j < 0 || q.i + di >= size[0] ||
        q.j + dj >= size[1])
      throw InputError("silhouette walk", "query " + std::to_string(k),
                       std::to_string(q.kind) + " at " + std::to_string(q.i) + ", " + std::to_string(q.j),
                       "not an edge or quad of the " + std::to_string(size[0]) + " x " + std::to_string(size[1]) + " map");
  }
  SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, queries_.id()));
  SV_GL(glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(queries.size() * sizeof(WalkQuery)), queries.data(),
                     GL_STREAM_DRAW));
  SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, results_.id()));
  SV_GL(glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(out.size() * sizeof(WalkResult)), nullptr, GL_STREAM_READ));
  SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, queries_.id()));
  SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, results_.id()));
  bindInputs(in, hitLimit);
  program_.set("queryCount", int(queries.size()));
  program_.set("gridQueries", 0);
  SV_GL(glDispatchCompute(GLuint((queries.size() + kLocalSize - 1) / kLocalSize), 1, 1));
  SV_GL(glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT));
  SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, results_.id()));
  SV_GL(glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(out.size() * sizeof(WalkResult)), out.data()));
  unbindInputs();
  return out;
}

void SilhouetteWalk::bindInputs(const WalkInputs& in, double hitLimit) {
  ensureNeighbours();
  SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, in.sceneVertices));
  SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, in.sceneIndices));
  SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, neighbours_.id()));
  program_.use();
  program_.set("vertexStride", in.vertexStride);
  program_.set("worldToLightView", in.worldToLightView);
  program_.set("triangleIds", 1);
  program_.set("hitLimit", float(hitLimit));
  program_.set("maxRestarts", kMaxRestarts);
  program_.set("depthHalvings", 16);
  program_.set("candidateTexels", 6);
  SV_GL(glActiveTexture(GL_TEXTURE1));
  SV_GL(glBindTexture(GL_TEXTURE_2D, in.triangleIds));
  SV_GL(glActiveTexture(GL_TEXTURE0));
}

void SilhouetteWalk::unbindInputs() {
  SV_GL(glActiveTexture(GL_TEXTURE1));
  SV_GL(glBindTexture(GL_TEXTURE_2D, 0));
  SV_GL(glActiveTexture(GL_TEXTURE0));
  for (GLuint b = 0; b < 5; ++b) SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, b, 0));
  SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0));
}

void SilhouetteWalk::dispatchGrid(const WalkInputs& in, double hitLimit, GLintptr indirectOffset) {
  bindInputs(in, hitLimit);
  program_.set("gridQueries", 1);
  SV_GL(glDispatchComputeIndirect(indirectOffset));
  unbindInputs();
}

Refinement SilhouetteWalk::run(const WalkInputs& in, const DepthMap& map, const BoundaryEdges& edges,
                               const SheetDepthRule& rule, bool blur, std::span<const double> blurredSheetDepths,
                               std::span<const glm::dvec2> centres) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<WalkQuery> queries = walkQueries(edges, centres);
  // A sample is a hit while ofSample keeps it short of the far plane: stored + bias (+ the blur
  // offset) below farSnap.
  const double hitLimit = std::min(rule.farSnap, rule.farSnap - rule.bias - (blur ? rule.blurOffset : 0.0));
  const std::vector<WalkResult> found = answers(in, queries, hitLimit);
  Refinement r = refinementFromWalks(map, edges, rule, blur, blurredSheetDepths, found, centres.size());
  r.msRays = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace shadowvol::gl
