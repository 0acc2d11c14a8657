// (volume_common.glsl and cube_common.glsl come first.) The GPU cube volume of a point light, its
// geometry-shader way (GpuVolumeDraw::AllQuads; docs/gpu.md "The GPU cube volume"): the cells of
// cube::Grid (shadowvol/cube_grid.h) drawn straight from the six faces' light-view depths, as
// buildCubeVolume (cube_volume.h) places them, with no read-back.
// One point per cell in, up to two triangle strips out:
//   - the sheet: each corner texel at its sheet depth (volume_common.glsl's sheetDepthOfTexel: no
//     border ring, the cube has none) on its texel centre's ray, light + d (D + x R + y U) as
//     cubeTexelDirection; a quad's diagonal by flipDiagonal on the light-relative points;
//   - the exact far cap: the same triangles at the far plane (each ray at face depth far: in the
//     face's far plane for an inner quad, a chord of the far cube across an edge), reversed;
//     not with drawCap = 0 (never set for a point light: its volume is counted by z-fail).
// A cell whose corners all lie on the far plane emits nothing; a cell with an all-far triangle
// emits it on the sheet and on the cap, bit-identical and of opposite orientation, so the two
// cancel in the stencil (buildCubeVolume drops such triangles and closes the rest by its cap).
// Positions are light-relative, world axes; lightToClip = P_camera V_camera T(light), composed
// in double on the CPU.
layout(points) in;
layout(triangle_strip, max_vertices = 8) out;
flat in ivec4 vCell[];
uniform mat4 lightToClip;

void emit(vec3 lightRelative) {
  gl_Position = lightToClip * vec4(lightRelative, 1.0);
  EmitVertex();
}

void main() {
  bool triangle = vCell[0].z < 0;
  int corners = triangle ? 3 : 4;
  int id[4] = int[4](vCell[0].x, vCell[0].y, triangle ? vCell[0].w : vCell[0].z, vCell[0].w);
  float d[4];
  vec3 p[4], f[4];
  bool allFar = true;
  for (int k = 0; k < 4; ++k) {
    if (k >= corners) break;
    ivec3 t = cubeTexel(id[k]);
    d[k] = cubeSheetDepth(t);
    vec3 dir = cubeDirection(t);
    p[k] = d[k] * dir;
    // A far sheet vertex and its cap copy must be bit-identical: reuse the sheet point.
    f[k] = d[k] < farPlane ? farPlane * dir : p[k];
    allFar = allFar && !(d[k] < farPlane);
  }
  if (allFar) return;
  if (triangle) {  // A, B, D of the quad it would be (corners 0, 1, 2 here): sheet ABD, cap ADB
    emit(p[0]); emit(p[1]); emit(p[2]);
    EndPrimitive();
    if (drawCap == 0) return;
    emit(f[0]); emit(f[2]); emit(f[1]);
    EndPrimitive();
    return;
  }
  // Strips as volume_gpu.geom's: fixed sheet A B D C, flipped B C A D; caps A D B C, B A C D.
  bool flip = perfect != 0 && flipDiagonal(p[0], p[1], p[2], p[3]);
  if (!flip) {
    emit(p[0]); emit(p[1]); emit(p[3]); emit(p[2]);
  } else {
    emit(p[1]); emit(p[2]); emit(p[0]); emit(p[3]);
  }
  EndPrimitive();
  if (drawCap == 0) return;
  if (!flip) {
    emit(f[0]); emit(f[3]); emit(f[1]); emit(f[2]);
  } else {
    emit(f[1]); emit(f[0]); emit(f[2]); emit(f[3]);
  }
  EndPrimitive();
}
