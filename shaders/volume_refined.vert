// (version_430.glsl, light_window_depth.glsl, volume_common.glsl and refine_common.glsl come
// first.) The refined GPU volume's vertices: gl_VertexID is a vertex index of volume_refined.comp
// (its header comment): a texel's sheet vertex or far-plane point, or a crossing's near vertex,
// far vertex or far-plane point (silhouette_walk.comp's record), to camera clip space.
uniform sampler2DArray crossingRecords;
uniform mat4 lightViewToClip;  // P_camera * V_camera * inverse(V_light), composed in double
void main() {
  uint id = uint(gl_VertexID), texels = uint(size.x * size.y);
  vec3 p;
  if (id < 2u * texels) {
    uint t = id < texels ? id : id - texels;
    ivec2 c = ivec2(int(t % uint(size.x)), int(t / uint(size.x)));
    p = lightViewPoint(c, id < texels ? sheetDepth(c) : farPlane);
  } else {
    uint rel = id - 2u * texels, slot = rel / 3u, k = rel % 3u, t = slot / 2u;
    vec4 record = texelFetch(crossingRecords, ivec3(int(t % uint(size.x)), int(t / uint(size.x)), int(slot % 2u)), 0);
    p = lightViewPointAt(record.xy, k == 0u ? record.z : (k == 1u ? record.w : farPlane));
  }
  gl_Position = lightViewToClip * vec4(p, 1.0);
}
