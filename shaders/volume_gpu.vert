#version 330 core
// The shadow volume drawn straight from the light-view depth texture: no vertex buffer, no
// read-back. Quad q = (i, j), i in [0, W-2], j in [0, H-2], corners (triangulation.h):
//   A = (i, j), B = (i+1, j), C = (i+1, j+1), D = (i, j+1).
// Sheet vertex of texel t, as phase 1 of buildVolume: texels of the outermost ring and texels
// without a hit (depth >= farSnap) sit on the far plane; others at clamp(depth + bias, near, far),
// snapped to the far plane when that is >= farSnap.
// exactCap = 1: 12 vertices per quad: its two sheet triangles (fixed B-D: ABD, BCD; flipped A-C:
//   ABC, ACD) and the same two triangles on the far plane with reversed winding (the quad's share
//   of the exact far cap). A quad with all four corners on the far plane is dropped (all its
//   vertices collapse to one point: zero-area triangles draw nothing).
// exactCap = 0 (the thesis): 6 vertices per quad (the full sheet), and in a draw of its own
//   (drawRectangle = 1) the 6 vertices of one far-plane rectangle over the texel centres
//   (0,0)..(W-1,H-1), facing away from the light.
// Large maps are drawn in several calls: quad index = firstQuad + gl_VertexID / vertices per quad.
uniform sampler2D lightDepth;   // R32F light-view depth (world units), >= farPlane = no hit
uniform ivec2 size;             // W, H texels
uniform float farPlane;         // light-view distance of the far plane
uniform float nearPlane;        // light-view distance of the near plane
uniform float farSnap;          // farPlane * (1 - kFarSnap) (depth_blur.h)
uniform float bias;             // world units added to every hit depth (away from the light)
uniform vec4 projXY;            // light projection P00, P11, P30, P31 (m[col][row])
uniform vec2 projShear;         // light projection P20, P21
uniform vec4 projZW;            // light projection P22, P32, P23, P33
uniform mat4 lightViewToClip;   // P_camera * V_camera * inverse(V_light), composed in double
uniform int perfect;            // 1: per-quad diagonal rule (flipDiagonal), 0: fixed B-D
uniform int exactCap;           // see above
uniform float planarTolerance;  // kPlanarTolerance of triangulation.h
uniform int firstQuad;          // quad index of gl_VertexID 0 in this draw call
uniform int drawRectangle;      // 1: this draw is the far rectangle of exactCap = 0

bool onRing(ivec2 t) { return t.x == 0 || t.y == 0 || t.x == size.x - 1 || t.y == size.y - 1; }

float sheetDepth(ivec2 t) {
  if (onRing(t)) return farPlane;
  float d = texelFetch(lightDepth, t, 0).r;
  if (!(d < farSnap)) return farPlane;
  d = clamp(d + bias, nearPlane, farPlane);
  return d < farSnap ? d : farPlane;
}

// Light-view point of the centre of texel t at light-view depth d (the inverse of the projection
// for x and y; z = -d exactly, as TexelUnprojector).
vec3 lightViewPoint(ivec2 t, float d) {
  vec2 ndc = (vec2(t) + 0.5) / vec2(size) * 2.0 - 1.0;
  float z = -d;
  float w = projZW.z * z + projZW.w;
  float x = (ndc.x * w - projShear.x * z - projXY.z) / projXY.x;
  float y = (ndc.y * w - projShear.y * z - projXY.w) / projXY.y;
  return vec3(x, y, z);
}

// triangulation.h's flipDiagonal, line for line, in float.
bool flipDiagonal(vec3 a, vec3 b, vec3 c, vec3 d) {
  float aA = length(cross(c - b, d - b));
  float aB = length(cross(c - a, d - a));
  float aC = length(cross(b - a, d - a));
  float aD = length(cross(b - a, c - a));
  float sixV = abs(dot(b - a, cross(c - a, d - a)));
  float l2 = max(max(max(dot(b - a, b - a), dot(c - a, c - a)), max(dot(d - a, d - a), dot(c - b, c - b))),
                 max(dot(d - b, d - b), dot(d - c, d - c)));
  float l = sqrt(l2);
  if (!(sixV > planarTolerance * l2 * l)) return false;
  return (aB < aC && aB < aA) || (aD < aC && aD < aA);
}

const int kFixed[12] = int[12](0, 1, 3, 1, 2, 3, 0, 3, 1, 1, 3, 2);
const int kFlipped[12] = int[12](0, 1, 2, 0, 2, 3, 0, 2, 1, 0, 3, 2);

void main() {
  int quadsX = size.x - 1;
  if (drawRectangle != 0) {
    ivec2 corner[4] = ivec2[4](ivec2(0, 0), ivec2(size.x - 1, 0), ivec2(size.x - 1, size.y - 1),
                               ivec2(0, size.y - 1));
    const int rect[6] = int[6](0, 3, 2, 0, 2, 1);  // A D C, A C B: facing away from the light
    gl_Position = lightViewToClip * vec4(lightViewPoint(corner[rect[gl_VertexID]], farPlane), 1.0);
    return;
  }
  int perQuad = exactCap != 0 ? 12 : 6;
  int local = gl_VertexID / perQuad;
  int v = gl_VertexID - local * perQuad;
  int q = firstQuad + local;
  ivec2 t0 = ivec2(q - (q / quadsX) * quadsX, q / quadsX);
  ivec2 t[4] = ivec2[4](t0, t0 + ivec2(1, 0), t0 + ivec2(1, 1), t0 + ivec2(0, 1));
  float d[4];
  bool allFar = true;
  for (int k = 0; k < 4; ++k) {
    d[k] = sheetDepth(t[k]);
    allFar = allFar && !(d[k] < farPlane);
  }
  if (exactCap != 0 && allFar) {
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
    return;
  }
  vec3 farP[4], sheetP[4];
  for (int k = 0; k < 4; ++k) {
    farP[k] = lightViewPoint(t[k], farPlane);
    sheetP[k] = d[k] < farPlane ? lightViewPoint(t[k], d[k]) : farP[k];
  }
  bool flip = perfect != 0 && flipDiagonal(sheetP[0], sheetP[1], sheetP[2], sheetP[3]);
  int corner = flip ? kFlipped[v] : kFixed[v];
  vec3 p = v < 6 ? sheetP[corner] : farP[corner];
  gl_Position = lightViewToClip * vec4(p, 1.0);
}
