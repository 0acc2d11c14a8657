// Shared by resolve.frag and volume_common.glsl (a version_*.glsl file comes first): the light
// pass's reversed-Z window depth <-> light-view depth (world units, -z in light view). With
// glClipControl ZERO_TO_ONE the window depth is clip z / w itself (renderer_impl.h's
// viewDepthFromWindow is the double mirror).
uniform vec4 depthParams;  // reversed-Z light projection P22, P32, P23, P33 (column-major m[col][row])

float viewDepth(float window) {
  float z = (window * depthParams.w - depthParams.y) / (depthParams.x - window * depthParams.z);
  return -z;
}
float windowDepth(float d) {
  float z = -d;
  return (depthParams.x * z + depthParams.y) / (depthParams.z * z + depthParams.w);
}

// Light-view depth of one layer's window depth w, as the resolve pass stores it: the far-plane
// distance where the light saw nothing (w cleared to 0), never beyond it.
float capturedDepth(float w, float farPlane) {
  return w <= 0.0 ? farPlane : min(viewDepth(w), farPlane);
}
