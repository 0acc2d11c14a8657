#include "refined_gpu_volume.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "shadowvol/check.h"
#include "shadowvol/gl/gl_error.h"

namespace shadowvol::gl {

namespace {
constexpr int kGroup = 16;  // local size 16 x 16 of boundary_edges.comp, boundary_unfold.comp, walk_slots.comp
constexpr int kCounters = 12;  // walk_slots.comp's layout of the Counters buffer
constexpr GLintptr kWalkDispatch = 4 * 4, kCellDispatch = 7 * 4;  // their byte offsets there

// A depth of a crossing record in double: the GPU's far plane is float(farPlane), so a depth equal
// to it is the far plane itself.
double recordDepth(float d, double farPlane) { return d == float(farPlane) ? farPlane : double(d); }

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
  const double farPlane = rule.farPlane;
  auto depth = [&](float d) { return recordDepth(d, farPlane); };
  Refinement r;
  r.crossings.resize(edges.edges.size());
  for (std::size_t k = 0; k < edges.edges.size(); ++k) {
    const BoundaryEdge& e = edges.edges[k];
    const std::size_t t = map.index(e.i, e.j);
    const std::uint32_t f = flags[t] >> e.axis;
    const bool same = (f & kFlagBoundary) && bool(f & kFlagNearAtP) == e.nearAtP && bool(f & kFlagSurface) == e.surface;
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
  // A centre the GPU walked: a quad its flags give 3 or 4 boundary sides (else the far plane, a
  // fallback: the record was not written this frame).
  auto gpuSides = [&](int i, int j) {
    const std::uint32_t a = flags[map.index(i, j)], b = flags[map.index(i + 1, j)], d = flags[map.index(i, j + 1)];
    return int(a & 1) + int((a >> 1) & 1) + int((b >> 1) & 1) + int(d & 1);
  };
  r.centreDepths.resize(centres.size());
  for (std::size_t k = 0; k < centres.size(); ++k) {
    const int i = int(std::floor(centres[k].x)), j = int(std::floor(centres[k].y));
    if (gpuSides(i, j) < 3) {
      r.centreDepths[k] = farPlane;
      ++r.fallbacks;
      continue;
    }
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
  auto depth = [&](float d) { return recordDepth(d, farPlane); };
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
  mesh.sortTriangles();  // the compute pass lists them in an order that changes from run to run
  return mesh;
}

RefinedGpuVolume::RefinedGpuVolume(const ShaderLibrary& shaders)
    : boundary_(Program::compute(shaders, sources("boundary_edges.comp"))),
      unfold_(Program::compute(shaders, sources("boundary_unfold.comp"))),
      slots_(Program::compute(shaders, sources("walk_slots.comp"))),
      list_(Program::compute(shaders, sources("volume_refined.comp"))),
      draw_(shaders, sources("volume_refined.vert"), {"depth_only.frag"}),
      flags_(makeBuffer()),
      counters_(makeBuffer()),
      rounds_(makeBuffer()),
      walkSlots_(makeBuffer()),
      refinedQuads_(makeBuffer()) {
  for (const Program* p : programs()) {
    p->use();
    p->set("rawDepth", 3);
    p->set("crossingRecords", 2);
  }
}

void RefinedGpuVolume::ensureSize(int w, int h) {
  if (w == w_ && h == h_) return;
  const std::int64_t texels = std::int64_t(w) * h;
  for (auto [buffer, n] : {std::pair{&flags_, texels}, std::pair{&walkSlots_, 3 * texels}, std::pair{&refinedQuads_, texels}}) {
    SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer->id()));
    SV_GL(glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(n * 4), nullptr, GL_DYNAMIC_COPY));
  }
  SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0));
  records_ = makeTexture();  // immutable storage: a new texture per size
  SV_GL(glBindTexture(GL_TEXTURE_2D_ARRAY, records_.id()));
  SV_GL(glTexStorage3D(GL_TEXTURE_2D_ARRAY, 1, GL_RGBA32F, w, h, 3));
  SV_GL(glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST));
  SV_GL(glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST));
  SV_GL(glBindTexture(GL_TEXTURE_2D_ARRAY, 0));
  w_ = w, h_ = h;
}

