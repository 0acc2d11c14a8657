#include "shadowvol/scene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <optional>
#include <numbers>
#include <set>
#include <sstream>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "shadowvol/camera.h"
#include "shadowvol/error.h"
#include "shadowvol/eye_plane_split.h"
#include "shadowvol/mesh_io.h"
#include "shadowvol/mesh_orientation.h"
#include "shadowvol/primitives.h"
#include "shadowvol/ray_parity.h"
#include "shadowvol/triangle_adjacency.h"
#include "clip_volume.h"
#include "json_text.h"
#include "scene_fit_range.h"

namespace shadowvol {
namespace {

using nlohmann::json;

constexpr int kMaxImageSide = 16384;
constexpr double kMaxMagnitude = kMaxSceneMagnitude;  // scene.h
constexpr const char* kMagnitudeProblem = "beyond the supported range (|value| <= 1e12)";
// Fields of view in degrees: at least this, below 179.
constexpr double kMinFovDegrees = 0.01;

std::string show(const json& v) {
  std::string s = v.dump();
  if (s.size() > 80) s = s.substr(0, 77) + "...";
  return s;
}

/// A JSON object being read: every key must be consumed, so unknown fields are errors.
class ObjectReader {
 public:
  ObjectReader(const json& obj, std::string pointer, const std::string& source)
      : obj_(obj), pointer_(std::move(pointer)), source_(source) {
    if (!obj_.is_object()) fail("", obj_, "expected a JSON object");
  }

  bool has(const std::string& key) const { return obj_.contains(key); }
  std::string pointer(const std::string& key) const { return pointer_ + "/" + key; }
  const std::string& source() const { return source_; }

  [[noreturn]] void fail(const std::string& key, const json& value, const std::string& problem) const {
    throw InputError(source_, key.empty() ? (pointer_.empty() ? "/" : pointer_) : pointer(key), show(value),
                     problem);
  }

  const json& raw(const std::string& key) {
    used_.insert(key);
    return obj_.at(key);
  }

  double number(const std::string& key, std::optional<double> fallback = std::nullopt) {
    if (!has(key)) {
      if (!fallback) fail(key, json(), "required field is missing");
      return *fallback;
    }
    const json& v = raw(key);
    if (!v.is_number()) fail(key, v, "expected a number");
    const double d = v.get<double>();
    if (!std::isfinite(d)) fail(key, v, "expected a finite number");
    if (std::abs(d) > kMaxMagnitude) fail(key, v, kMagnitudeProblem);
    return d;
  }

  double positive(const std::string& key, std::optional<double> fallback = std::nullopt) {
    const double d = number(key, fallback);
    if (!(d > 0.0)) fail(key, json(d), "must be greater than zero");
    return d;
  }

  int integer(const std::string& key, int fallback, int lo, int hi) {
    if (!has(key)) return fallback;
    const json& v = raw(key);
    // A whole number past 64 bits arrives as a float (99999999999999999999999999): out of range.
    if (v.is_number_float() && std::abs(v.get<double>()) >= 9.2e18 && std::isfinite(v.get<double>()))
      fail(key, v, "must be between " + std::to_string(lo) + " and " + std::to_string(hi));
    if (!v.is_number_integer()) fail(key, v, "expected a whole number");
    const auto i = v.get<long long>();
    if (i < lo || i > hi)
      fail(key, v, "must be between " + std::to_string(lo) + " and " + std::to_string(hi));
    return int(i);
  }

  std::string string(const std::string& key, std::optional<std::string> fallback = std::nullopt) {
    if (!has(key)) {
      if (!fallback) fail(key, json(), "required field is missing");
      return *fallback;
    }
    const json& v = raw(key);
    if (!v.is_string()) fail(key, v, "expected a string");
    if (v.get_ref<const std::string&>().find('\0') != std::string::npos)  // a file name would end there
      fail(key, v, "a NUL character (\\u0000) is not allowed in a string");
    return v.get<std::string>();
  }

  glm::dvec3 vec3(const std::string& key, std::optional<glm::dvec3> fallback = std::nullopt) {
    if (!has(key)) {
      if (!fallback) fail(key, json(), "required field is missing");
      return *fallback;
    }
    const json& v = raw(key);
    if (!v.is_array() || v.size() != 3) fail(key, v, "expected an array of 3 numbers");
    glm::dvec3 r;
    for (int k = 0; k < 3; ++k) {
      if (!v[k].is_number() || !std::isfinite(v[k].get<double>())) fail(key, v, "expected 3 finite numbers");
      r[k] = v[k].get<double>();
      if (std::abs(r[k]) > kMaxMagnitude) fail(key, v, kMagnitudeProblem);
    }
    return r;
  }

  /// A number (all axes equal) or an array of n positive numbers; with `mirrors`, negative ones
  /// too (a scale that mirrors an axis), never zero.
  std::vector<double> sizes(const std::string& key, int n, double fallback, bool mirrors = false) {
    if (!has(key)) return std::vector<double>(n, fallback);
    const json& v = raw(key);
    std::vector<double> r;
    if (v.is_number()) r.assign(n, v.get<double>());
    else if (v.is_array() && int(v.size()) == n && std::all_of(v.begin(), v.end(), [](const json& e) { return e.is_number(); }))
      for (const auto& e : v) r.push_back(e.get<double>());
    else fail(key, v, "expected a number or an array of " + std::to_string(n) + " numbers");
    for (double d : r) {
      if (mirrors && !(std::isfinite(d) && d != 0.0))
        fail(key, v, "scale factors must be finite and non-zero (negative ones mirror)");
      if (!mirrors && !(std::isfinite(d) && d > 0.0)) fail(key, v, "sizes must be finite and greater than zero");
      if (std::abs(d) > kMaxMagnitude) fail(key, v, kMagnitudeProblem);
    }
    return r;
  }

  /// Call when done: any key not read is an unknown field.
  void finish() const {
    for (auto it = obj_.begin(); it != obj_.end(); ++it)
      if (!used_.count(it.key())) fail(it.key(), it.value(), "unknown field");
  }

