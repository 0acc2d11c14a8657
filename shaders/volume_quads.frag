// (volume_common.glsl comes first.) One fragment per quad of the GPU volume, on a (W-1) x (H-1)
// R8UI target: 0 = dropped (exact cap and all four corners on the far plane), 1 = fixed diagonal
// B-D, 2 = flipped diagonal A-C. Evaluated once per quad here instead of once per vertex.
layout(location = 0) out uint quadCode;

void main() {
  ivec2 t0 = ivec2(gl_FragCoord.xy);
  vec3 p[4];
  bool allFar = true;
  for (int k = 0; k < 4; ++k) {
    float d = sheetDepth(t0 + kCornerOffset[k]);
    allFar = allFar && !(d < farPlane);
    p[k] = lightViewPoint(t0 + kCornerOffset[k], d);
  }
  if (exactCap != 0 && allFar) {
    quadCode = 0u;
    return;
  }
  quadCode = (perfect != 0 && flipDiagonal(p[0], p[1], p[2], p[3])) ? 2u : 1u;
}
