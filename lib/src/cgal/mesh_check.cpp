#include "shadowvol/cgal/mesh_check.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>
#include <optional>
#include <sstream>
#include <vector>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Cartesian_converter.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/intersections.h>

#include "shadowvol/check.h"
#include "shadowvol/mesh_io.h"

namespace shadowvol {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using EK = CGAL::Exact_predicates_exact_constructions_kernel;  // exact intersections of reported pairs
using Point = K::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;

Point toPoint(const glm::dvec3& p) {
  return {p.x, p.y, p.z};
}

// Point-in-volume queries by CGAL's ray parity over the faces that are not exactly flat. A flat
// face (collinear corners) holds no area a ray could cross, and CGAL's rays, which try another
// direction whenever one meets a face edge-on, meet a flat face so from every direction and would
// retry without end: `check` hung on a volume far from the origin read back in single precision,
// most of its faces rounded flat (a twelfth probe's finding).
class InsideTest {
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_face_graph_triangle_primitive<Mesh>>>;
  using Side = CGAL::Side_of_triangle_mesh<Mesh, K, CGAL::Default, Tree>;

 public:
  explicit InsideTest(const Mesh& m) {
    std::vector<Mesh::Face_index> faces;
    for (auto f : m.faces()) {
      const auto h = m.halfedge(f);
      if (!CGAL::collinear(m.point(m.source(h)), m.point(m.target(h)), m.point(m.target(m.next(h)))))
        faces.push_back(f);
    }
    if (faces.empty()) return;  // nothing to be inside of
    tree_.insert(faces.begin(), faces.end(), m);
    tree_.build();
    side_.emplace(tree_);
  }
  InsideTest(const InsideTest&) = delete;
  InsideTest& operator=(const InsideTest&) = delete;

  CGAL::Bounded_side operator()(const Point& p) const { return side_ ? (*side_)(p) : CGAL::ON_UNBOUNDED_SIDE; }

 private:
  Tree tree_;
  std::optional<Side> side_;  // refers to tree_
};

// Whether a closed 2-manifold is outward. PMP::is_outward_oriented decides from the faces around
// one extreme vertex, which is ambiguous where a closed volume touches itself at that point (the
// copies of a far vertex of the exact volume, docs/volume.md; a point light's sheet reaching the
// far cube at a cap vertex): it can answer either way there. So this decides from every
// connected component: outward iff each component's signed volume has the sign its nesting
// asks, positive inside an even number of other components (a solid), negative inside an odd
// number (a cavity, such as the inner side of a point light's shell). A component's probe is the
// centroid of one of its kProbes largest faces, the first that lies on no other component's
// surface (components touch along far-plane edges), classified only against components whose
// bounding box holds it; no such probe makes the answer no. Beyond kMaxComponents components
// (the pairwise box tests would cost too much) PMP::is_outward_oriented's answer stands.
bool isOutward(const Mesh& sm) {
  constexpr std::size_t kMaxComponents = 4096, kProbes = 8;
  std::vector<Mesh> parts;
  PMP::split_connected_components(sm, parts);
  if (parts.size() > kMaxComponents) return PMP::is_outward_oriented(sm);
  std::vector<std::vector<Point>> probes(parts.size());
  std::vector<double> volume;
  std::vector<CGAL::Bbox_3> box;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const Mesh& m = parts[k];
    std::vector<std::pair<double, Point>> faces;
    CGAL::Bbox_3 b;
    for (auto f : m.faces()) {
      auto h = m.halfedge(f);
      const Point &p = m.point(m.source(h)), &q = m.point(m.target(h)), &r = m.point(m.target(m.next(h)));
      faces.push_back({CGAL::to_double(CGAL::squared_area(p, q, r)), CGAL::centroid(p, q, r)});
      b += p.bbox() + q.bbox() + r.bbox();
    }
    const std::size_t count = std::min(kProbes, faces.size());
    std::partial_sort(faces.begin(), faces.begin() + std::ptrdiff_t(count), faces.end(),
                      [](const auto& x, const auto& y) { return x.first > y.first; });
    for (std::size_t c = 0; c < count; ++c) probes[k].push_back(faces[c].second);
    volume.push_back(CGAL::to_double(PMP::volume(m)));
    box.push_back(b);
  }
  std::vector<std::unique_ptr<InsideTest>> side(parts.size());
  std::vector<int> depth(parts.size(), 0);
  for (std::size_t a = 0; a < parts.size(); ++a) {
    bool decided = false;
    for (const Point& p : probes[a]) {
      int inside = 0;
      bool onSurface = false;
      for (std::size_t b = 0; b < parts.size() && !onSurface; ++b) {
        if (b == a || !CGAL::do_overlap(box[b], p.bbox())) continue;
        if (!side[b]) side[b] = std::make_unique<InsideTest>(parts[b]);
        const CGAL::Bounded_side s = (*side[b])(p);
        onSurface = s == CGAL::ON_BOUNDARY;
        inside += s == CGAL::ON_BOUNDED_SIDE;
      }
      if (onSurface) continue;
      depth[a] = inside;
      decided = true;
      break;
    }
    if (!decided) return false;
  }
  for (std::size_t a = 0; a < parts.size(); ++a)
    if (depth[a] % 2 == 0 ? !(volume[a] > 0.0) : !(volume[a] < 0.0)) return false;
  return true;
}

