// (version_330.glsl and volume_common.glsl come first.) The vertices of the indexed GPU volume
// (volume_index.frag lists its triangles): gl_VertexID is the index, t = j * W + i for texel
// (i, j) on the sheet (at its sheet depth, the geometry shader's rule), W * H + t for the same
// texel on the far plane. Each vertex is placed once per use in the vertex cache, not once per
// quad corner as in the geometry shader.
uniform mat4 lightViewToClip;  // P_camera * V_camera * inverse(V_light), composed in double
void main() {
  int texels = size.x * size.y;
  bool cap = gl_VertexID >= texels;
  int t = cap ? gl_VertexID - texels : gl_VertexID;
  ivec2 texel = ivec2(t - (t / size.x) * size.x, t / size.x);
  float d = cap ? farPlane : sheetDepth(texel);
  gl_Position = lightViewToClip * vec4(lightViewPoint(texel, d), 1.0);
}
