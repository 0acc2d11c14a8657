// A point light's dual-paraboloid projection, the mirror of dual_paraboloid.h (keep in step:
// tests/gl/test_dual_paraboloid_gl.cpp draws the maps and checks them against its C++ side).
// Included after a version_*.glsl file.
uniform mat4 paraboloidToFront;  // world offset -> the front hemisphere's frame (rotation only)
uniform vec2 paraboloidRange;    // the stored distance range: near, far (world units)

// World offset -> hemisphere h's frame (0 front; 1 back: half a turn about the frame's x axis).
vec3 paraboloidFrameOffset(vec3 worldOffset, int h) {
  vec3 f = (paraboloidToFront * vec4(worldOffset, 0.0)).xyz;
  return h == 0 ? f : vec3(f.x, -f.y, -f.z);
}

// The disc point of a frame offset: d.xy / (1 + d.z), d its direction (the frame's axis for the
// light itself). 1 + d.z is kept from 0 for the point straight behind, which the caller clips.
vec2 paraboloidXy(vec3 frameOffset) {
  float l = length(frameOffset);
  vec3 d = l > 0.0 ? frameOffset / l : vec3(0.0, 0.0, 1.0);
  return d.xy / max(1.0 + d.z, 1e-6);
}

// Stored value of a distance: 1 - (distance - near) / (far - near), reversed as the other maps.
float paraboloidStoredDepth(float distance) {
  return 1.0 - (distance - paraboloidRange.x) / (paraboloidRange.y - paraboloidRange.x);
}