void RefinedGpuVolume::findCrossings(int width, int height, const TexelFootprint& footprint,
                                     const std::function<void(GLintptr indirectOffset)>& crossings) {
  ensureSize(width, height);
  const GLuint gx = GLuint((width + kGroup - 1) / kGroup), gy = GLuint((height + kGroup - 1) / kGroup);
  const std::array<GLuint, kCounters> zero{};
  SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, counters_.id()));
  SV_GL(glBufferData(GL_SHADER_STORAGE_BUFFER, sizeof(zero), zero.data(), GL_DYNAMIC_READ));
  // The unfolding's dispatches (boundary_unfold.comp): none until a pass gives them work groups.
  std::vector<GLuint> rounds(3 * (kMaxUnfoldRounds + 1), 0);
  for (int r = 0; r <= kMaxUnfoldRounds; ++r) rounds[3 * r + 1] = gy, rounds[3 * r + 2] = 1;
  SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, rounds_.id()));
  SV_GL(glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(rounds.size() * 4), rounds.data(), GL_DYNAMIC_COPY));
  SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, flags_.id()));
  SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 6, counters_.id()));
  SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 7, rounds_.id()));

  boundary_.use();
  boundary_.set("footprint", glm::vec2(float(footprint.a), float(footprint.b)));
  boundary_.set("jumpFootprints", float(kJumpFootprints));
  boundary_.set("jumpSlope", float(kJumpSlope));
  boundary_.set("unfoldRounds", kMaxUnfoldRounds);
  boundary_.set("groupsX", int(gx));
  SV_GL(glDispatchCompute(gx, gy, 1));

  unfold_.use();
  unfold_.set("groupsX", int(gx));
  unfold_.set("roundCount", kMaxUnfoldRounds);
  SV_GL(glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, rounds_.id()));
  unfold_.set("phase", 0);
  for (int r = 0; r <= kMaxUnfoldRounds; ++r) {
    SV_GL(glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT));
    if (r == kMaxUnfoldRounds) unfold_.set("phase", 1);
    else unfold_.set("round", r);
    SV_GL(glDispatchComputeIndirect(GLintptr(12 * r)));
  }
  SV_GL(glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT));

  // The work lists (walk_slots.comp) and the walk over them.
  SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 7, walkSlots_.id()));
  SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, refinedQuads_.id()));
  slots_.use();
  slots_.set("phase", 0);
  SV_GL(glDispatchCompute(gx, gy, 1));
  SV_GL(glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT));
  slots_.set("phase", 1);
  SV_GL(glDispatchCompute(1, 1, 1));
  SV_GL(glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT));
  SV_GL(glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, counters_.id()));
  SV_GL(glBindImageTexture(0, records_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F));
  crossings(kWalkDispatch);  // binds SSBOs 2-4 and unbinds them afterwards
  SV_GL(glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0));
  SV_GL(glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F));
  SV_GL(glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT));
  for (GLuint b = 5; b < 8; ++b) SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, b, 0));
  SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0));
}

void RefinedGpuVolume::dispatchCells(std::int64_t capacity) {
  SV_CHECK(w_ > 0 && h_ > 0);
  SV_GL(glActiveTexture(GL_TEXTURE2));
  SV_GL(glBindTexture(GL_TEXTURE_2D_ARRAY, records_.id()));
  SV_GL(glActiveTexture(GL_TEXTURE0));
  SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, refinedQuads_.id()));
  SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, flags_.id()));
  SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 6, counters_.id()));
  list_.use();
  list_.set("capacity", int(std::min<std::int64_t>(capacity, 0x7fffffff)));
  SV_GL(glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, counters_.id()));
  SV_GL(glDispatchComputeIndirect(kCellDispatch));
  SV_GL(glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0));
  for (GLuint b = 4; b < 7; ++b) SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, b, 0));
}

RefinedGpuCounts RefinedGpuVolume::walkCounts() const {
  std::array<GLuint, 2> c{};
  SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, counters_.id()));
  SV_GL(glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 2 * 4, GLsizeiptr(sizeof(c)), c.data()));
  SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0));
  return {c[0], c[1]};
}

std::vector<std::uint32_t> RefinedGpuVolume::readFlags() const {
  std::vector<std::uint32_t> out(std::size_t(w_) * std::size_t(h_));
  SV_GL(glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT));
  SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, flags_.id()));
  SV_GL(glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(out.size() * 4), out.data()));
  SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0));
  return out;
}

std::vector<glm::vec4> RefinedGpuVolume::readRecords() const {
  std::vector<glm::vec4> out(std::size_t(w_) * std::size_t(h_) * 3);
  SV_GL(glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT));
  SV_GL(glBindTexture(GL_TEXTURE_2D_ARRAY, records_.id()));
  SV_GL(glGetTexImage(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA, GL_FLOAT, out.data()));
  SV_GL(glBindTexture(GL_TEXTURE_2D_ARRAY, 0));
  return out;
}

}  // namespace shadowvol::gl
