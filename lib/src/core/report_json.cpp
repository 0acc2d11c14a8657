#include "shadowvol/report_json.h"

#include "shadowvol/dual_paraboloid.h"

#include "shadowvol/light.h"

namespace shadowvol {

nlohmann::json describeScene(const Scene& s) {
  // Positions in world units (stored + origin); directions need no origin.
  auto v3 = [](const glm::dvec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); };
  auto w3 = [&](const glm::dvec3& v) { return v3(v + s.origin); };
  nlohmann::json light = {{"type", toString(s.light.type)},
                          {"position", w3(s.light.position)},
                          {"near", s.light.nearPlane},
                          {"far", s.light.farPlane}};
  if (s.light.type != LightType::Point) {  // a point light has neither
    light["direction"] = v3(s.light.direction);
    light["up"] = v3(lightUp(s.light));
  }
  if (s.light.type == LightType::Spot) light["fov"] = s.light.fovYDegrees;
  if (s.light.type == LightType::Directional) light["extent"] = s.light.halfExtent;
  const Bounds3 b = s.bounds();
  return {{"source", s.source},
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
          {"raysCast", s.raysCast},
          {"crossingFallbacks", s.crossingFallbacks},
          {"bias", s.biasUsed},
          {"ms", {{"blur", s.msBlur}, {"sheet", s.msSheet}, {"refine", s.msRefine}, {"rays", s.msRays},
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

}  // namespace shadowvol