 private:
  const json& obj_;
  std::string pointer_;
  const std::string& source_;
  std::set<std::string> used_;
};

glm::dmat4 readTransform(ObjectReader& parent) {
  if (!parent.has("transform")) return glm::dmat4(1.0);
  ObjectReader r(parent.raw("transform"), parent.pointer("transform"), parent.source());
  glm::dmat4 m(1.0);
  if (r.has("matrix")) {
    if (r.has("translate") || r.has("rotate") || r.has("scale"))
      r.fail("matrix", r.raw("matrix"), "give either matrix or translate/rotate/scale, not both");
    const json& v = r.raw("matrix");
    if (!v.is_array() || v.size() != 16) r.fail("matrix", v, "expected 16 numbers (row-major 4x4)");
    for (int k = 0; k < 16; ++k) {
      if (!v[k].is_number() || !std::isfinite(v[k].get<double>())) r.fail("matrix", v, "expected 16 finite numbers");
      if (std::abs(v[k].get<double>()) > kMaxMagnitude) r.fail("matrix", v, kMagnitudeProblem);
      m[k % 4][k / 4] = v[k].get<double>();  // row-major in the file, column-major in GLM
    }
    // Meshes take affine transforms only: a projective bottom row would divide by w per vertex
    // (and a zero w row makes every point infinite).
    if (m[0][3] != 0.0 || m[1][3] != 0.0 || m[2][3] != 0.0 || m[3][3] != 1.0)
      r.fail("matrix", v, "the bottom row must be 0 0 0 1 (an affine transform; elements 13-16 of the row-major list)");
    // Singular: its determinant under 1e-12 of its columns' lengths' product (Hadamard's bound: the
    // determinant when the columns are orthogonal), so that neither a uniform scale of 1e-5 (an
    // absolute 1e-12 once refused it) nor a stretch of 1e6 along one axis is refused, as "scale"
    // takes both; columns that nearly share a plane are.
    const glm::dmat3 linear(m);
    const double bound = glm::length(linear[0]) * glm::length(linear[1]) * glm::length(linear[2]);
    if (!(std::abs(glm::determinant(linear)) > 1e-12 * bound))
      r.fail("matrix", v,
             "the matrix is singular (its determinant is under 1e-12 of its columns' lengths' product)");
  } else {
    const glm::dvec3 t = r.vec3("translate", glm::dvec3(0.0));
    const glm::dvec3 rot = r.vec3("rotate", glm::dvec3(0.0));
    const std::vector<double> s = r.sizes("scale", 3, 1.0, true);
    m = glm::translate(m, t);
    m = glm::rotate(m, glm::radians(rot.z), glm::dvec3(0, 0, 1));
    m = glm::rotate(m, glm::radians(rot.y), glm::dvec3(0, 1, 0));
    m = glm::rotate(m, glm::radians(rot.x), glm::dvec3(1, 0, 0));
    m = glm::scale(m, glm::dvec3(s[0], s[1], s[2]));
  }
  r.finish();
  return m;
}

// The mesh's positions (stored from `fileOrigin`, RebasedMesh) under m, in double (not yet
// rebased to the scene's origin); a mirror flips the winding in `mesh` so that faces stay outward.
std::vector<glm::dvec3> applyTransform(TriangleMesh& mesh, const glm::dmat4& m, const glm::dvec3& fileOrigin) {
  std::vector<glm::dvec3> world;
  world.reserve(mesh.positions.size());
  for (const auto& p : mesh.positions) world.emplace_back(m * glm::dvec4(glm::dvec3(p) + fileOrigin, 1.0));
  if (glm::determinant(glm::dmat3(m)) < 0.0)
    for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
  return world;
}

// An object as read from the file: topology in `obj.mesh`, world positions in double in `world`
// (obj.mesh.positions are filled once the scene's origin is known).
struct ReadObject {
  SceneObject obj;
  std::vector<glm::dvec3> world;
  std::filesystem::path file;  ///< a mesh object's file, as read
  std::vector<std::string> notes;  ///< warnings about the object (its winding repaired, its file's precision)
};

// How finely coordinates of a format with `mantissaBits` (52: double, 23: float) can place detail
// in the box lo..hi at its distance from the origin: the box's diagonal, the largest coordinate's
// magnitude and the format's spacing there (at most).
struct StepsAcross {
  double extent = 0.0, reach = 0.0, step = 0.0;
  StepsAcross(const glm::dvec3& lo, const glm::dvec3& hi, int mantissaBits)
      : extent(glm::length(hi - lo)),
        reach(std::max({std::abs(lo.x), std::abs(lo.y), std::abs(lo.z), std::abs(hi.x), std::abs(hi.y), std::abs(hi.z)})),
        step(reach * std::ldexp(1.0, -mantissaBits)) {}
  double count() const { return extent / step; }
  /// Fewer than `floor` steps across a box of some size away from the origin.
  bool fewerThan(double floor) const { return extent > 0.0 && step > 0.0 && count() < floor; }
};

// A mesh file that stores float coordinates (RebasedMesh::floatExtent) with fewer than
// kMinMeshFloatSteps single-precision steps across a part at its distance from the file's origin:
// the file's detail finer than a step is gone before any transform or rebasing can help (a
// probe's mesh stored at 1e7, README "Scene files"; a text format's digits are read in double and
// rebased, readRebasedTriangleMesh). The same floor as the scene's double steps.
constexpr double kMinMeshFloatSteps = 2e3;

// The warning about a mesh object's file, `where` naming it (empty when it has steps enough).
std::string meshFloatPrecisionNote(const RebasedMesh& read, const std::string& where) {
  const double step = read.floatReach * std::ldexp(1.0, -23);
  if (!(read.floatExtent > 0.0 && step > 0.0 && read.floatExtent / step < kMinMeshFloatSteps)) return {};
  char buf[240];
  std::snprintf(buf, sizeof buf,
                "the mesh is %.3g units across at %.3g from its file's origin, only about %.0f single-precision "
                "steps: the file stores its coordinates as float, so its detail finer than %.3g units is lost",
                read.floatExtent, read.floatReach, read.floatExtent / step, step);
  return where + ": " + buf +
         "; store it nearer its own origin (a glTF node or the object's transform can place it), or as text "
         "(.obj, .off, ASCII .ply or .stl: read in double and rebased)";
}

// The note about what removeExtraTriangles left out of a mesh file.
std::string extraTrianglesText(const ExtraTriangles& e) {
  std::vector<std::string> parts;
  if (e.duplicates > 0)
    parts.push_back(std::to_string(e.duplicates) + (e.duplicates == 1 ? " triangle" : " triangles") +
                    " repeating another's corners in the same order");
  if (e.flat > 0)
    parts.push_back(std::to_string(e.flat) + (e.flat == 1 ? " flat triangle" : " flat triangles") +
                    " (corners on a line) on edges that are closed without it");
  std::string text;
  for (std::size_t k = 0; k < parts.size(); ++k) text += (k ? " and " : "") + parts[k];
  return text + " left out: they add no surface and would keep the mesh from being closed";
}

// The warning about what orientOutward changed in object `name` (empty when nothing).
std::string orientationNote(const OrientationResult& o, const std::string& name, std::size_t triangles) {
  std::vector<std::string> what;
  if (o.repairedComponents > 0)
    what.push_back("had faces wound against their neighbours (in " + std::to_string(o.repairedComponents) +
                   (o.repairedComponents == 1 ? " connected part)" : " connected parts)"));
  char volume[32];
  std::snprintf(volume, sizeof volume, "%.4g", o.volumeBefore);
  if (o.insideOut) what.push_back("was inside out (signed volume " + std::string(volume) + ")");
  if (o.looseParts > 0)
    what.push_back("had " + std::to_string(o.looseParts) +
                   (o.looseParts == 1 ? " part inside out on its own" : " parts inside out on their own"));
  std::string text = std::string(o.open ? "the open mesh" : "the closed mesh") + " \"" + name + "\"";
  for (std::size_t k = 0; k < what.size(); ++k)
    text += (k == 0 ? " " : k + 1 == what.size() ? " and " : ", ") + what[k];
  if (o.reversed > 0)
    text += ": " + std::to_string(o.reversed) + " of its " + std::to_string(triangles) + " triangles were reversed " +
            (o.open ? "to agree with most of their part (open, it has no outside to face)" : "so that it faces outward") +
            " (set \"orient\": \"as-stored\" to keep the file's winding)";
  if (o.partsNotChecked > 0)
    text += std::string(o.reversed > 0 ? "; " : ": ") + std::to_string(o.partsNotChecked) +
            " of its parts were not tested for lying inside another (too many triangles) and were taken as solids "
            "of their own";
  return o.reversed > 0 || o.partsNotChecked > 0 ? text : std::string();
}

// A mesh object's "orient": "outward" (the default: mesh_orientation.h's repair) or "as-stored".
// Returns the warning about what was reversed, or nothing.
std::string orientMesh(ObjectReader& r, ReadObject& read, const std::string& source) {
  const std::string orient = r.string("orient", std::string("outward"));
  if (orient == "as-stored") return {};
  if (orient != "outward") r.fail("orient", json(orient), "expected \"outward\" or \"as-stored\"");
  const OrientationResult o = orientOutward(read.obj.mesh, read.world);
  const std::string note = orientationNote(o, read.obj.name, read.obj.mesh.triangleCount());
  return note.empty() ? note : source + ": " + r.pointer("orient") + ": " + note;
}

// The mesh of a built-in primitive type. Each refuses, before generating anything, a tessellation
// whose triangle count (an upper bound) exceeds `budget`, the triangles the scene may still hold.
TriangleMesh makePrimitive(ObjectReader& r, const std::string& t, std::size_t budget) {
  auto within = [&](const char* field, double triangles) {
    if (triangles > double(budget))
      r.fail(field, r.has(field) ? r.raw(field) : json(),
             "up to " + std::to_string(std::size_t(triangles)) + " triangles: more than the " +
                 std::to_string(budget) + " the scene may still hold");
  };
  if (t == "plane") {
    const auto s = r.sizes("size", 2, 10.0);
    const int n = r.integer("subdivisions", 1, 1, 4096);
    within("subdivisions", 2.0 * n * n);
    return makePlane(s[0], s[1], n);
  }
  if (t == "sphere") {
    const double radius = r.positive("radius", 1.0);
    const std::string tess = r.string("tessellation", std::string("ico"));
    if (tess == "ico") {
      const int detail = r.integer("detail", 3, 0, 8);
      within("detail", 20.0 * std::pow(4.0, detail));  // at most 1.3 million triangles
      return makeIcoSphere(radius, detail);
    }
    if (tess != "uv") r.fail("tessellation", json(tess), "expected \"ico\" or \"uv\"");
    const int segments = r.integer("segments", 32, 3, 8192);
    const int rings = r.integer("rings", 16, 2, 8192);
    within("rings", 2.0 * segments * rings);
    return makeUvSphere(radius, segments, rings);
  }
  if (t == "hemisphere") {
    const double radius = r.positive("radius", 1.0);
    const int segments = r.integer("segments", 64, 3, 8192);
    const int rings = r.integer("rings", 16, 1, 8192);
    within("rings", 2.0 * segments * (rings + 1.0));
    return makeHemisphere(radius, segments, rings);
  }
  if (t == "box") {
    const auto s = r.sizes("size", 3, 1.0);
    return makeBox(s[0], s[1], s[2]);
  }
  if (t == "cylinder") {
    const double radius = r.positive("radius", 0.5);
    const double height = r.positive("height", 1.0);
    const int segments = r.integer("segments", 32, 3, 8192);
    within("segments", 4.0 * segments);  // two per side quad, one per cap fan
    return makeCylinder(radius, height, segments);
  }
  if (t == "tree") {
    const double trunkRadius = r.positive("trunkRadius", 0.08);
    const double trunkHeight = r.positive("trunkHeight", 2.0);
    const double crownRadius = r.positive("crownRadius", 0.8);
    const int detail = r.integer("detail", 3, 0, 8);
    within("detail", 4.0 * 16 + 20.0 * std::pow(4.0, detail));  // a 16-segment trunk and an ico-sphere crown
    return makeTree(trunkRadius, trunkHeight, crownRadius, detail);
  }
  r.fail("type", json(t), "unknown object type (plane, sphere, hemisphere, box, cylinder, tree, mesh)");
}

ReadObject readObject(const json& v, std::size_t index, const std::string& source,
                      const std::filesystem::path& baseDir, std::size_t budget) {
  ObjectReader r(v, "/objects/" + std::to_string(index), source);
  ReadObject read;
  SceneObject& obj = read.obj;
  obj.type = r.string("type");
  obj.name = r.string("name", obj.type + "#" + std::to_string(index));
  glm::dvec3 fileOrigin(0.0);  // a mesh file's stored positions are relative to it
  std::string precisionNote;
  if (obj.type == "mesh") {
    const std::string file = r.string("file");
    std::filesystem::path p(file);
    if (p.is_relative()) p = baseDir / p;
    read.file = p;
    try {
      RebasedMesh rebased = readRebasedTriangleMesh(p);
      obj.mesh = std::move(rebased.mesh);
      fileOrigin = rebased.origin;
      precisionNote = meshFloatPrecisionNote(rebased, source + ": " + r.pointer("file") + " (" + p.string() + ")");
      // Triangles that bound nothing and only keep the mesh from being closed (an inside-out mesh
      // with one stray flat triangle was neither turned outward nor captured as closed).
      if (const ExtraTriangles extra = removeExtraTriangles(obj.mesh); extra.total() > 0)
        read.notes.push_back(source + ": " + r.pointer("file") + " (" + p.string() + "): " + extraTrianglesText(extra));
      // Vertices no face uses would widen the bounds the light and camera are fitted to (a
      // thirteenth probe's stray vertex 1000 units off made a directional light's texel 4 units).
      if (const std::size_t unused = obj.mesh.removeUnusedVertices(); unused > 0)
        read.notes.push_back(source + ": " + r.pointer("file") + " (" + p.string() + "): " + std::to_string(unused) +
                             (unused == 1 ? " vertex" : " vertices") +
                             " used by no face left out (they would widen the scene's bounds, to which the light "
                             "and camera are fitted)");
    } catch (const InputError& e) {
      throw InputError(source, r.pointer("file"), show(json(file)), e.what());
    }
  } else {
    obj.mesh = makePrimitive(r, obj.type, budget);
  }
  if (obj.mesh.triangleCount() > budget) {  // a mesh file's (and a box's 12) named by what holds them
    const bool mesh = obj.type == "mesh";
    r.fail(mesh ? "file" : "type", r.raw(mesh ? "file" : "type"),
           std::to_string(obj.mesh.triangleCount()) + " triangles: more than the " + std::to_string(budget) +
               " the scene may still hold");
  }
  read.world = applyTransform(obj.mesh, readTransform(r), fileOrigin);
  if (obj.type == "mesh") {
    if (!precisionNote.empty()) read.notes.push_back(std::move(precisionNote));
    if (std::string note = orientMesh(r, read, source); !note.empty()) read.notes.push_back(std::move(note));
  }
  r.finish();
  for (const auto& p : read.world)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      r.fail("transform", json(), "the transform makes coordinates non-finite");
  return read;
}


// Scene::origin's rule: the bounds' centre when it lies further from the world origin than the
// bounds' radius, else 0 (then stored coordinates are at most about twice the scene's extent, and
// float keeps what it would keep for the scene centred). But where what the camera looks at (its
// target, moved into the bounds) lies more than kDetailRange view distances from that origin,
// float would round it by more than about a tenth of a pixel (an elephant at 1e6 beside a ground
// of side 3e6): then that point is the origin, and the far parts of the scene take the rounding.
constexpr double kDetailRange = 1e3;

glm::dvec3 chooseOrigin(const Bounds3& b, const Camera& camera) {
  if (b.empty()) return glm::dvec3(0.0);
  const glm::dvec3 byBounds = glm::length(b.center()) <= b.radius() ? glm::dvec3(0.0) : b.center();
  const glm::dvec3 seen = glm::clamp(camera.target, b.min, b.max);
  const double view = glm::length(camera.target - camera.eye);
  if (view > 0.0 && glm::length(seen - byBounds) > kDetailRange * view) return seen;
  return byBounds;
}

// Picks the scene's origin and stores every position relative to it: the objects' (double -> float
// only now), the light's and the camera's.
void rebase(Scene& scene, std::vector<std::vector<glm::dvec3>>& world, const std::string& source) {
  Bounds3 b;
  for (const auto& w : world)
    for (const auto& p : w) b.extend(p);
  scene.origin = chooseOrigin(b, scene.camera);
  for (std::size_t k = 0; k < world.size(); ++k) {
    auto& positions = scene.objects[k].mesh.positions;
    for (std::size_t i = 0; i < world[k].size(); ++i) {
      positions[i] = glm::vec3(world[k][i] - scene.origin);
      if (!std::isfinite(positions[i].x) || !std::isfinite(positions[i].y) || !std::isfinite(positions[i].z))
        throw InputError(source, "/objects/" + std::to_string(k) + "/transform", "",
                         "coordinates beyond single precision's range (|x| > 3.4e38 from the scene's centre)");
    }
    world[k] = {};
  }
  scene.light.position -= scene.origin;
  for (Light& l : scene.otherLights) l.position -= scene.origin;
  scene.camera.eye -= scene.origin;
  scene.camera.target -= scene.origin;
}

// A scene under kMinSceneRadius: single precision (Embree's rays, the GPU's depth, the float
// margins of the fit) loses its shadows, whatever its place: a thirteenth probe's default scene
// scaled by 1e-8 (radius 1.4e-7) failed validate with the map from rays, by 1e-9 it missed most of
// the shadow, by 1e-10 `build` wrote an empty volume; scaled by 1e-7 it matched the unscaled one.
constexpr double kMinSceneRadius = 1e-6;
void warnAboutSmallScene(const Scene& scene, const std::string& source, std::vector<std::string>& warnings) {
  const double radius = scene.bounds().radius();
  if (!(radius > 0.0 && radius < kMinSceneRadius)) return;
  warnings.push_back(source + ": /objects: the scene's radius is " + numberText(radius) + " units, under the " +
                     numberText(kMinSceneRadius) +
                     " that single precision (the GPU's depth, Embree's rays) resolves: its shadows can be lost or "
                     "wrong; scale the whole scene up (its unit is yours to choose)");
}

// A scene so small for its distance from the world origin that its input coordinates (double)
// hold fewer than kMinSceneDoubleSteps steps across it: rebasing keeps what the input has, not
// what it lacks (a sixth probe's lion head scaled by 1e-7 at 1e7, about 370 steps across, failed
// validate's agreement without a word; 3,700 steps agreed on every pixel).
constexpr double kMinSceneDoubleSteps = 2e3;
void warnAboutInputPrecision(const Scene& scene, const std::string& source, std::vector<std::string>& warnings) {
  const Bounds3 b = scene.bounds();
  const StepsAcross s(glm::dvec3(b.min) + scene.origin, glm::dvec3(b.max) + scene.origin, 52);
  if (!s.fewerThan(kMinSceneDoubleSteps)) return;
  char buf[200];
  std::snprintf(buf, sizeof buf, "the scene is %.3g units across at %.3g from the world origin, only about %.0f", s.extent,
                s.reach, s.count());
  warnings.push_back(source + ": /objects: " + buf +
                     " double-precision steps: its coordinates cannot place detail finer than that, so shadow "
                     "edges and validate's agreement can be off; give the coordinates nearer the origin");
}

void readLightPlanes(ObjectReader& r, Light& light) {
  if (r.has("near")) {
    light.nearPlane = r.number("near");
    if (light.type != LightType::Directional && !(light.nearPlane > 0.0))
      r.fail("near", json(light.nearPlane), std::string("a ") + toString(light.type) + " light's near plane must be greater than zero");
    if (light.type == LightType::Directional && !(light.nearPlane >= 0.0))
      r.fail("near", json(light.nearPlane),
             "a directional light's near plane must be >= 0: it is a distance in front of the plane through its "
             "position, and nothing behind that plane is lit");
  }
  if (r.has("far")) {
    light.farPlane = r.number("far");
    if (r.has("near") && !(light.farPlane > light.nearPlane))
      r.fail("far", json(light.farPlane), "far must be greater than near (" + numberText(light.nearPlane) + ")");
    if (light.type != LightType::Directional && !(light.farPlane > 0.0))
      r.fail("far", json(light.farPlane), "must be greater than zero");
  }
}

void readIntensity(ObjectReader& r, Light& light) {
  light.intensity = r.number("intensity", 1.0);
  if (!(light.intensity >= 0.0 && light.intensity <= 1e3))
    r.fail("intensity", json(light.intensity), "a light's intensity (its diffuse factor) must be in [0, 1000]");
}

// Whether `d` is too short to take a direction from: zero; for the difference of two points whose
// magnitude reaches `scale` (0 for a direction given as such), under 1e-14 of it (about 45 double
// steps: fewer leave the direction mostly rounding; a scene that coarse in double is warned about,
// warnAboutInputPrecision); or under 1e-150, where its square
// underflows in double and normalizing it gives NaN. Scale-free but for that floor.
bool tooShortForADirection(const glm::dvec3& d, double scale) {
  const double length = glm::length(d);
  return !(length > 1e-14 * scale) || !(length > 1e-150);
}

Light readLight(const json& v, const std::string& pointer, const std::string& source) {
  ObjectReader r(v, pointer, source);
  Light light;
  const std::string type = r.string("type");
  if (!parseLightType(type, light.type))
    r.fail("type", json(type), "expected " + choicesText(namesIn(kLightTypeNames), true));

  if (light.type != LightType::Directional || r.has("position")) light.position = r.vec3("position");
  if (light.type == LightType::Point) {
    for (const char* field : {"direction", "target", "up", "fov", "extent"})
      if (r.has(field))
        r.fail(field, r.raw(field), "a point light shines every way from its position: it has no direction, up, "
                                    "fov or extent (its six cube faces are fixed, README \"Point lights\")");
    readLightPlanes(r, light);
    readIntensity(r, light);
    r.finish();
    return light;
  }
  light.fitPosition = light.type == LightType::Directional && !r.has("position");
  if (r.has("target") && r.has("direction"))
    r.fail("target", r.raw("target"), "give either direction or target, not both");
  if (r.has("target")) {
    if (light.type == LightType::Directional && !r.has("position"))
      r.fail("target", r.raw("target"), "a directional light with a target needs a position too");
    const glm::dvec3 target = r.vec3("target");
    light.direction = target - light.position;
    if (tooShortForADirection(light.direction, std::max(glm::length(target), glm::length(light.position))))
      r.fail("target", r.raw("target"),
             "target and position coincide (closer than 1e-14 of their distance from the origin, or than "
             "1e-150): they give no direction");
  } else {
    light.direction = r.vec3("direction");
    if (tooShortForADirection(light.direction, 0.0))
      r.fail("direction", r.raw("direction"), "the direction is zero (or shorter than 1e-150)");
  }
  light.direction = glm::normalize(light.direction);
  light.up = r.vec3("up", glm::dvec3(0.0));  // 0 = chosen from the direction (lightUp)
  if (r.has("up") && tooShortForADirection(light.up, 0.0))
    r.fail("up", r.raw("up"), "the up vector is zero (or shorter than 1e-150)");
  if (glm::length(light.up) > 0.0 && glm::length(glm::cross(glm::normalize(light.up), light.direction)) < 1e-6)
    r.fail("up", json::array({light.up.x, light.up.y, light.up.z}), "up is parallel to the light direction");

  if (light.type == LightType::Spot) {
    light.fovYDegrees = r.number("fov", 60.0);
    if (!(light.fovYDegrees >= kMinFovDegrees && light.fovYDegrees < 179.0))
      r.fail("fov", json(light.fovYDegrees), "a spot light's field of view must be in [0.01, 179) degrees");
  } else if (r.has("extent")) {
    light.halfExtent = r.positive("extent");
  }
  readLightPlanes(r, light);
  readIntensity(r, light);
  r.finish();
  return light;
}

Camera readCamera(const json& v, const std::string& source) {
  ObjectReader r(v, "/camera", source);
  Camera c;
  c.eye = r.vec3("eye");
  c.target = r.vec3("target");
  c.up = r.vec3("up", glm::dvec3(0.0, 1.0, 0.0));
  const glm::dvec3 view = c.target - c.eye;
  if (tooShortForADirection(view, std::max(glm::length(c.target), glm::length(c.eye))))
    r.fail("target", r.raw("target"),
           "target and eye coincide (closer than 1e-14 of their distance from the origin, or than 1e-150): they "
           "give no view direction");
  const json upValue = json::array({c.up.x, c.up.y, c.up.z});
  if (tooShortForADirection(c.up, 0.0)) r.fail("up", upValue, "the up vector is zero (or shorter than 1e-150)");
  if (glm::length(glm::cross(glm::normalize(view), glm::normalize(c.up))) < 1e-6)
    r.fail("up", upValue, "up is parallel to the view direction (target - eye)");
  c.fovYDegrees = r.number("fov", 45.0);
  if (!(c.fovYDegrees >= kMinFovDegrees && c.fovYDegrees < 179.0))
    r.fail("fov", json(c.fovYDegrees), "the camera's field of view must be in [0.01, 179) degrees");
  c.width = r.integer("width", 640, 1, kMaxImageSide);
  c.height = r.integer("height", 480, 1, kMaxImageSide);
  if (r.has("near")) c.nearPlane = r.positive("near");
  if (r.has("far")) {
    c.farPlane = r.positive("far");
    if (c.nearPlane > 0.0 && !(c.farPlane > c.nearPlane))
      r.fail("far", json(c.farPlane), "far must be greater than near");
  }
  r.finish();
  return c;
}

// Parity of crossings of a ray with a closed mesh (ray_parity.h); odd = inside.
bool insideClosedMesh(const TriangleMesh& m, const glm::dvec3& origin) {
  int crossings = 0;
  for (const auto& t : m.triangles)
    crossings += parityRayCrosses(origin, glm::dvec3(m.positions[t[0]]), glm::dvec3(m.positions[t[1]]),
                                  glm::dvec3(m.positions[t[2]]));
  return crossings % 2 == 1;
}

// The file's `light` or `lights` (one of them, not both): at most kMaxSceneLights.
void readLights(ObjectReader& top, Scene& scene, const std::string& source) {
  if (top.has("light") && top.has("lights"))
    top.fail("lights", top.raw("lights"), "give either `light` (one light) or `lights` (an array), not both");
  if (!top.has("light") && !top.has("lights"))
    top.fail("light", json(), "required field is missing (or `lights`, an array of lights)");
  if (top.has("light")) {
    scene.light = readLight(top.raw("light"), "/light", source);
    return;
  }
  const json& lights = top.raw("lights");
  if (!lights.is_array() || lights.empty() || lights.size() > kMaxSceneLights)
    top.fail("lights", lights.is_array() ? json(std::to_string(lights.size()) + " lights") : lights,
             "expected an array of 1 to " + std::to_string(kMaxSceneLights) + " lights");
  scene.lightsArray = true;
  for (std::size_t k = 0; k < lights.size(); ++k) {
    Light l = readLight(lights[k], "/lights/" + std::to_string(k), source);
    if (k == 0) scene.light = l;
    else scene.otherLights.push_back(l);
  }
}

// Light k (as scene.light, forEachLight) fitted to the loaded scene: the fit's notes as warnings,
// their "/light/" pointers made the light's own; the camera's (its planes are fitted with the
// first light's) in `cameraWarnings` too.
void fitLoadedLight(Scene& scene, std::size_t k, const std::string& source, std::vector<std::string>& warnings,
                    std::vector<std::string>& cameraWarnings) {
  const Light given = scene.light;
  const std::string pointer = scene.lightPointer(k);
  for (auto& note : fitLightAndCamera(scene)) {  // "<source>: /light/far: ..." or "<source>: /camera/far: ..."
    const std::string prefix = source + ": /light/";
    if (note.rfind(prefix, 0) == 0) note = source + ": " + pointer + "/" + note.substr(prefix.size());
    else if (note.rfind(source + ": /camera/", 0) == 0) cameraWarnings.push_back(note);
    warnings.push_back(std::move(note));
  }
  // A far directional light's given planes move with it (scene_fit.cpp): its far, from where it stands now.
  const double moved = scene.light.type == LightType::Directional && !given.fitPosition
                           ? glm::dot(scene.light.position - given.position, scene.light.direction)
                           : 0.0;
  if (given.farPlane > 0.0 && given.nearPlane == 0.0 && scene.light.nearPlane >= given.farPlane - moved)
    throw InputError(source, pointer + "/far", numberText(given.farPlane), "far lies before the fitted near plane");
}

// A directional light's window (2 x extent) narrower than kMinWindowFloatSteps float steps of the
// scene's coordinates in its view is refused: its texels would collapse (a thirteenth probe's
// extent of 1e-200 made Embree abort on the rays' non-finite origins).
void checkDirectionalWindow(const Scene& scene, std::size_t k, const std::string& source) {
  const Light& l = scene.light;
  if (l.type != LightType::Directional) return;
  const double reach = detail::viewReach(scene.bounds(), lightView(l));
  const double least = kMinWindowFloatSteps * std::numeric_limits<float>::epsilon() * reach;
  if (2.0 * l.halfExtent >= least) return;
  throw InputError(source, scene.lightPointer(k) + "/extent", numberText(l.halfExtent),
                   "the light's window, twice the extent, spans fewer than " + numberText(kMinWindowFloatSteps) +
                       " single-precision steps of the scene's coordinates in its view (" + numberText(reach) +
                       " units out): its texels would collapse; give an extent of at least " + numberText(least / 2.0));
}

// A spot or point light's near plane below far x this (the fit's floor is far x 1e-7, where the
// light touches geometry) is warned about: float depth keeps about 7 digits.
constexpr double kMinLightNearFraction = 1e-6;

// The warnings about light k (as scene.light): inside a closed mesh; a near plane so close to the
// light that depth precision is lost; a directional light's plane through the scene.
void warnAboutLight(const Scene& scene, const std::vector<bool>& closed, std::size_t k, const std::string& source,
                    std::vector<std::string>& warnings) {
  const std::string pointer = scene.lightPointer(k);
  for (std::size_t i = 0; i < scene.objects.size(); ++i)
    if (const SceneObject& o = scene.objects[i]; closed[i] && insideClosedMesh(o.mesh, scene.light.position))
      warnings.push_back(source + ": " + pointer + "/position: the " + toString(scene.light.type) +
                         " light is inside the closed mesh \"" + o.name +
                         "\": it lights only what the mesh encloses (its inner side and the objects inside); "
                         "everything outside it is in shadow");
  // A probe's finding: a point light on a wall had its near plane fitted down to far x 1e-7, and
  // its refined GPU volume disagreed with its crossing counts along every shadow edge.
  const Light& l = scene.light;
  if (l.type != LightType::Directional && l.nearPlane < l.farPlane * kMinLightNearFraction) {
    char buf[400];
    std::snprintf(buf, sizeof buf,
                  "/near: %.6g, %.3g times nearer than the far plane (%.6g): the light (nearly) touches the scene's "
                  "geometry, and the GPU's depth precision is lost so near it (a refined GPU volume can disagree "
                  "with its crossing counts); move the light off the surface or give a larger near",
                  l.nearPlane, l.farPlane / l.nearPlane, l.farPlane);
    warnings.push_back(source + ": " + pointer + buf);
  }
  if (scene.light.type == LightType::Directional) {
    const auto [lo, hi] = detail::depthRange(scene.bounds(), scene.light.position, scene.light.direction);
    if (hi <= 0.0)
      warnings.push_back(source + ": " + pointer + "/position: the whole scene lies behind the plane through the "
                                                   "directional light's position: nothing is lit or casts a shadow");
    else if (lo < 0.0)
      warnings.push_back(source + ": " + pointer + "/position: the plane through the directional light's position "
                                                   "cuts the scene's bounds: what lies behind it is neither lit nor "
                                                   "casts a shadow");
  }
}

// Points on the camera's near rectangle (9 x 7, its corners and border included), for the test of a
// near plane that cuts a closed mesh.
std::vector<glm::dvec3> nearRectangleSamples(const Camera& c) {
  const double halfH = c.nearPlane * std::tan(0.5 * c.fovYDegrees * std::numbers::pi / 180.0);
  const double halfW = halfH * double(c.width) / double(c.height);
  const glm::dmat4 toWorld = glm::inverse(cameraView(c));  // the camera's own frame, as every pass has it
  std::vector<glm::dvec3> points;
  for (int b = 0; b < 7; ++b)
    for (int a = 0; a < 9; ++a)
      points.push_back(glm::dvec3(toWorld * glm::dvec4(halfW * (a / 4.0 - 1.0), halfH * (b / 3.0 - 1.0), -c.nearPlane, 1.0)));
  return points;
}

bool boxesOverlap(const Bounds3& a, const Bounds3& b) {
  return !(a.empty() || b.empty()) && a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y &&
         b.min.y <= a.max.y && a.min.z <= b.max.z && b.min.z <= a.max.z;
}

// A camera whose view holds no object (it looks away, or a given near/far range holds nothing)
// renders only the background: said, since every command would otherwise run on without a word.
void warnAboutCamera(const Scene& scene, const std::vector<bool>& closed, const std::string& source,
                     std::vector<std::string>& warnings) {
  const Camera& c = scene.camera;
  const std::vector<glm::dvec3> nearPoints = nearRectangleSamples(c);
  Bounds3 nearBox;
  for (const auto& p : nearPoints) nearBox.extend(p);
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    if (!closed[i]) continue;
    const TriangleMesh& mesh = scene.objects[i].mesh;
    if (insideClosedMesh(mesh, c.eye)) {
      warnings.push_back(source + ": /camera/eye: the camera is inside the closed mesh \"" + scene.objects[i].name +
                         "\": images show its inside, and validation counts its inner faces");
      continue;
    }
    // A probe's finding: a near plane that cut the sphere showed its inside lit, without a word.
    const Bounds3 box = mesh.bounds();
    if (!boxesOverlap(nearBox, box)) continue;
    const auto inBox = [&](const glm::dvec3& p) {
      return p.x >= box.min.x && p.x <= box.max.x && p.y >= box.min.y && p.y <= box.max.y && p.z >= box.min.z &&
             p.z <= box.max.z;
    };  // each parity test reads every triangle: only the samples inside the mesh's box
    if (std::any_of(nearPoints.begin(), nearPoints.end(),
                    [&](const glm::dvec3& p) { return inBox(p) && insideClosedMesh(mesh, p); }))
      warnings.push_back(source + ": /camera/near: the camera's near plane (" + numberText(c.nearPlane) +
                         ") cuts the closed mesh \"" + scene.objects[i].name +
                         "\": images show its inside, which the light does not reach (validate scores it as shadowed or "
                         "facing away)");
  }
  const std::string w = detail::emptyViewWarning(
      cameraProjection(c) * cameraView(c), scene.objects, "in the camera's view", c.nearPlane, c.farPlane,
      "images show only the background (check /camera/target, /camera/near and /camera/far)");
  if (!w.empty()) warnings.push_back(source + ": /camera: " + w);
}

}  // namespace

