#include "shadowvol/silhouette_volume.h"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <sstream>
#include <unordered_map>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include "shadowvol/check.h"
#include "shadowvol/cube_map.h"
#include "shadowvol/error.h"

namespace shadowvol {
namespace {

using OMesh = OpenMesh::TriMesh_ArrayKernelT<>;
using Tri = std::array<std::uint32_t, 3>;

std::string describe(const glm::dvec3& p) {
  std::ostringstream s;
  s.precision(9);
  s << "(" << p.x << ", " << p.y << ", " << p.z << ")";
  return s.str();
}

/// The mesh as stored: its own vertices, triangles with a repeated vertex dropped.
void asStored(const TriangleMesh& in, std::vector<glm::dvec3>& positions, std::vector<Tri>& triangles) {
  for (const auto& p : in.positions) positions.emplace_back(p);
  for (const auto& t : in.triangles)
    if (t[0] != t[1] && t[1] != t[2] && t[2] != t[0]) triangles.push_back(t);
}

/// Welds vertices with exactly equal positions (sort order, deterministic) and drops triangles
/// with a repeated vertex (zero area; their edges cancel, so dropping keeps closedness).
void weld(const TriangleMesh& in, std::vector<glm::dvec3>& positions, std::vector<Tri>& triangles) {
  std::vector<std::uint32_t> order(in.positions.size());
  std::iota(order.begin(), order.end(), 0u);
  auto less = [&](std::uint32_t a, std::uint32_t b) {
    const glm::vec3 &p = in.positions[a], &q = in.positions[b];
    if (p.x != q.x) return p.x < q.x;
    if (p.y != q.y) return p.y < q.y;
    if (p.z != q.z) return p.z < q.z;
    return a < b;
  };
  std::sort(order.begin(), order.end(), less);
  std::vector<std::uint32_t> remap(in.positions.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    if (k == 0 || in.positions[order[k]] != in.positions[order[k - 1]]) positions.emplace_back(in.positions[order[k]]);
    remap[order[k]] = std::uint32_t(positions.size() - 1);
  }
  for (const auto& t : in.triangles) {
    const Tri w{remap[t[0]], remap[t[1]], remap[t[2]]};
    if (w[0] != w[1] && w[1] != w[2] && w[2] != w[0]) triangles.push_back(w);
  }
}

struct Object {
  SilhouetteObjectInfo info;
  std::string pointer;                // "/objects/K": where the scene file holds it
  OMesh mesh;                         // casters only: the welded mesh with half-edge connectivity
  std::vector<glm::dvec3> positions;  // welded, double (= OpenMesh vertex idx)
  std::vector<Tri> triangles;         // = OpenMesh face idx
};

/// Light-facing flags per triangle (see silhouetteEdges in the header).
std::vector<char> facing(const Object& o, const Light& light) {
  std::vector<char> f(o.triangles.size());
  const glm::dvec3 dir = glm::normalize(light.direction);
  for (std::size_t k = 0; k < o.triangles.size(); ++k) {
    const auto& t = o.triangles[k];
    const glm::dvec3 &p0 = o.positions[t[0]], &p1 = o.positions[t[1]], &p2 = o.positions[t[2]];
    const glm::dvec3 n = glm::cross(p1 - p0, p2 - p0);
    const glm::dvec3 toLight = light.type != LightType::Directional ? light.position - p0 : -dir;
    f[k] = glm::dot(n, toLight) > 0.0;
  }
  return f;
}

}  // namespace

struct SilhouetteOccluders::Impl {
  std::string source;
  std::vector<Object> objects;
  std::vector<SilhouetteObjectInfo> infos;
};

namespace {

/// Classifies o (its positions and triangles set) by the rule of the header and, for a caster,
/// builds its half-edge connectivity. Returns why it is neither a closed 2-manifold nor an open
/// sheet, or an empty string.
std::string classify(Object& o) {
  o.info.vertices = o.positions.size();
  o.info.triangles = o.triangles.size();
  o.info.boundaryEdges = 0;
  // Edge check: per undirected edge the number of triangles using it in each direction.
  struct Uses {
    std::uint32_t forward = 0, backward = 0;  // forward: from the smaller to the larger index
  };
  std::unordered_map<std::uint64_t, Uses> edges;
  edges.reserve(o.triangles.size() * 2);
  for (const auto& t : o.triangles)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = t[k], b = t[(k + 1) % 3];
      Uses& u = edges[(std::uint64_t(std::min(a, b)) << 32) | std::max(a, b)];
      (a < b ? u.forward : u.backward) += 1;
    }
  // The first offending edge in index order (deterministic).
  std::vector<std::pair<std::uint64_t, Uses>> sorted(edges.begin(), edges.end());
  std::sort(sorted.begin(), sorted.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  for (const auto& [key, u] : sorted) {
    auto edge = [&, key = key] {
      return "the edge " + describe(o.positions[key >> 32]) + " - " + describe(o.positions[key & 0xffffffffu]);
    };
    if (u.forward + u.backward > 2)
      return edge() + " has " + std::to_string(u.forward + u.backward) + " triangles (non-manifold edge)";
    if (u.forward > 1 || u.backward > 1) return edge() + " is used twice in the same direction (inconsistently oriented triangles)";
    if (u.forward + u.backward == 1) ++o.info.boundaryEdges;
  }
  // Half-edge connectivity; OpenMesh refuses a face at a non-manifold vertex (two fans touching).
  o.mesh = OMesh();
  for (const auto& p : o.positions) o.mesh.add_vertex(OMesh::Point(float(p.x), float(p.y), float(p.z)));
  OpenMesh::mostream& err = omerr();
  const bool wasEnabled = err.is_enabled();
  err.disable();  // the failure is reported by the caller, naming the object
  std::string why;
  for (const auto& t : o.triangles) {
    const auto f =
        o.mesh.add_face(OMesh::VertexHandle(int(t[0])), OMesh::VertexHandle(int(t[1])), OMesh::VertexHandle(int(t[2])));
    if (!f.is_valid()) {
      why = "a triangle at the vertex " + describe(o.positions[t[0]]) + ", " + describe(o.positions[t[1]]) + " or " +
            describe(o.positions[t[2]]) + " makes it non-manifold (two fans touching at a vertex)";
      break;
    }
  }
  if (wasEnabled) err.enable();
  if (!why.empty()) return why;
  SV_CHECK_EQ(o.mesh.n_faces(), o.triangles.size());
  o.info.role = o.info.boundaryEdges == 0 && !o.triangles.empty() ? SilhouetteRole::Caster : SilhouetteRole::ReceiverOnly;
  if (o.info.role == SilhouetteRole::ReceiverOnly) o.mesh = OMesh();  // connectivity not needed
  return {};
}

}  // namespace

SilhouetteOccluders::SilhouetteOccluders(const Scene& scene) : impl_(std::make_unique<Impl>()) {
  impl_->source = scene.source;
  for (std::size_t k = 0; k < scene.objects.size(); ++k) {
    const SceneObject& so = scene.objects[k];
    // Closedness is decided on the mesh's own topology first (two vertices of a closed mesh may
    // share a position); only a mesh that is not closed as stored is welded by position (an STL
    // or soup stores every triangle's corners apart) and classified again.
    Object stored, welded;
    stored.info.name = welded.info.name = so.name;
    stored.pointer = welded.pointer = "/objects/" + std::to_string(k);
    asStored(so.mesh, stored.positions, stored.triangles);
    const std::string storedWhy = classify(stored);
    Object* chosen = nullptr;
    std::string why;
    if (storedWhy.empty() && stored.info.role == SilhouetteRole::Caster) {
      chosen = &stored;
    } else {
      weld(so.mesh, welded.positions, welded.triangles);
      why = classify(welded);
      if (why.empty()) chosen = &welded;
      else if (storedWhy.empty()) chosen = &stored;  // an open sheet as stored
    }
    if (!chosen)
      throw InputError(scene.source, stored.pointer, "",
                       "object '" + so.name + "' is neither a closed 2-manifold (a shadow caster) nor an open sheet " +
                           "(a receiver only), so silhouette shadow volumes cannot use it: " + why);
    impl_->infos.push_back(chosen->info);
    impl_->objects.push_back(std::move(*chosen));
  }
}

SilhouetteOccluders::~SilhouetteOccluders() = default;
SilhouetteOccluders::SilhouetteOccluders(SilhouetteOccluders&&) noexcept = default;
SilhouetteOccluders& SilhouetteOccluders::operator=(SilhouetteOccluders&&) noexcept = default;

const std::string& SilhouetteOccluders::source() const {
  return impl_->source;
}

const std::vector<SilhouetteObjectInfo>& SilhouetteOccluders::objects() const {
  return impl_->infos;
}

std::vector<std::string> SilhouetteOccluders::receiversOnly() const {
  std::vector<std::string> names;
  for (const auto& i : impl_->infos)
    if (i.role == SilhouetteRole::ReceiverOnly) names.push_back(i.name);
  return names;
}

namespace {

/// Calls emit(frontHalfedge) for every silhouette edge: the half-edge of the edge whose face
/// faces the light (so from -> to is the edge as it runs in that triangle).
template <typename Emit>
void forEachSilhouetteEdge(const Object& o, const std::vector<char>& front, Emit emit) {
  const OMesh& m = o.mesh;
  for (const auto e : m.edges()) {
    const auto h0 = m.halfedge_handle(e, 0), h1 = m.halfedge_handle(e, 1);
    const auto f0 = m.face_handle(h0), f1 = m.face_handle(h1);
    SV_CHECK(f0.is_valid() && f1.is_valid());  // casters are closed
    const bool a = front[std::size_t(f0.idx())], b = front[std::size_t(f1.idx())];
    if (a != b) emit(a ? h0 : h1);
  }
}

}  // namespace

std::vector<std::array<glm::dvec3, 2>> SilhouetteOccluders::silhouetteEdges(std::size_t object,
                                                                            const Light& light) const {
  SV_CHECK_LT(object, impl_->objects.size());
  const Object& o = impl_->objects[object];
  std::vector<std::array<glm::dvec3, 2>> out;
  if (o.info.role != SilhouetteRole::Caster) return out;
  forEachSilhouetteEdge(o, facing(o, light), [&](OMesh::HalfedgeHandle h) {
    out.push_back({o.positions[std::size_t(o.mesh.from_vertex_handle(h).idx())],
                   o.positions[std::size_t(o.mesh.to_vertex_handle(h).idx())]});
  });
  return out;
}

SilhouetteVolume buildSilhouetteVolume(const SilhouetteOccluders& occluders, const Light& light) {
  const auto& impl = *occluders.impl_;
  SilhouetteVolume out;
  out.receiversOnly = occluders.receiversOnly();
  const glm::dmat4 view = lightView(light);
  const bool point = light.type == LightType::Point;
  // Depth along the light's axis; a point light's along the axis of the cube face that sees p
  // (cube_map.h), so its far plane is the far cube.
  auto depthOf = [&](const glm::dvec3& p) {
    return point ? cubeDepth(p - light.position) : -(view * glm::dvec4(p, 1.0)).z;
  };
  const bool spot = light.type == LightType::Spot;

  // Which casters take part, and the extrusion depth.
  std::vector<const Object*> casters;
  double deepest = -1e300;
  for (const auto& o : impl.objects) {
    if (o.info.role != SilhouetteRole::Caster) continue;
    double lo = 1e300, hi = -1e300;
    for (const auto& p : o.positions) {
      const double d = depthOf(p);
      lo = std::min(lo, d);
      hi = std::max(hi, d);
    }
    if (spot && hi <= 0.0) {
      out.skipped.push_back(o.info.name);
      continue;
    }
    if (spot && lo <= 0.0)
      throw InputError(impl.source, o.pointer, "",
                       "object '" + o.info.name +
                           "' reaches behind the spot light (light-view depth <= 0 at some vertex); silhouette "
                           "shadow volumes need each casting object entirely in front of the light");
    if (point && lo < light.nearPlane)
      throw InputError(impl.source, o.pointer, "",
                       "object '" + o.info.name +
                           "' reaches into the point light's near cube (a vertex closer than its near plane along "
                           "every axis): silhouette shadow volumes need each casting object clear of the light");
    deepest = std::max(deepest, hi);
    casters.push_back(&o);
  }
  out.extrusionDepth = light.farPlane;
  if (deepest >= light.farPlane) out.extrusionDepth = deepest * 1.001;
  // A point light's far cap is flat per caster triangle, a chord between points of the far cube
  // that may lie on different faces: nearer the light than the cube by up to a factor of sqrt(3)
  // times the cosine of half the angle the triangle subtends. Eight times the depth keeps it
  // beyond every receiver for triangles subtending up to 90 degrees.
  if (point) out.extrusionDepth *= kPointLightExtrusion;
  const double D = out.extrusionDepth;
  const glm::dvec3 dir = glm::normalize(light.direction);
  auto extrude = [&](const glm::dvec3& p) {
    const double d = depthOf(p);
    return spot || point ? light.position + (p - light.position) * (D / d) : p + dir * (D - d);
  };

  VolumeMesh& mesh = out.mesh;
  for (const Object* op : casters) {
    const Object& o = *op;
    const std::vector<char> front = facing(o, light);
    std::vector<std::uint32_t> nearIndex(o.positions.size(), UINT32_MAX), farIndex(o.positions.size(), UINT32_MAX);
    auto nearVertex = [&](std::uint32_t v) {
      if (nearIndex[v] == UINT32_MAX) {
        nearIndex[v] = std::uint32_t(mesh.positions.size());
        mesh.positions.push_back(o.positions[v]);
      }
      return nearIndex[v];
    };
    auto farVertex = [&](std::uint32_t v) {
      if (farIndex[v] == UINT32_MAX) {
        farIndex[v] = std::uint32_t(mesh.positions.size());
        mesh.positions.push_back(extrude(o.positions[v]));
      }
      return farIndex[v];
    };
    for (std::size_t k = 0; k < o.triangles.size(); ++k) {
      const Tri& t = o.triangles[k];
      if (front[k]) {  // light cap: the object's own triangle, same winding (outward = toward the light)
        mesh.triangles.push_back({nearVertex(t[0]), nearVertex(t[1]), nearVertex(t[2])});
        ++out.lightCapTriangles;
      } else {  // dark cap: projected, same winding (outward = away from the light)
        mesh.triangles.push_back({farVertex(t[0]), farVertex(t[1]), farVertex(t[2])});
        ++out.darkCapTriangles;
      }
    }
    forEachSilhouetteEdge(o, front, [&](OMesh::HalfedgeHandle h) {
      // a -> b runs in the lit triangle; the wall uses b -> a near and a' -> b' far.
      const auto a = std::uint32_t(o.mesh.from_vertex_handle(h).idx()),
                 b = std::uint32_t(o.mesh.to_vertex_handle(h).idx());
      const std::uint32_t na = nearVertex(a), nb = nearVertex(b), fa = farVertex(a), fb = farVertex(b);
      mesh.triangles.push_back({nb, na, fa});
      mesh.triangles.push_back({nb, fa, fb});
      ++out.silhouetteEdges;
    });
  }
  return out;
}

SilhouetteVolume buildSilhouetteVolume(const Scene& scene) {
  return buildSilhouetteVolume(SilhouetteOccluders(scene), scene.light);
}

}  // namespace shadowvol
