// (volume_common.glsl comes first.) The shadow volume drawn straight from the light-view depth
// texture: no vertex buffer, no read-back. volume_quads.frag has classified every quad.
// exactCap = 1: 12 vertices per quad: its two sheet triangles (fixed B-D: ABD, BCD; flipped A-C:
//   ABC, ACD) and the same two triangles on the far plane with reversed winding (the quad's share
//   of the exact far cap). A dropped quad collapses all 12 vertices to one point (zero-area
//   triangles draw nothing).
// exactCap = 0 (the thesis): 6 vertices per quad (the full sheet), and in a draw of its own
//   (drawRectangle = 1) the 6 vertices of one far-plane rectangle over the texel centres
//   (0,0)..(W-1,H-1), facing away from the light.
// Large maps are drawn in several calls: quad index = firstQuad + gl_VertexID / vertices per quad.
uniform usampler2D quadCodes;   // (W-1) x (H-1), from volume_quads.frag
uniform mat4 lightViewToClip;   // P_camera * V_camera * inverse(V_light), composed in double
uniform int firstQuad;          // quad index of gl_VertexID 0 in this draw call
uniform int drawRectangle;      // 1: this draw is the far rectangle of exactCap = 0

// Corner (0..3 = A..D) of each of the 12 vertices: sheet triangles, then far triangles reversed.
const int kFixed[12] = int[12](0, 1, 3, 1, 2, 3, 0, 3, 1, 1, 3, 2);
const int kFlipped[12] = int[12](0, 1, 2, 0, 2, 3, 0, 2, 1, 0, 3, 2);

void main() {
  if (drawRectangle != 0) {
    ivec2 corner[4] = ivec2[4](ivec2(0, 0), ivec2(size.x - 1, 0), ivec2(size.x - 1, size.y - 1),
                               ivec2(0, size.y - 1));
    const int rect[6] = int[6](0, 3, 2, 0, 2, 1);  // A D C, A C B: facing away from the light
    gl_Position = lightViewToClip * vec4(lightViewPoint(corner[rect[gl_VertexID]], farPlane), 1.0);
    return;
  }
  int quadsX = size.x - 1;
  int perQuad = exactCap != 0 ? 12 : 6;
  int local = gl_VertexID / perQuad;
  int v = gl_VertexID - local * perQuad;
  int q = firstQuad + local;
  ivec2 t0 = ivec2(q - (q / quadsX) * quadsX, q / quadsX);
  uint code = texelFetch(quadCodes, t0, 0).r;
  if (code == 0u) {
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
    return;
  }
  ivec2 t = t0 + kCornerOffset[code == 2u ? kFlipped[v] : kFixed[v]];
  // One call site for sheet and far vertices, so a far sheet vertex and its cap copy are
  // bit-identical.
  float d = v < 6 ? sheetDepth(t) : farPlane;
  gl_Position = lightViewToClip * vec4(lightViewPoint(t, d), 1.0);
}