std::string Scene::lightPointer(std::size_t k) const {
  return lightsArray ? "/lights/" + std::to_string(k) : "/light";
}

Scene Scene::withOnlyLight(std::size_t k) const {
  Scene s;
  s.source = source;
  s.origin = origin;
  s.objects = objects;
  s.light = lightAt(k);
  s.camera = camera;
  return s;
}

std::size_t Scene::triangleCount() const {
  std::size_t n = 0;
  for (const auto& o : objects) n += o.mesh.triangleCount();
  return n;
}

Bounds3 Scene::bounds() const {
  Bounds3 b;
  for (const auto& o : objects) b.extend(o.mesh.bounds());
  return b;
}

TriangleMesh Scene::merged() const {
  TriangleMesh m;
  for (const auto& o : objects) m.append(o.mesh);
  return m;
}

SceneLoadResult parseScene(const std::string& text, const std::string& source,
                           const std::filesystem::path& baseDir, std::size_t maxTriangles) {
  const json doc = parseJsonText(text, source);
  SceneLoadResult result;
  Scene& scene = result.scene;
  scene.source = source;
  ObjectReader top(doc, "", source);
  if (top.has("description")) top.string("description");
  if (!top.has("objects")) top.fail("objects", json(), "required field is missing");
  const json& objects = top.raw("objects");
  if (!objects.is_array() || objects.empty())
    top.fail("objects", objects, "expected a non-empty array of objects");
  std::vector<std::vector<glm::dvec3>> world;
  std::size_t budget = maxTriangles;
  for (std::size_t k = 0; k < objects.size(); ++k) {
    ReadObject read = readObject(objects[k], k, source, baseDir, budget);
    budget -= read.obj.mesh.triangleCount();
    scene.objects.push_back(std::move(read.obj));
    if (!read.file.empty()) scene.files.push_back(read.file);
    for (std::string& note : read.notes) result.warnings.push_back(std::move(note));
    world.push_back(std::move(read.world));
  }
  readLights(top, scene, source);
  if (!top.has("camera")) top.fail("camera", json(), "required field is missing");
  scene.camera = readCamera(top.raw("camera"), source);
  top.finish();

  if (scene.triangleCount() == 0) throw InputError(source, "/objects", "", "the scene has no triangles");
  rebase(scene, world, source);
  warnAboutInputPrecision(scene, source, result.warnings);
  warnAboutSmallScene(scene, source, result.warnings);
  forEachLight(scene, [&](std::size_t k) {
    fitLoadedLight(scene, k, source, result.warnings, result.cameraWarnings);
    checkDirectionalWindow(scene, k, source);
  });
  bool splitComplete = true;
  forEachLight(scene, [&](std::size_t) { splitComplete = splitSceneAcrossEyePlanes(scene, maxTriangles).complete && splitComplete; });
  if (!splitComplete)
    result.warnings.push_back(source + ": /objects: triangles crossing the camera's or light's eye plane are more than " +
                              std::to_string(int(kEyePlaneEdgeRatio)) +
                              " near planes long, and splitting them all would pass the triangle budget: the GPU "
                              "clips them in single precision, so expect shadow edges off by a pixel; subdivide "
                              "or shrink the largest objects (README \"Known limits\")");
  const std::size_t cameraPlaneNotes = result.cameraWarnings.size();  // already in warnings
  std::vector<bool> closed;
  for (const auto& o : scene.objects) closed.push_back(isClosedSurface(o.mesh));
  forEachLight(scene, [&](std::size_t k) { warnAboutLight(scene, closed, k, source, result.warnings); });
  warnAboutCamera(scene, closed, source, result.cameraWarnings);
  result.warnings.insert(result.warnings.end(), result.cameraWarnings.begin() + std::ptrdiff_t(cameraPlaneNotes),
                         result.cameraWarnings.end());
  return result;
}

