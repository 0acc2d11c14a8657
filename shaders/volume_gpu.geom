// (volume_common.glsl comes first.) The shadow volume drawn straight from the light-view depth
// texture: one point per quad in (every quad, or only those volume_keep.geom kept), up to two
// triangle strips out. No read-back.
// exactCap = 1: the quad's two sheet triangles (fixed B-D: ABD, BCD; flipped A-C: ABC, ACD) and
//   the same two triangles on the far plane with reversed winding (the quad's share of the exact
//   far cap; not with drawCap = 0, for z-pass); a quad with all four corners on the far plane
//   emits nothing.
// exactCap = 0 (the thesis): the two sheet triangles of every quad; drawRectangle = 1 (a draw of
//   ringVertexCount() points) emits the far-plane rectangle over the texel centres
//   (0,0)..(W-1,H-1), facing away from the light, as a fan from its centre over every ring
//   vertex: point k is the triangle (centre, ring vertex k, ring vertex k + 1). The sheet's ring
//   lies on the rectangle's edges; one triangle per ring edge shares the sheet's vertices there
//   (the same lightViewPoint of the same texel), so the two meet without T-junctions, where a
//   rasteriser's snapping would let a pixel centre on the border fall in one and not the other.
// Strips: triangle k of a strip is (v_k, v_k+1, v_k+2) with odd k reordered by GL, so
//   fixed sheet  A B D C = ABD, BCD      flipped sheet  B C A D = ABC, ACD
//   fixed cap    A D B C = ADB, BDC      flipped cap    B A C D = ACB, ADC (all as listed).
layout(points) in;
layout(triangle_strip, max_vertices = 8) out;
flat in int vQuad[];
uniform mat4 lightViewToClip;  // P_camera * V_camera * inverse(V_light), composed in double
uniform int drawRectangle;     // 1: emit only the far rectangle of exactCap = 0

void emit(vec3 lightViewPosition) {
  gl_Position = lightViewToClip * vec4(lightViewPosition, 1.0);
  EmitVertex();
}

// The ring's vertices in the rectangle's winding (clockwise in texel space, i right and j up:
// up the left side from (0, 0), along the top, down the right side, back along the bottom);
// ringVertex(ringVertexCount()) is ringVertex(0).
int ringVertexCount() { return 2 * (size.x - 1) + 2 * (size.y - 1); }
ivec2 ringVertex(int k) {
  int w = size.x - 1, h = size.y - 1;
  if (k < h) return ivec2(0, k);
  k -= h;
  if (k < w) return ivec2(k, h);
  k -= w;
  if (k < h) return ivec2(w, h - k);
  k -= h;
  return ivec2(w - min(k, w), 0);
}

void main() {
  if (drawRectangle != 0) {
    int k = vQuad[0];
    emit(lightViewPointAt(0.5 * vec2(size - 1), farPlane));  // the centre
    emit(lightViewPoint(ringVertex(k), farPlane));
    emit(lightViewPoint(ringVertex(k + 1), farPlane));
    EndPrimitive();
    return;
  }
  ivec2 t0 = quadCorner(vQuad[0]);
  if (exactCap != 0 && quadAllFar(t0)) return;
  float d[4];
  for (int k = 0; k < 4; ++k) d[k] = sheetDepth(t0 + kCornerOffset[k]);
  vec3 p[4], f[4];
  for (int k = 0; k < 4; ++k) {
    p[k] = lightViewPoint(t0 + kCornerOffset[k], d[k]);
    // A far sheet vertex and its cap copy must be bit-identical: reuse the sheet point.
    f[k] = d[k] < farPlane ? lightViewPoint(t0 + kCornerOffset[k], farPlane) : p[k];
  }
  bool flip = perfect != 0 && flipDiagonal(p[0], p[1], p[2], p[3]);
  if (!flip) {
    emit(p[0]); emit(p[1]); emit(p[3]); emit(p[2]);
  } else {
    emit(p[1]); emit(p[2]); emit(p[0]); emit(p[3]);
  }
  EndPrimitive();
  if (exactCap == 0 || drawCap == 0) return;
  if (!flip) {
    emit(f[0]); emit(f[3]); emit(f[1]); emit(f[2]);
  } else {
    emit(f[1]); emit(f[0]); emit(f[2]); emit(f[3]);
  }
  EndPrimitive();
}
