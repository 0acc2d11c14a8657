#include "refined_gpu_volume.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "shadowvol/check.h"
#include "shadowvol/gl/gl_error.h"

namespace shadowvol::gl {

namespace {
constexpr int kGroup = 8;  // local size 8 x 8 of boundary_edges.comp, boundary_unfold.comp, volume_refined.comp
constexpr std::int64_t kMaxIndexBytes = std::int64_t(1) << 29;  // 512 MiB

std::vector<std::string> sources(const char* body) {
  return {"version_430.glsl", "light_window_depth.glsl", "volume_common.glsl", "refine_common.glsl", body};
}
}  // namespace

Refinement refinementFromGpuRecords(const DepthMap& map, const BoundaryEdges& edges, const SheetDepthRule& rule,
                                    bool blur, std::span<const double> blurredSheetDepths,
                                    std::span<const glm::dvec2> centres, std::span<const std::uint32_t> flags,
                                    std::span<const glm::vec4> records) {
  const std::size_t texels = std::size_t(map.width) * std::size_t(map.height);
  SV_CHECK_EQ(flags.size(), texels);
  SV_CHECK_EQ(records.size(), 3 * texels);
  constexpr std::uint32_t kBoundaryBit = 1, kNearAtPBit = 4, kSurfaceBit = 16;  // refine_common.glsl
  // The GPU's far plane is float(farPlane): a depth equal to it is the far plane.
  const double farPlane = rule.farPlane;
  auto depth = [&](float d) { return d == float(farPlane) ? farPlane : double(d); };
  Refinement r;
  r.crossings.resize(edges.edges.size());
  for (std::size_t k = 0; k < edges.edges.size(); ++k) {
    const BoundaryEdge& e = edges.edges[k];
    const std::size_t t = map.index(e.i, e.j);
    const std::uint32_t f = flags[t] >> e.axis;
    const bool same = (f & kBoundaryBit) && bool(f & kNearAtPBit) == e.nearAtP && bool(f & kSurfaceBit) == e.surface;
    Crossing& c = r.crossings[k];
    if (!same) {
      const BisectionSegment g = edgeSegment(map, e, rule, blur, blurredSheetDepths);
      c = {0.5, g.nearFallback, g.farDepth};
      ++r.fallbacks;
      continue;
    }
    const glm::vec4 rec = records[std::size_t(e.axis) * texels + t];
    const double along = (e.axis == 0 ? double(rec.x) : double(rec.y)) - (e.axis == 0 ? e.i : e.j);
    c.s = std::clamp(e.nearAtP ? along : 1.0 - along, 0.0, 1.0);
    c.nearDepth = depth(rec.z);
    c.farDepth = depth(rec.w);
  }
  r.centreDepths.resize(centres.size());
  for (std::size_t k = 0; k < centres.size(); ++k) {
    const int i = int(std::floor(centres[k].x)), j = int(std::floor(centres[k].y));
    r.centreDepths[k] = depth(records[2 * texels + map.index(i, j)].x);
  }
  return r;
}

VolumeMesh decodeRefinedGpuVolume(const DepthMap& map, const SheetDepthRule& rule, bool blur,
                                  std::span<const std::uint32_t> indices, std::span<const glm::vec4> records) {
  const std::uint64_t w = std::uint64_t(map.width), texels = w * std::uint64_t(map.height);
  SV_CHECK_EQ(records.size(), 3 * texels);
  SV_CHECK_EQ(indices.size() % 3, 0u);
  const TexelUnprojector unproject(map);
  const double farPlane = rule.farPlane;
  auto depth = [&](float d) { return d == float(farPlane) ? farPlane : double(d); };
  auto place = [&](std::uint64_t id) -> glm::dvec3 {
    if (id < 2 * texels) {
      const std::uint64_t t = id % texels;
      const int i = int(t % w), j = int(t / w);
      return unproject.worldPoint(i, j, id < texels ? sheetDepthOf(map, i, j, rule, blur) : farPlane);
    }
    const std::uint64_t rel = id - 2 * texels, slot = rel / 3, k = rel % 3, t = slot / 2;
    SV_CHECK_LT(t, texels);
    const glm::vec4 r = records[(slot % 2) * texels + t];
    return unproject.worldPoint(r.x, r.y, k == 0 ? depth(r.z) : k == 1 ? depth(r.w) : farPlane);
  };
  std::vector<std::uint32_t> sorted(indices.begin(), indices.end());
  std::sort(sorted.begin(), sorted.end());
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  VolumeMesh mesh;
  mesh.positions.resize(sorted.size());
  for (std::size_t k = 0; k < sorted.size(); ++k) mesh.positions[k] = place(sorted[k]);
  auto number = [&](std::uint32_t id) {
    return std::uint32_t(std::lower_bound(sorted.begin(), sorted.end(), id) - sorted.begin());
  };
  mesh.triangles.resize(indices.size() / 3);
  for (std::size_t k = 0; k < mesh.triangles.size(); ++k)
    mesh.triangles[k] = {number(indices[3 * k]), number(indices[3 * k + 1]), number(indices[3 * k + 2])};
  return mesh;
}

RefinedGpuVolume::RefinedGpuVolume(const ShaderLibrary& shaders)
    : boundary_(Program::compute(shaders, sources("boundary_edges.comp"))),
      unfold_(Program::compute(shaders, sources("boundary_unfold.comp"))),
      list_(Program::compute(shaders, sources("volume_refined.comp"))),
      draw_(shaders, sources("volume_refined.vert"), {"depth_only.frag"}),
      flags_(makeBuffer()),
      counters_(makeBuffer()),
      rounds_(makeBuffer()),
      indices_(makeBuffer()),
      vao_(makeVertexArray()) {
  for (const Program* p : programs()) {
    p->use();
    p->set("rawDepth", 3);
    p->set("crossingRecords", 2);
  }
}

void RefinedGpuVolume::ensureSize(int w, int h) {
  if (w == w_ && h == h_) return;
  SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, flags_.id()));
  SV_GL(glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(std::int64_t(w) * h * 4), nullptr, GL_DYNAMIC_COPY));
  SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0));
  records_ = makeTexture();  // immutable storage: a new texture per size
  SV_GL(glBindTexture(GL_TEXTURE_2D_ARRAY, records_.id()));
  SV_GL(glTexStorage3D(GL_TEXTURE_2D_ARRAY, 1, GL_RGBA32F, w, h, 3));
  SV_GL(glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST));
  SV_GL(glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST));
  SV_GL(glBindTexture(GL_TEXTURE_2D_ARRAY, 0));
  w_ = w, h_ = h;
}

