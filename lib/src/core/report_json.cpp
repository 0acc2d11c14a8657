#include "shadowvol/report_json.h"

#include "shadowvol/dual_paraboloid.h"

#include "shadowvol/light.h"

namespace shadowvol {

nlohmann::json describeScene(const Scene& s) {
  // Positions in world units (stored + origin); directions need no origin.
  auto v3 = [](const glm::dvec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); };
  auto w3 = [&](const glm::dvec3& v) { return v3(v + s.origin); };
  auto describeLight = [&](const Light& l) {
    nlohmann::json light = {{"type", toString(l.type)},
                            {"position", w3(l.position)},
                            {"near", l.nearPlane},
                            {"far", l.farPlane},
                            {"intensity", l.intensity}};
    if (l.type != LightType::Point) {  // a point light has neither
      light["direction"] = v3(l.direction);
      light["up"] = v3(lightUp(l));
    }
    if (l.type == LightType::Spot) light["fov"] = l.fovYDegrees;
    if (l.type == LightType::Directional) light["extent"] = l.halfExtent;
    return light;
  };
  const nlohmann::json light = describeLight(s.light);
  const Bounds3 b = s.bounds();
  nlohmann::json j = {{"source", s.source},
          {"objects", s.objects.size()},
          {"triangles", s.triangleCount()},
          {"origin", v3(s.origin)},
          {"bounds", {{"min", w3(b.min)}, {"max", w3(b.max)}}},
          {"light", light},
          {"camera",
           {{"eye", w3(s.camera.eye)},
            {"target", w3(s.camera.target)},
            {"up", v3(s.camera.up)},
            {"fov", s.camera.fovYDegrees},
            {"width", s.camera.width},
            {"height", s.camera.height},
            {"near", s.camera.nearPlane},
            {"far", s.camera.farPlane}}}};
  if (s.lightCount() > 1) {
    j["lights"] = nlohmann::json::array();
    for (std::size_t k = 0; k < s.lightCount(); ++k) j["lights"].push_back(describeLight(s.lightAt(k)));
  }
  return j;
}

nlohmann::json describeVolumeStats(const VolumeBuildStats& s) {
  return {{"quads", s.quads},
          {"droppedQuads", s.droppedQuads},
          {"flippedQuads", s.flippedQuads},
          {"flippedFraction", s.quads ? double(s.flippedQuads) / double(s.quads) : 0.0},
          {"capTrianglesBefore", s.capTrianglesBefore},
          {"capTrianglesAfter", s.capTrianglesAfter},
          {"splitVertices", s.splitVertices},
          {"boundaryEdges", s.boundaryEdges},
          {"farBoundaryEdges", s.farBoundaryEdges},
          {"refinedCells", s.refinedCells},
          {"ambiguousCells", s.ambiguousCells},
          {"chordPoints", s.chordPoints},
          {"subgridQuads", s.subgridQuads},
          {"subgridSamples", s.subgridSamples},
          {"subgridBoundaryEdges", s.subgridBoundaryEdges},
          {"subgridFarBoundaryEdges", s.subgridFarBoundaryEdges},
          {"subgridSplitTriangles", s.subgridSplitTriangles},
          {"hiddenQuads", s.hiddenQuads},
          {"rimQuads", s.rimQuads},
          {"creaseQuads", s.creaseQuads},
          {"thinQuads", s.thinQuads},
          {"thinRays", s.thinRays},
          {"plainBends", s.plainBends},
          {"subgridBiasSamples", s.subgridBiasSamples},
          {"rimCrossings", s.rimCrossings},
          {"raysCast", s.raysCast},
          {"crossingFallbacks", s.crossingFallbacks},
          {"snappedCrossings", s.snappedCrossings},
          {"prismFaces", s.prismFaces},
          {"prismWalls", s.prismWalls},
          {"prismTriangles", s.prismTriangles},
          {"prismColumnTexels", s.prismColumnTexels},
          {"bias", s.biasUsed},
          {"ms", {{"blur", s.msBlur}, {"sheet", s.msSheet}, {"refine", s.msRefine}, {"rays", s.msRays}, {"hidden", s.msHidden}, {"prisms", s.msPrisms},
                  {"cap", s.msCap}, {"total", s.msTotal}}}};
}

nlohmann::json describeDualParaboloid(int cubeFaceSide) {
  const int side = dualParaboloidSide(cubeFaceSide);
  const TexelSolidAngles p = paraboloidTexelSolidAngles(side), c = cubeTexelSolidAngles(cubeFaceSide);
  auto angles = [](const TexelSolidAngles& a, double texels) {
    return nlohmann::json{{"texels", texels},
                          {"usedFraction", a.usedFraction},
                          {"smallestTexelSr", a.smallest},
                          {"largestTexelSr", a.largest},
                          {"largestOverSmallest", a.largest / a.smallest}};
  };
  nlohmann::json j = angles(p, 2.0 * side * side);
  j["side"] = side;
  j["cubeMap"] = angles(c, 6.0 * cubeFaceSide * cubeFaceSide);
  j["cubeMap"]["side"] = cubeFaceSide;
  j["largestTexelOverCubes"] = p.largest / c.largest;
  return j;
}

std::string jsonText(const nlohmann::json& j, int indent) {
  return j.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace shadowvol
