// Shared by the GPU volume's stages (volume_gpu.geom, volume_keep.geom, volume_mesh.comp,
// volume_index.frag, volume_index.vert; the GPU cube volume's volume_cube.geom; and the refined
// GPU volume's with refine_common.glsl after this file: boundary_edges.comp, boundary_unfold.comp,
// walk_slots.comp, silhouette_walk.comp, volume_refined.comp, volume_refined.vert; each program's
// sources are version_330.glsl or version_430.glsl, light_window_depth.glsl, this file, then the
// stage's body): the sheet vertex of a texel, the quads the exact cap drops and the diagonal rule,
// mirroring buildVolume.
//
// Quad q = (i, j), i in [0, W-2], j in [0, H-2], corners (triangulation.h):
//   A = (i, j), B = (i+1, j), C = (i+1, j+1), D = (i, j+1).
// Sheet vertex of texel t, as steps 1-4 of buildVolume (volume_builder.h): texels of the
// outermost ring and texels without a hit (depth >= farSnap) sit exactly on the far plane; others
// at clamp(depth + bias, near, far), snapped to the far plane when that is >= farSnap.
uniform sampler2D lightDepth;   // R32F light-view depth (world units), >= farSnap = no hit; or,
                                // with windowDepthInput, the light pass's first layer itself
uniform int windowDepthInput;   // 1: lightDepth holds reversed-Z window depth, converted here as
                                // the resolve pass does (back and front capture without blur)
uniform ivec2 size;             // W, H texels
uniform float farPlane;         // light-view distance of the far plane
uniform float nearPlane;        // light-view distance of the near plane
uniform float farSnap;          // farPlane * (1 - kFarSnap) (depth_blur.h)
uniform float bias;             // world units added to every hit depth (away from the light)
uniform vec4 projXY;            // light projection P00, P11, P30, P31 (m[col][row])
uniform vec2 projShear;         // light projection P20, P21
uniform vec4 projZW;            // light projection P22, P32, P23, P33
uniform int perfect;            // 1: per-quad diagonal rule (flipDiagonal), 0: fixed B-D
uniform int drawCap;            // 1: emit the far cap (z-fail); 0: the sheet alone (z-pass, zpass.h)
uniform int exactCap;           // 1: exact cap (all-far quads dropped), 0: the thesis's rectangle
uniform float planarTolerance;  // kPlanarTolerance of triangulation.h

const ivec2 kCornerOffset[4] = ivec2[4](ivec2(0, 0), ivec2(1, 0), ivec2(1, 1), ivec2(0, 1));

bool onRing(ivec2 t) { return t.x == 0 || t.y == 0 || t.x == size.x - 1 || t.y == size.y - 1; }

// Steps 1 (without the ring) and 3 for a texel's light-view depth (blurred already, blur.frag,
// when the volume blurs): the far plane when invalid, else the clamped depth, snapped.
float sheetDepthOfTexel(float d) {
  if (!(d < farSnap)) return farPlane;
  d = clamp(d + bias, nearPlane, farPlane);
  return d < farSnap ? d : farPlane;
}

float sheetDepth(ivec2 t) {
  if (onRing(t)) return farPlane;
  float d = texelFetch(lightDepth, t, 0).r;
  if (windowDepthInput != 0) d = capturedDepth(d, farPlane);
  return sheetDepthOfTexel(d);
}

// Texel (i, j) of corner A of quad q (q = j * (W - 1) + i).
ivec2 quadCorner(int q) {
  int quadsX = size.x - 1;
  return ivec2(q - (q / quadsX) * quadsX, q / quadsX);
}

// With the exact cap, a quad whose four corners all lie on the far plane contributes nothing
// (volume_builder.h: such quads are dropped; the cap closes what is left).
bool quadAllFar(ivec2 t0) {
  for (int k = 0; k < 4; ++k)
    if (sheetDepth(t0 + kCornerOffset[k]) < farPlane) return false;
  return true;
}

// Light-view point at texel coordinates u (texel (i, j)'s centre is u = (i, j); the map's edges
// are u = -0.5 and W - 0.5) and light-view depth d (the inverse of the projection for x and y;
// z = -d exactly, as TexelUnprojector).
vec3 lightViewPointAt(vec2 u, float d) {
  vec2 ndc = (u + 0.5) / vec2(size) * 2.0 - 1.0;
  float z = -d;
  float w = projZW.z * z + projZW.w;
  float x = (ndc.x * w - projShear.x * z - projXY.z) / projXY.x;
  float y = (ndc.y * w - projShear.y * z - projXY.w) / projXY.y;
  return vec3(x, y, z);
}
vec3 lightViewPoint(ivec2 t, float d) { return lightViewPointAt(vec2(t), d); }

// The projection's w of a light-view point (> 0 in front of a spot light; 1 for a directional one)
// and its texel coordinates (as lightViewPointAt's u), for w > 0.
float lightClipW(vec3 p) { return projZW.z * p.z + projZW.w; }
vec2 texelOf(vec3 p) {
  vec2 clip = vec2(projXY.x * p.x + projShear.x * p.z + projXY.z, projXY.y * p.y + projShear.y * p.z + projXY.w);
  return (clip / lightClipW(p) + 1.0) * 0.5 * vec2(size) - 0.5;
}

// triangulation.h's flipDiagonal in float: squared areas as there; the planarity test keeps its
// sqrt form here, since in float (L^2)^3 would overflow for coordinates beyond about 4e6.
float sq(vec3 v) { return dot(v, v); }
bool flipDiagonal(vec3 a, vec3 b, vec3 c, vec3 d) {
  float aA = sq(cross(c - b, d - b));
  float aB = sq(cross(c - a, d - a));
  float aC = sq(cross(b - a, d - a));
  float aD = sq(cross(b - a, c - a));
  float sixV = abs(dot(b - a, cross(c - a, d - a)));
  float l2 = max(max(max(dot(b - a, b - a), dot(c - a, c - a)), max(dot(d - a, d - a), dot(c - b, c - b))),
                 max(dot(d - b, d - b), dot(d - c, d - c)));
  float l = sqrt(l2);
  if (!(sixV > planarTolerance * l2 * l)) return false;
  return (aB < aC && aB < aA) || (aD < aC && aD < aA);
}
