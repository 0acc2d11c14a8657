#version 330 core
// The depth blur of volume_builder.h, mirrored: for texel (i, j), 9 samples at offsets
// {-1.5, 0, +1.5}^2 texels, each a bilinear interpolation (texel centres at integer coordinates,
// clamp to edge) over the VALID texels with non-zero weight only (depth < farSnap, i.e.
// isFarDepth of depth_blur.h is false), weights renormalised; a sample without such a texel is
// skipped; the result is the mean of the valid samples plus blurOffset.
// An invalid centre texel is passed through unchanged.
uniform sampler2D lightDepth;  // R32F light-view depth, >= farPlane = no hit
uniform ivec2 size;            // W, H texels
uniform float farSnap;      // farPlane * (1 - kFarSnap): depths at or beyond are invalid
uniform float blurOffset;      // world units, away from the light
layout(location = 0) out float blurred;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  float c = texelFetch(lightDepth, p, 0).r;
  if (!(c < farSnap)) {
    blurred = c;
    return;
  }
  float sum = 0.0;
  int n = 0;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      vec2 s = vec2(p) + 1.5 * vec2(float(dx), float(dy));
      vec2 s0 = floor(s);
      vec2 f = s - s0;
      ivec2 i0 = ivec2(s0);
      float acc = 0.0, wsum = 0.0;
      for (int b = 0; b <= 1; ++b) {
        for (int a = 0; a <= 1; ++a) {
          float w = (a == 1 ? f.x : 1.0 - f.x) * (b == 1 ? f.y : 1.0 - f.y);
          ivec2 q = clamp(i0 + ivec2(a, b), ivec2(0), size - 1);
          float d = texelFetch(lightDepth, q, 0).r;
          if (w > 0.0 && d < farSnap) {
            acc += w * d;
            wsum += w;
          }
        }
      }
      if (wsum > 0.0) {
        sum += acc / wsum;
        n += 1;
      }
    }
  }
  blurred = sum / float(n) + blurOffset;  // n >= 1: the centre sample is valid
}
