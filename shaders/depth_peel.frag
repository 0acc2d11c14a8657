#version 330 core
// Second depth layer (midpoint capture): keep only fragments strictly behind the first layer at
// the same texel, so the depth test leaves the second-nearest surface.
uniform sampler2D firstLayer;  // window depth (reversed Z: larger = nearer) of the first layer
void main() {
  if (gl_FragCoord.z >= texelFetch(firstLayer, ivec2(gl_FragCoord.xy), 0).r) discard;
}
