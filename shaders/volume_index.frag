// (version_430.glsl, light_window_depth.glsl and volume_common.glsl come first.) Listing pass of
// the indexed GPU volume (GpuVolumeDraw::Indexed, exact cap only), drawn into a framebuffer
// without attachments, one fragment per block of 8 x 4 quads: the quads whose corner A lies in
// one word of the light pass's occupancy image (light_mark.frag). Their corners are that word's
// texels, the first column of the word to the right, the first row of the word above and the first
// texel of the word above and to the right. A block whose bits are all clear returns at once; the
// others read the depths of their covered texels (the others are far without a read), and for
// each quad that is not all on the far plane append its triangles, as texel indices, at an
// atomically taken offset of `indices`: the two sheet triangles and, with drawCap, their reversed
// copies on the far plane, with the vertex order of volume_gpu.geom's strips (fixed B-D: ABD, DBC
// and ADB, BDC; flipped A-C: BCA, ACD and BAC, CAD), so that both rasterise alike. Index
// t = j * W + i is texel (i, j) on the sheet, W * H + t the same texel on the far plane; a far sheet
// vertex is its own cap copy (index t), so the two are one vertex. volume_index.vert places the
// vertices. The triangles' order varies from frame to frame; the wrapping stencil does not depend
// on it. Past `capacity` indices nothing is written but the count still grows, so the renderer can
// grow the buffer and run the pass again. At most 32 quads per block (one bit each in keptMask);
// keep kBlock in step with renderer.cpp and light_mark.frag (the GL tests compare the counts with
// the other ways of drawing).
const ivec2 kBlock = ivec2(8, 4);
layout(std430, binding = 0) buffer Count { uint indexCount; };
layout(std430, binding = 1) writeonly buffer Indices { uint indices[]; };
uniform int capacity;          // indices the buffer holds
uniform usampler2D occupancy;  // light_mark.frag's bits; with useOccupancy = 0 every texel is read
uniform int useOccupancy;

uint occupancyWord(ivec2 b) {
  return all(lessThan(b, textureSize(occupancy, 0))) ? texelFetch(occupancy, b, 0).r : 0u;
}

void main() {
  ivec2 b = ivec2(gl_FragCoord.xy);
  ivec2 q0 = b * kBlock;  // corner A of the block's first quad
  // The block's texels and those of its neighbours it shares (all set without occupancy).
  uint here = ~0u, right = ~0u, above = ~0u, aboveRight = ~0u;
  if (useOccupancy != 0) {
    here = occupancyWord(b);
    right = occupancyWord(b + ivec2(1, 0));
    above = occupancyWord(b + ivec2(0, 1));
    aboveRight = occupancyWord(b + ivec2(1, 1));
    if (here == 0u && (right & 0x01010101u) == 0u && (above & 0xffu) == 0u && (aboveRight & 1u) == 0u) return;
  }
  float d[(kBlock.x + 1) * (kBlock.y + 1)];
  for (int y = 0; y <= kBlock.y; ++y)
    for (int x = 0; x <= kBlock.x; ++x) {
      ivec2 t = q0 + ivec2(x, y);
      uint word = y < kBlock.y ? (x < kBlock.x ? here : right) : (x < kBlock.x ? above : aboveRight);
      bool covered = (word & (1u << uint((x % kBlock.x) + kBlock.x * (y % kBlock.y)))) != 0u;
      d[y * (kBlock.x + 1) + x] = covered && all(lessThan(t, size)) ? sheetDepth(t) : farPlane;
    }
  uint keptMask = 0u;
  uint kept = 0u;
  for (int y = 0; y < kBlock.y; ++y)
    for (int x = 0; x < kBlock.x; ++x) {
      int k = y * (kBlock.x + 1) + x;
      if (any(greaterThanEqual(q0 + ivec2(x, y), size - 1))) continue;
      if (d[k] < farPlane || d[k + 1] < farPlane || d[k + kBlock.x + 1] < farPlane || d[k + kBlock.x + 2] < farPlane) {
        keptMask |= 1u << uint(y * kBlock.x + x);
        ++kept;
      }
    }
  if (kept == 0u) return;
  uint n = drawCap != 0 ? 12u : 6u;  // drawCap = 0 (z-pass): the sheet triangles alone
  uint v = atomicAdd(indexCount, n * kept);
  if (v + n * kept > uint(capacity)) return;
  uint texels = uint(size.x * size.y);
  for (int y = 0; y < kBlock.y; ++y)
    for (int x = 0; x < kBlock.x; ++x) {
      if ((keptMask & (1u << uint(y * kBlock.x + x))) == 0u) continue;
      uint s[4], f[4];
      vec3 p[4];
      for (int c = 0; c < 4; ++c) {
        ivec2 o = ivec2(x, y) + kCornerOffset[c];
        float dc = d[o.y * (kBlock.x + 1) + o.x];
        ivec2 t = q0 + o;
        s[c] = uint(t.y * size.x + t.x);
        f[c] = dc < farPlane ? texels + s[c] : s[c];
        p[c] = lightViewPoint(t, dc);
      }
      if (perfect == 0 || !flipDiagonal(p[0], p[1], p[2], p[3])) {
        indices[v] = s[0]; indices[v + 1u] = s[1]; indices[v + 2u] = s[3];
        indices[v + 3u] = s[3]; indices[v + 4u] = s[1]; indices[v + 5u] = s[2];
        if (drawCap != 0) {
          indices[v + 6u] = f[0]; indices[v + 7u] = f[3]; indices[v + 8u] = f[1];
          indices[v + 9u] = f[1]; indices[v + 10u] = f[3]; indices[v + 11u] = f[2];
        }
      } else {
        indices[v] = s[1]; indices[v + 1u] = s[2]; indices[v + 2u] = s[0];
        indices[v + 3u] = s[0]; indices[v + 4u] = s[2]; indices[v + 5u] = s[3];
        if (drawCap != 0) {
          indices[v + 6u] = f[1]; indices[v + 7u] = f[0]; indices[v + 8u] = f[2];
          indices[v + 9u] = f[2]; indices[v + 10u] = f[0]; indices[v + 11u] = f[3];
        }
      }
      v += n;
    }
}