void RefinedGpuVolume::findCrossings(SilhouetteWalk& walk, const WalkInputs& in, const TexelFootprint& footprint,
                                     double hitLimit) {
  ensureSize(in.width, in.height);
  const GLuint gx = GLuint((in.width + kGroup - 1) / kGroup), gy = GLuint((in.height + kGroup - 1) / kGroup);
  const std::array<GLuint, 4> zero{0, 0, 0, 0};
  SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, counters_.id()));
  SV_GL(glBufferData(GL_SHADER_STORAGE_BUFFER, sizeof(zero), zero.data(), GL_DYNAMIC_READ));
  // Round 0 runs in full; each later one only when the round before made an edge continuous.
  std::vector<GLuint> rounds(3 * kMaxUnfoldRounds, 0);
  for (int r = 0; r < kMaxUnfoldRounds; ++r) rounds[3 * r] = r == 0 ? gx : 0, rounds[3 * r + 1] = gy, rounds[3 * r + 2] = 1;
  SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, rounds_.id()));
  SV_GL(glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(rounds.size() * 4), rounds.data(), GL_DYNAMIC_COPY));
  SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, flags_.id()));
  SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 6, counters_.id()));
  SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 7, rounds_.id()));

  boundary_.use();
  boundary_.set("footprint", glm::vec2(float(footprint.a), float(footprint.b)));
  boundary_.set("jumpFootprints", float(kJumpFootprints));
  boundary_.set("jumpSlope", float(kJumpSlope));
  SV_GL(glDispatchCompute(gx, gy, 1));

  unfold_.use();
  unfold_.set("groupsX", int(gx));
  SV_GL(glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, rounds_.id()));
  for (int r = 0; r < kMaxUnfoldRounds; ++r) {
    SV_GL(glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT));
    unfold_.set("nextRound", r + 1 < kMaxUnfoldRounds ? r + 1 : -1);
    for (int phase = 0; phase < 2; ++phase) {
      unfold_.set("phase", phase);
      SV_GL(glDispatchComputeIndirect(GLintptr(12 * r)));
      SV_GL(glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT));
    }
  }
  SV_GL(glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0));

  SV_GL(glBindImageTexture(0, records_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F));
  walk.program().use();
  walk.program().set("rawDepth", 3);
  walk.dispatchGrid(in, hitLimit);  // unbinds SSBOs 0-4 afterwards
  SV_GL(glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F));
  SV_GL(glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT));
  for (GLuint b = 5; b < 8; ++b) SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, b, 0));
  SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0));
}

