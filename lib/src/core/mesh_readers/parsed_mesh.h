// What the readers parse (OBJ, OFF, PLY, STL, and the Assimp reader's meshes placed by their
// nodes), before it is stored in float: positions in double, so that a mesh far from its file's
// origin can be rebased before the rounding (README "Scene files").
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "shadowvol/triangle_mesh.h"

namespace shadowvol::mesh_readers {

/// How finely a file's float coordinates place (a part of) a mesh: its extent and the largest
/// magnitude of its coordinates, as the file stores them. Detail finer than a float step there is
/// gone before any rebasing can help.
struct FloatPlacement {
  double extent = 0.0, reach = 0.0;
  /// Float steps across the part at its distance from the file's origin; infinite for none.
  double steps() const;
  /// The placement of `points` (the bounding box of float values).
  static FloatPlacement of(std::span<const glm::dvec3> points);
  /// The one of `a` and `b` with fewer steps.
  static FloatPlacement worse(const FloatPlacement& a, const FloatPlacement& b);
};

/// A mesh as parsed: every position finite and within float's range (the readers check it).
/// `weldCorners` (STL, Assimp): positions whose stored (float) values are bit-identical (0 and -0
/// alike) become one vertex when stored, numbered in the order of the positions.
struct ParsedMesh {
  /// A polygon of more than 3 corners, fanned into `count` triangles from triangles[first].
  struct Polygon {
    std::uint64_t first = 0;
    std::uint32_t count = 0;
  };
  std::vector<glm::dvec3> positions;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<Polygon> polygons;  ///< polygon_fan.h
  bool weldCorners = false;
  /// Where the file stores float coordinates (binary STL, binary PLY with float x, y, z, a format
  /// read through Assimp, per mesh as stored before its node places it): the worst part's.
  FloatPlacement floatPlacement;
};

/// Float keeps at least this many steps across a mesh before its reader rebases it: 2^20, about a
/// millionth of its size. Fewer when the mesh lies further than 8 times its size from its file's
/// origin (a survey in map coordinates, a part placed in a large assembly).
inline constexpr double kMinStoredSteps = 1048576.0;

/// Where `parsed` is stored from (world = stored + origin): 0 while float keeps kMinStoredSteps
/// across the vertices its faces use where they lie (every mesh near its file's origin: stored
/// exactly as before), else the centre of their bounding box. The indices must be in range.
glm::dvec3 storageOrigin(const ParsedMesh& parsed);

/// The mesh stored: each position minus `origin` in double, then rounded to float; corners welded
/// when `parsed.weldCorners`.
TriangleMesh storedMesh(const ParsedMesh& parsed, const glm::dvec3& origin);

}  // namespace shadowvol::mesh_readers
