// Procedural primitives in object space (centred at the origin, Y up), counter-clockwise seen from
// outside. All closed (watertight, shared vertices) except the plane, a single-sided square.
#pragma once

#include "shadowvol/triangle_mesh.h"

namespace shadowvol {

/// Square in the XZ plane facing +Y, sizeX x sizeZ, split into subdivisions^2 cells (2 triangles
/// each). Single-sided and open.
TriangleMesh makePlane(double sizeX, double sizeZ, int subdivisions);

/// UV sphere: `segments` around Y (>= 3), `rings` from pole to pole (>= 2);
/// 2 * segments * (rings - 1) triangles.
TriangleMesh makeUvSphere(double radius, int segments, int rings);

/// Icosphere: an icosahedron subdivided `detail` times (0..8), 20 * 4^detail triangles.
TriangleMesh makeIcoSphere(double radius, int detail);

/// Axis-aligned box sizeX x sizeY x sizeZ, 12 triangles.
TriangleMesh makeBox(double sizeX, double sizeY, double sizeZ);

/// Closed cylinder along Y from y = -height/2 to +height/2, `segments` around (>= 3),
/// 4 * segments triangles (side quads plus fan caps).
TriangleMesh makeCylinder(double radius, double height, int segments);

/// Closed hemisphere (dome over y = 0, flat disc closing it): the grazing-light test body.
TriangleMesh makeHemisphere(double radius, int segments, int rings);

/// A "tree": a thin cylindrical trunk standing on y = 0 with an icosphere crown on top;
/// two closed meshes appended (they overlap; each is closed on its own).
TriangleMesh makeTree(double trunkRadius, double trunkHeight, double crownRadius, int detail);

}  // namespace shadowvol
