// Light pass of a dual-paraboloid map (dual_paraboloid.h): a vertex's offset in its hemisphere's
// frame; light_paraboloid.geom projects it (disc point, stored depth, the other hemisphere
// clipped away by gl_ClipDistance[0] = frame z). As in the reference tutorial the projection is
// per vertex (of the triangle, or of its subdivision), so edges and depths are interpolated
// straight in the disc: exact at the vertices, approximate across a triangle that spans a large
// angle (the method's distortion; docs/gpu.md "Dual-paraboloid maps").
layout(location = 0) in vec3 position;  // world
uniform vec3 lightPosition;             // world
uniform int hemisphere;                 // 0 front, 1 back
out vec3 frameOffset;                   // to light_paraboloid.geom, which projects
void main() {
  frameOffset = paraboloidFrameOffset(position - lightPosition, hemisphere);
}
