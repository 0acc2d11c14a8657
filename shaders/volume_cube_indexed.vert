// (version_430.glsl, light_window_depth.glsl, volume_common.glsl and cube_common.glsl come first.)
// The vertices of the indexed GPU cube volume (volume_cube_list.comp lists its triangles):
// gl_VertexID is the index, 2 t for texel t on the sheet (at its sheet depth), 2 t + 1 for the
// same texel on the far plane (only listed for texels off it), placed as volume_cube.geom places
// them, light-relative, then by lightToClip.
uniform mat4 lightToClip;
void main() {
  ivec3 t = cubeTexel(gl_VertexID >> 1);
  float d = (gl_VertexID & 1) != 0 ? farPlane : cubeSheetDepth(t);
  gl_Position = lightToClip * vec4(d * cubeDirection(t), 1.0);
}
