// Light pass of a dual-paraboloid map, optionally subdivided: each triangle is cut into s x s
// smaller ones (s = 1, 2, 4 or 8, the power of two that brings its widest corner-to-corner angle
// seen from the light under `subdivisionAngle`, at most `maxSubdivision`), whose corners lie on
// the triangle, and each corner is projected as light_paraboloid.vert would: edges and depths are
// still interpolated straight in the disc, but over a smaller angle. maxSubdivision 1 = the
// tutorial's pass (dual_paraboloid.h).
layout(triangles) in;
layout(triangle_strip, max_vertices = 80) out;  // s = 8: 8 strips of 2 (8 - row) + 1 vertices
in vec3 frameOffset[];                          // the corner in its hemisphere's frame
uniform int maxSubdivision;                     // 1, 2, 4 or 8
uniform float subdivisionAngle;                 // radians
out float gl_ClipDistance[1];

void emitCorner(vec3 f) {
  gl_ClipDistance[0] = f.z;
  gl_Position = vec4(paraboloidXy(f), paraboloidStoredDepth(length(f)), 1.0);
  EmitVertex();
}

float angleBetween(vec3 a, vec3 b) {
  float la = length(a), lb = length(b);
  if (la <= 0.0 || lb <= 0.0) return 3.14159265;  // a corner at the light: as wide as can be
  return acos(clamp(dot(a, b) / (la * lb), -1.0, 1.0));
}

void main() {
  vec3 a = frameOffset[0], b = frameOffset[1], c = frameOffset[2];
  float widest = max(angleBetween(a, b), max(angleBetween(b, c), angleBetween(c, a)));
  int s = 1;
  while (s < maxSubdivision && widest / float(s) > subdivisionAngle) s *= 2;
  // Row i of the barycentric grid: the strip between lines i and i + 1 of the points
  // a + (c - a) u + (b - a) v (u, v multiples of 1 / s), in the order that gives its first
  // triangle, and so all (strips keep one winding), the winding of a, b, c.
  float t = 1.0 / float(s);
  for (int i = 0; i < s; ++i) {
    for (int k = 0; k <= s - i; ++k) {
      emitCorner(a + (c - a) * (float(k) * t) + (b - a) * (float(i) * t));
      if (k < s - i) emitCorner(a + (c - a) * (float(k) * t) + (b - a) * (float(i + 1) * t));
    }
    EndPrimitive();
  }
}
