// (version_330.glsl and light_window_depth.glsl come first.) Window depth of the light's
// layer(s) -> light-view depth (world units, -z in light view).
// Output 0 (R32F): the depth, or farPlane where the light saw nothing (the "no hit" value of the
// GPU volume path: texels at or beyond the far plane are invalid, as kNoHit on the CPU).
// gl_FragDepth: the window depth of the same quantity, for the shadow-map baselines (midpoint,
// entry).
uniform sampler2D layer0;    // first layer window depth, reversed Z (1 = near, cleared to 0 = no hit)
uniform sampler2D layer1;    // second layer window depth (midpoint: the next surface; entry: the nearest back face)
uniform int layers;          // 0: layer0 alone; 1 (midpoint): mean of the two layers (second missing = far
                             // plane); 2 (entry): layer0 where layer1 has a back face, else no hit
uniform float farPlane;      // light-view distance of the far plane
layout(location = 0) out float lightDepth;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  float w0 = texelFetch(layer0, p, 0).r;
  float w1 = texelFetch(layer1, p, 0).r;
  if (layers == 2 && w1 <= 0.0) w0 = 0.0;  // entry: no back face behind, nothing recorded
  if (layers != 1 || w0 <= 0.0) {
    lightDepth = capturedDepth(w0, farPlane);  // what the indexed GPU volume reads itself
    gl_FragDepth = max(w0, 0.0);
    return;
  }
  float d = 0.5 * (viewDepth(w0) + (w1 <= 0.0 ? farPlane : viewDepth(w1)));
  gl_FragDepth = clamp(windowDepth(d), 0.0, 1.0);
  lightDepth = min(d, farPlane);
}