bool RefinedGpuVolume::list(RefinedGpuCounts& counts) {
  SV_CHECK(w_ > 0 && h_ > 0);
  const std::int64_t quads = std::int64_t(w_ - 1) * (h_ - 1);
  // Vertex indices run to 8 W H (volume_refined.comp), the count to 60 per quad: 32 bits.
  if (std::int64_t(w_) * h_ * 8 > std::int64_t(0xffffffff) || quads * 60 > std::int64_t(0xffffffff)) return false;
  if (indexCapacity_ == 0) {
    SV_GL(glBindVertexArray(vao_.id()));
    SV_GL(glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.id()));
    SV_GL(glBindVertexArray(0));
  }
  auto grow = [&](std::int64_t n) {
    SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, indices_.id()));
    SV_GL(glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(n * 4), nullptr, GL_DYNAMIC_COPY));
    indexCapacity_ = n;
  };
  if (indexCapacity_ == 0) grow(std::min<std::int64_t>(quads * 12, 12 * 65536));
  SV_GL(glActiveTexture(GL_TEXTURE2));
  SV_GL(glBindTexture(GL_TEXTURE_2D_ARRAY, records_.id()));
  SV_GL(glActiveTexture(GL_TEXTURE0));
  const GLuint gx = GLuint((w_ - 1 + kGroup - 1) / kGroup), gy = GLuint((h_ - 1 + kGroup - 1) / kGroup);
  std::array<GLuint, 4> c{};
  for (int attempt = 0; attempt < 2; ++attempt) {
    // Keep the walk's counts ([2], [3]); clear the listing's.
    const GLuint zero[2] = {0, 0};
    SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, counters_.id()));
    SV_GL(glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(zero), zero));
    SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, flags_.id()));
    SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 6, counters_.id()));
    SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 7, indices_.id()));
    list_.use();
    list_.set("capacity", int(std::min<std::int64_t>(indexCapacity_, 0x7fffffff)));
    SV_GL(glDispatchCompute(gx, gy, 1));
    SV_GL(glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_ELEMENT_ARRAY_BARRIER_BIT));
    SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, counters_.id()));
    SV_GL(glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(c), c.data()));
    if (std::int64_t(c[0]) <= indexCapacity_ || std::int64_t(c[0]) * 4 > kMaxIndexBytes) break;
    grow(std::int64_t(c[0]) + std::int64_t(c[0]) / 4);
  }
  for (GLuint b = 5; b < 8; ++b) SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, b, 0));
  SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0));
  SV_GL(glActiveTexture(GL_TEXTURE2));
  SV_GL(glBindTexture(GL_TEXTURE_2D_ARRAY, 0));
  SV_GL(glActiveTexture(GL_TEXTURE0));
  counts = {c[0], c[1], c[2], c[3]};
  const bool fits = std::int64_t(c[0]) <= indexCapacity_;
  indexCount_ = fits ? c[0] : 0;
  return fits;
}

void RefinedGpuVolume::draw(const glm::mat4& lightViewToClip) {
  SV_GL(glActiveTexture(GL_TEXTURE2));
  SV_GL(glBindTexture(GL_TEXTURE_2D_ARRAY, records_.id()));
  SV_GL(glActiveTexture(GL_TEXTURE0));
  draw_.use();
  draw_.set("lightViewToClip", lightViewToClip);
  SV_GL(glBindVertexArray(vao_.id()));
  SV_GL(glDrawElements(GL_TRIANGLES, GLsizei(indexCount_), GL_UNSIGNED_INT, nullptr));
  SV_GL(glBindVertexArray(0));
  SV_GL(glActiveTexture(GL_TEXTURE2));
  SV_GL(glBindTexture(GL_TEXTURE_2D_ARRAY, 0));
  SV_GL(glActiveTexture(GL_TEXTURE0));
}

std::vector<std::uint32_t> RefinedGpuVolume::readFlags() const {
  std::vector<std::uint32_t> out(std::size_t(w_) * std::size_t(h_));
  SV_GL(glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT));
  SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, flags_.id()));
  SV_GL(glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(out.size() * 4), out.data()));
  SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0));
  return out;
}

std::vector<std::uint32_t> RefinedGpuVolume::readIndices() const {
  std::vector<std::uint32_t> out(indexCount_);
  if (out.empty()) return out;
  SV_GL(glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT));
  SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, indices_.id()));
  SV_GL(glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(out.size() * 4), out.data()));
  SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0));
  return out;
}

std::vector<glm::vec4> RefinedGpuVolume::readRecords() const {
  std::vector<glm::vec4> out(std::size_t(w_) * std::size_t(h_) * 3);
  SV_GL(glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT));
  SV_GL(glBindTexture(GL_TEXTURE_2D_ARRAY, records_.id()));
  SV_GL(glPixelStorei(GL_PACK_ALIGNMENT, 4));
  SV_GL(glGetTexImage(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA, GL_FLOAT, out.data()));
  SV_GL(glBindTexture(GL_TEXTURE_2D_ARRAY, 0));
  return out;
}

}  // namespace shadowvol::gl
