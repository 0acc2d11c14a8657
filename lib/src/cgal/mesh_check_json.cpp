#include "shadowvol/cgal/mesh_check_json.h"

namespace shadowvol {

nlohmann::json meshCheckJson(const MeshCheckReport& m, const std::string& notApplicable) {
  return {{"valid", m.valid()},
          {"vertices", m.vertices},
          {"triangles", m.triangles},
          {"closedManifold", m.closedManifold()},
          {"outward", m.outward},
          {"volume", m.volume},
          {"boundaryEdges", m.boundaryEdges},
          {"overusedEdges", m.overusedEdges},
          {"nonManifoldVertices", m.nonManifoldVertices},
          {"degenerateTriangles", m.degenerateTriangles},
          {"nonFiniteVertices", m.nonFiniteVertices},
          {"badIndexTriangles", m.badIndexTriangles},
          {"isolatedVertices", m.isolatedVertices},
          {"coincidentVertices", m.coincidentVertices},
          {"selfIntersectingPairs",
           m.selfIntersectingPairs ? nlohmann::json(*m.selfIntersectingPairs) : nlohmann::json("not checked")},
          {"allowedTouchingPairs", m.allowedTouchingPairs},
          {"notApplicable", notApplicable.empty() ? nlohmann::json() : nlohmann::json(notApplicable)},
          {"summary", m.summary()}};
}

}  // namespace shadowvol
