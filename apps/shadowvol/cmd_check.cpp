// shadowvol check: a mesh file checked as shadowvol's own volumes are (CGAL, mesh_check.h).
#include <cstdio>
#include <iostream>
#include <memory>

#include "cli_common.h"
#include "shadowvol/report_json.h"
#include "shadowvol/cgal/mesh_check.h"
#include "shadowvol/cgal/mesh_check_json.h"
#include "shadowvol/mesh_io.h"
#include "shadowvol/version.h"

namespace shadowvol::cli {
namespace {

// The file's triangles as a volume mesh: positions as read (single precision), in double.
VolumeMesh asVolume(const TriangleMesh& m) {
  VolumeMesh v;
  v.positions.reserve(m.positions.size());
  for (const auto& p : m.positions) v.positions.push_back(glm::dvec3(p));
  v.triangles.assign(m.triangles.begin(), m.triangles.end());
  return v;
}

// The checks that failed, in words ("" when none).
std::string failures(const MeshCheckReport& r) {
  std::string out;
  auto add = [&](bool failed, const std::string& what) {
    if (failed) out += (out.empty() ? "" : "; ") + what;
  };
  add(!r.closedManifold(), "not a closed 2-manifold (" + std::to_string(r.boundaryEdges) + " boundary edges, " +
                               std::to_string(r.overusedEdges) + " over-used edges, " +
                               std::to_string(r.nonManifoldVertices) + " non-manifold vertices, " +
                               std::to_string(r.badIndexTriangles) + " triangles with a repeated index)");
  // A fifteenth probe's: a triangle soup (corners written once per triangle) was named only by its
  // boundary edges.
  add(r.boundaryEdges > 0 && r.coincidentVertices > 0,
      (r.coincidentVertices == 1 ? std::string("1 vertex lies") : std::to_string(r.coincidentVertices) + " vertices lie") +
          " on another vertex: corners the file may not share, where its edges are open (weld them, or write the "
          "mesh as .stl, whose corners are welded on reading)");
  add(r.closedManifold() && r.triangles > 0 && !r.outward,
      "not outward (a part's signed volume disagrees with its nesting)");
  add(r.nonFiniteVertices > 0, std::to_string(r.nonFiniteVertices) + " non-finite vertices");
  add(r.degenerateTriangles > 0, std::to_string(r.degenerateTriangles) + " zero-area triangles");
  add(r.isolatedVertices > 0, std::to_string(r.isolatedVertices) + " vertices used by no triangle");
  add(out.empty() && !r.valid(), "encloses no volume (signed volume " + std::to_string(r.volume) + ")");
  return out;
}

}  // namespace

void registerCheckCommand(CLI::App& app, Runner& run) {
  struct Options {
    std::string mesh;
    std::vector<std::size_t> partStarts;
    bool json = false;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "check",
      "Check a mesh file as shadowvol checks its own volumes (CGAL): a closed 2-manifold (every edge once each "
      "way, every vertex one fan), outward (each part's signed volume as its nesting asks), finite, no zero-area "
      "triangle and no unused vertex. Exit 0 when it is a valid closed volume (or an empty one, as build writes when "
      "nothing is in shadow), 3 when not, naming what failed; "
      "shared corners count only where the file shares them (STL's are welded on reading)");
  cmd->add_option("mesh", o->mesh, "The mesh file (.ply, .obj, .off, .stl, or any format Assimp reads)")->required();
  cmd->add_option("--part-starts", o->partStarts,
                  "The file's triangles where a closed part after the first begins (build --face-prisms prints it, "
                  "and its JSON as partStarts): each part is checked alone, a later one as a union of solids that "
                  "may overlap (every component outward), as build checks its own volume")
      ->delimiter(',');
  addJsonOption(*cmd, o->json);
  cmd->callback([&run, o] {
    run = [o] {
      // Rebased (the verdict does not depend on where the mesh lies), so that a volume written in
      // world coordinates far from the origin is judged before float rounds it.
      const TriangleMesh m = readRebasedTriangleMesh(o->mesh, EmptyMesh::Allow).mesh;  // build writes an empty volume
      VolumeMesh volume = asVolume(m);
      std::size_t previous = 0;
      for (const std::size_t start : o->partStarts) {
        if (start <= previous || start >= volume.triangleCount())
          throw InputError("command line", "--part-starts", std::to_string(start),
                           "each must be above the one before (and above 0) and below the file's " +
                               std::to_string(volume.triangleCount()) + " triangles");
        previous = start;
      }
      volume.partStarts = o->partStarts;
      const MeshCheckReport r = checkMesh(volume);
      const std::string failed = failures(r);
      if (o->json) {
        nlohmann::json j = meshCheckJson(r);
        j["file"] = o->mesh;
        j["failed"] = failed.empty() ? nlohmann::json() : nlohmann::json(failed);
        j["shadowvolVersion"] = SHADOWVOL_VERSION;
        std::cout << jsonText(j) << '\n';
      } else {
        std::printf("%s: %s\n", o->mesh.c_str(), r.summary().c_str());
        const char* valid = r.triangles == 0 ? "valid: an empty volume (no triangles: nothing in shadow)"
                                             : "valid: a closed, outward, finite volume";
        std::printf("%s\n", failed.empty() ? valid : ("NOT VALID: " + failed).c_str());
      }
      return failed.empty() ? kOk : kValidationFailed;
    };
  });
}

}  // namespace shadowvol::cli
