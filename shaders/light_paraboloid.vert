// Light pass of a dual-paraboloid map (dual_paraboloid.h): a vertex's disc point and stored
// depth in its hemisphere, the other hemisphere clipped away (gl_ClipDistance[0] = frame z). As
// in the reference tutorial the projection is per vertex, so a triangle's edges and depths are
// interpolated straight in the disc: the map is exact at the vertices, approximate across a
// triangle that spans a large angle (the method's distortion; docs/gpu.md "Dual-paraboloid maps").
layout(location = 0) in vec3 position;  // world
uniform vec3 lightPosition;             // world
uniform int hemisphere;                 // 0 front, 1 back
out float gl_ClipDistance[1];
void main() {
  vec3 f = paraboloidFrameOffset(position - lightPosition, hemisphere);
  gl_ClipDistance[0] = f.z;
  gl_Position = vec4(paraboloidXy(f), paraboloidStoredDepth(length(f)), 1.0);
}
