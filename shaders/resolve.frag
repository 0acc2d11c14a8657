#version 330 core
// Window depth of the light's layer(s) -> light-view depth (world units, -z in light view).
// Output 0 (R32F): the depth, or farPlane where the light saw nothing (the "no hit" value of the
// GPU volume path: texels at or beyond the far plane are invalid, as kNoHit on the CPU).
// gl_FragDepth: the window depth of the same quantity, for the shadow-map baselines (midpoint).
uniform sampler2D layer0;    // first layer window depth, reversed Z (1 = near, cleared to 0 = no hit)
uniform sampler2D layer1;    // second layer window depth (midpoint only)
uniform int midpoint;        // 1: mean of the first and second layer (second missing = far plane)
uniform vec4 depthParams;    // reversed-Z light projection P22, P32, P23, P33 (column-major m[col][row])
uniform float farPlane;      // light-view distance of the far plane
layout(location = 0) out float lightDepth;

// With glClipControl ZERO_TO_ONE the window depth is clip z / w itself (renderer.cpp's
// viewDepthFromWindow is the double mirror).
float viewDepth(float window) {
  float z = (window * depthParams.w - depthParams.y) / (depthParams.x - window * depthParams.z);
  return -z;
}
float windowDepth(float d) {
  float z = -d;
  return (depthParams.x * z + depthParams.y) / (depthParams.z * z + depthParams.w);
}

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  float w0 = texelFetch(layer0, p, 0).r;
  if (w0 <= 0.0) {
    lightDepth = farPlane;
    gl_FragDepth = 0.0;
    return;
  }
  float d = viewDepth(w0);
  if (midpoint != 0) {
    float w1 = texelFetch(layer1, p, 0).r;
    float d1 = w1 <= 0.0 ? farPlane : viewDepth(w1);
    d = 0.5 * (d + d1);
    gl_FragDepth = clamp(windowDepth(d), 0.0, 1.0);
  } else {
    gl_FragDepth = w0;
  }
  lightDepth = min(d, farPlane);
}