SceneLoadResult loadScene(const std::filesystem::path& path) {
  constexpr std::uintmax_t kMaxSceneFileBytes = 64u << 20;  // scene files are small; meshes are separate
  std::error_code ec;
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
    throw InputError(path.string(), "", "", "not a regular file (a folder, device or pipe)");
  if (std::filesystem::exists(path, ec) && std::filesystem::file_size(path, ec) > kMaxSceneFileBytes)
    throw InputError(path.string(), "", std::to_string(std::filesystem::file_size(path, ec)) + " bytes",
                     "larger than a scene file may be (64 MiB)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "", "", "cannot open the scene file");
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw InputError(path.string(), "", "", "cannot read the scene file");
  SceneLoadResult r = parseScene(ss.str(), path.string(), path.parent_path());
  r.scene.files.insert(r.scene.files.begin(), path);
  return r;
}

Scene defaultScene() {
  Scene s;
  s.source = "default";
  SceneObject ground{"ground", "plane", makePlane(20.0, 20.0, 1)};
  SceneObject sphere{"sphere", "sphere", makeIcoSphere(1.0, 4)};
  for (auto& p : sphere.mesh.positions) p.y += 2.0f;
  s.objects = {std::move(ground), std::move(sphere)};
  s.light.type = LightType::Spot;
  s.light.position = {3.0, 9.0, 2.0};
  s.light.direction = glm::normalize(glm::dvec3(-0.3, 0.0, -0.2) - s.light.position);
  s.light.fovYDegrees = 55.0;
  s.camera.eye = {0.0, 6.0, 11.0};
  s.camera.target = {0.0, 1.0, 0.0};
  s.camera.fovYDegrees = 45.0;
  s.camera.width = 640;
  s.camera.height = 480;
  fitLightAndCamera(s);
  splitSceneAcrossEyePlanes(s, kMaxSceneTriangles);
  return s;
}

void exportSceneMesh(const Scene& scene, const std::filesystem::path& path, bool worldCoordinates) {
  writeTriangleMesh(scene.merged(), path, MeshFrame{scene.origin, worldCoordinates});
}

}  // namespace shadowvol