// Builds a Surface_mesh; returns false if CGAL refuses a face (non-manifold input).
bool buildSurfaceMesh(const VolumeMesh& in, Mesh& out) {
  std::vector<Mesh::Vertex_index> v;
  v.reserve(in.positions.size());
  for (const auto& p : in.positions) v.push_back(out.add_vertex(toPoint(p)));
  for (const auto& t : in.triangles)
    if (out.add_face(v[t[0]], v[t[1]], v[t[2]]) == Mesh::null_face()) return false;
  return true;
}

}  // namespace

bool MeshCheckReport::valid() const {
  const bool noSelfIntersection = !selfIntersectingPairs || *selfIntersectingPairs == 0;
  if (triangles == 0) return nonFiniteVertices == 0 && isolatedVertices == 0;
  return closedManifold() && outward && volume > 0.0 && nonFiniteVertices == 0 && degenerateTriangles == 0 &&
         isolatedVertices == 0 && noSelfIntersection;
}

std::string MeshCheckReport::summary() const {
  std::ostringstream s;
  s << vertices << " vertices, " << triangles << " triangles; non-finite " << nonFiniteVertices << ", bad index "
    << badIndexTriangles << ", degenerate " << degenerateTriangles << ", boundary edges " << boundaryEdges
    << ", overused edges " << overusedEdges << ", non-manifold vertices " << nonManifoldVertices << ", isolated "
    << isolatedVertices << ", coincident " << coincidentVertices;
  if (triangles == 0)
    s << "; empty (no triangles: nothing in shadow, nothing to orient)";  // valid(): an empty volume is one
  else
    s << "; outward " << (outward ? "yes" : "no") << ", volume " << volume;
  s << "; self-intersecting pairs ";
  if (selfIntersectingPairs)
    s << *selfIntersectingPairs << " (allowed touching " << allowedTouchingPairs << ")";
  else
    s << "not checked";
  return s.str();
}

namespace {

// One corner of a triangle (v, a, b): the link of v gets the edge a -> b.
struct Corner {
  std::uint32_t v, a, b;
};

// Index sanity and degenerate faces into `r`; the directed edges (from << 32 | to) and the
// corners of the sound triangles.
void checkTriangles(const VolumeMesh& mesh, MeshCheckReport& r, std::vector<std::uint64_t>& directed,
                    std::vector<Corner>& corners) {
  const std::size_t nv = mesh.positions.size();
  std::vector<bool> used(nv, false);
  directed.reserve(mesh.triangles.size() * 3);
  corners.reserve(mesh.triangles.size() * 3);
  for (const auto& t : mesh.triangles) {
    if (t[0] >= nv || t[1] >= nv || t[2] >= nv || t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
      ++r.badIndexTriangles;
      continue;
    }
    for (int k = 0; k < 3; ++k) {
      used[t[k]] = true;
      directed.push_back((std::uint64_t(t[k]) << 32) | t[(k + 1) % 3]);
      corners.push_back({t[k], t[(k + 1) % 3], t[(k + 2) % 3]});
    }
    if (r.nonFiniteVertices == 0 &&
        CGAL::collinear(toPoint(mesh.positions[t[0]]), toPoint(mesh.positions[t[1]]), toPoint(mesh.positions[t[2]])))
      ++r.degenerateTriangles;
  }
  r.isolatedVertices = std::size_t(std::count(used.begin(), used.end(), false));
}

// Directed edges: each once, its opposite present.
void checkEdges(std::vector<std::uint64_t>& directed, MeshCheckReport& r) {
  std::sort(directed.begin(), directed.end());
  for (std::size_t k = 0; k < directed.size(); ++k) {
    if (k > 0 && directed[k] == directed[k - 1]) {
      ++r.overusedEdges;
      continue;
    }
    const std::uint64_t opposite = (directed[k] << 32) | (directed[k] >> 32);
    if (!std::binary_search(directed.begin(), directed.end(), opposite)) ++r.boundaryEdges;
  }
}

// Whether the link edges a -> b of one vertex's corners [s, e) (sorted by a) form one fan: one
// cycle, or at a boundary one open path (its missing edges are counted as boundary edges already,
// so a manifold surface with a boundary has no non-manifold vertex; with no boundary edge only a
// cycle is possible). Two fans meeting at the vertex, or an edge used twice, are not one.
// `ends` is scratch space.
bool oneFan(const std::vector<Corner>& corners, std::size_t s, std::size_t e, std::vector<std::uint32_t>& ends) {
  for (std::size_t k = s + 1; k < e; ++k)
    if (corners[k].a == corners[k - 1].a) return false;  // one edge out of each a
  auto from = [&](std::uint32_t a) {
    auto it = std::lower_bound(corners.begin() + std::ptrdiff_t(s), corners.begin() + std::ptrdiff_t(e), a,
                               [](const Corner& c, std::uint32_t x) { return c.a < x; });
    return (it != corners.begin() + std::ptrdiff_t(e) && it->a == a) ? &*it : nullptr;
  };
  ends.clear();  // the b's: an a that is none of them starts an open path
  for (std::size_t k = s; k < e; ++k) ends.push_back(corners[k].b);
  std::sort(ends.begin(), ends.end());
  if (std::adjacent_find(ends.begin(), ends.end()) != ends.end()) return false;  // one edge into each b
  std::optional<std::uint32_t> start;
  for (std::size_t k = s; k < e; ++k)
    if (!std::binary_search(ends.begin(), ends.end(), corners[k].a)) {
      if (start) return false;  // two open paths
      start = corners[k].a;
    }
  const std::uint32_t first = start ? *start : corners[s].a;
  std::size_t steps = 0;
  std::uint32_t at = first;
  for (const Corner* c = from(at); c && steps <= e - s; c = from(at)) {
    at = c->b;
    ++steps;
    if (at == first) break;
  }
  return steps == e - s;  // the walk from `first` met every link edge: one path or one cycle
}

// Vertex fans: the vertices whose link is not one fan (oneFan).
void checkFans(std::vector<Corner>& corners, MeshCheckReport& r) {
  std::sort(corners.begin(), corners.end(),
            [](const Corner& x, const Corner& y) { return x.v != y.v ? x.v < y.v : x.a < y.a; });
  std::vector<std::uint32_t> ends;
  for (std::size_t s = 0; s < corners.size();) {
    std::size_t e = s;
    while (e < corners.size() && corners[e].v == corners[s].v) ++e;
    if (!oneFan(corners, s, e, ends)) ++r.nonManifoldVertices;
    s = e;
  }
}


// Whether the exact intersection of two triangles lies wholly where touching is allowed. It is
// constructed exactly (touching triangles meet in exactly one point or segment, which inexact
// constructions may miss), then tested point by point.
bool touchAllowed(const K::Triangle_3& a, const K::Triangle_3& b, const MeshCheckOptions& options) {
  const CGAL::Cartesian_converter<K, EK> toExact;
  const auto x = CGAL::intersection(toExact(a), toExact(b));
  if (!x) return false;
  std::vector<EK::Point_3> pts;
  if (const auto* p = boost::get<EK::Point_3>(&*x))
    pts = {*p};
  else if (const auto* s = boost::get<EK::Segment_3>(&*x))
    pts = {s->source(), s->target()};
  else if (const auto* t = boost::get<EK::Triangle_3>(&*x))
    pts = {t->vertex(0), t->vertex(1), t->vertex(2)};
  else if (const auto* v = boost::get<std::vector<EK::Point_3>>(&*x))
    pts = *v;
  return !pts.empty() && std::all_of(pts.begin(), pts.end(), [&](const EK::Point_3& p) {
    return options.allowedTouch({CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
  });
}

// CGAL's self-intersecting face pairs, those that only touch where allowed counted apart.
void checkSelfIntersections(const Mesh& sm, const MeshCheckOptions& options, MeshCheckReport& r) {
  std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> pairs;
  PMP::self_intersections(sm, std::back_inserter(pairs));
  auto triangleOf = [&](Mesh::Face_index f) {
    auto h = sm.halfedge(f);
    return K::Triangle_3(sm.point(sm.source(h)), sm.point(sm.target(h)), sm.point(sm.target(sm.next(h))));
  };
  std::size_t counted = 0;
  for (const auto& [f, g] : pairs) {
    if (options.allowedTouch && touchAllowed(triangleOf(f), triangleOf(g), options))
      ++r.allowedTouchingPairs;
    else
      ++counted;
  }
  r.selfIntersectingPairs = counted;
}

}  // namespace

MeshCheckReport sumReports(const std::vector<MeshCheckReport>& reports) {
  MeshCheckReport r;
  r.outward = true;
  bool selfChecked = true;
  std::size_t selfPairs = 0;
  for (const MeshCheckReport& m : reports) {
    r.vertices += m.vertices;
    r.triangles += m.triangles;
    r.nonFiniteVertices += m.nonFiniteVertices;
    r.badIndexTriangles += m.badIndexTriangles;
    r.degenerateTriangles += m.degenerateTriangles;
    r.boundaryEdges += m.boundaryEdges;
    r.overusedEdges += m.overusedEdges;
    r.nonManifoldVertices += m.nonManifoldVertices;
    r.isolatedVertices += m.isolatedVertices;
    r.coincidentVertices += m.coincidentVertices;
    if (m.triangles > 0) r.outward = r.outward && m.outward;  // an empty mesh is valid, not outward
    r.volume += m.volume;
    selfChecked = selfChecked && m.selfIntersectingPairs.has_value();
    selfPairs += m.selfIntersectingPairs.value_or(0);
    r.allowedTouchingPairs += m.allowedTouchingPairs;
  }
  if (selfChecked) r.selfIntersectingPairs = selfPairs;
  r.outward = r.outward && r.triangles > 0;
  return r;
}

namespace {

// Whether every connected component has a positive signed volume: the outward rule of a union of
// solids that may overlap (a volume's parts after the first, VolumeMesh::partStarts), where one
// component's probe may lie inside another without being a cavity.
bool everyComponentOutward(const Mesh& sm) {
  std::vector<Mesh> parts;
  PMP::split_connected_components(sm, parts);
  for (const Mesh& m : parts)
    if (!(CGAL::to_double(PMP::volume(m)) > 0.0)) return false;
  return true;
}

MeshCheckReport checkPart(const VolumeMesh& mesh, const MeshCheckOptions& options, bool overlapping);

}  // namespace

MeshCheckReport checkMesh(const VolumeMesh& mesh, const MeshCheckOptions& options) {
  if (mesh.partCount() > 1) {
    std::vector<MeshCheckReport> parts;
    for (std::size_t k = 0; k < mesh.partCount(); ++k) parts.push_back(checkPart(mesh.partMesh(k), options, k > 0));
    MeshCheckReport r = sumReports(parts);
    // Self-intersections are the first part's: the later ones overlap themselves by design.
    r.selfIntersectingPairs = parts[0].selfIntersectingPairs;
    r.allowedTouchingPairs = parts[0].allowedTouchingPairs;
    // Vertices no part uses are still isolated: count the whole mesh's (a part's are renumbered).
    r.vertices = mesh.positions.size();
    std::vector<std::uint8_t> used(mesh.positions.size(), 0);
    for (const auto& t : mesh.triangles)
      for (const std::uint32_t v : t)
        if (v < used.size()) used[v] = 1;
    r.isolatedVertices += std::size_t(std::count(used.begin(), used.end(), std::uint8_t(0)));
    return r;
  }
  return checkPart(mesh, options, false);
}

namespace {

MeshCheckReport checkPart(const VolumeMesh& mesh, const MeshCheckOptions& options, bool overlapping) {
  MeshCheckReport r;
  r.vertices = mesh.positions.size();
  r.triangles = mesh.triangles.size();
  for (const auto& p : mesh.positions)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) ++r.nonFiniteVertices;
  std::vector<std::uint64_t> directed;
  std::vector<Corner> corners;
  checkTriangles(mesh, r, directed, corners);
  checkEdges(directed, r);
  checkFans(corners, r);
  r.coincidentVertices = coincidentVertices(mesh);

  if (!r.closedManifold() || r.nonFiniteVertices > 0 || mesh.triangles.empty()) return r;
  Mesh sm;
  if (!buildSurfaceMesh(mesh, sm)) {
    ++r.nonManifoldVertices;  // CGAL refused a face our checks accepted; report it as non-manifold
    return r;
  }
  r.outward = overlapping ? everyComponentOutward(sm) : isOutward(sm);
  r.volume = CGAL::to_double(PMP::volume(sm));
  if (options.selfIntersections && !overlapping && r.degenerateTriangles == 0) checkSelfIntersections(sm, options, r);
  return r;
}

}  // namespace

struct VolumeClassifier::Impl {
  std::vector<Mesh> meshes;  // one per part
  std::vector<std::unique_ptr<InsideTest>> sides;
};

VolumeClassifier::VolumeClassifier(const VolumeMesh& mesh) : impl_(std::make_unique<Impl>()) {
  impl_->meshes.resize(mesh.partCount());
  for (std::size_t k = 0; k < mesh.partCount(); ++k) {
    const bool ok = mesh.partCount() == 1 ? buildSurfaceMesh(mesh, impl_->meshes[k])
                                          : buildSurfaceMesh(mesh.partMesh(k), impl_->meshes[k]);
    SV_CHECK(ok);
  }
  for (const Mesh& m : impl_->meshes) impl_->sides.push_back(std::make_unique<InsideTest>(m));
}
VolumeClassifier::~VolumeClassifier() = default;
VolumeClassifier::VolumeClassifier(VolumeClassifier&&) noexcept = default;
VolumeClassifier& VolumeClassifier::operator=(VolumeClassifier&&) noexcept = default;

VolumeClassifier::Side VolumeClassifier::classify(const glm::dvec3& point) const {
  Side side = Side::Outside;
  for (const auto& test : impl_->sides) switch ((*test)(toPoint(point))) {
      case CGAL::ON_BOUNDED_SIDE:
        return Side::Inside;
      case CGAL::ON_BOUNDARY:
        side = Side::Boundary;
        break;
      default:
        break;
    }
  return side;
}

}  // namespace shadowvol
