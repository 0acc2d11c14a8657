// (version_430.glsl, light_window_depth.glsl and volume_common.glsl come first.) Listing pass of
// the indexed GPU volume (GpuVolumeDraw::Indexed, exact cap only), drawn into a framebuffer
// without attachments, one fragment per block of 8 x 4 quads: the quads whose corner A lies in
// one word of the light pass's occupancy image (light_mark.frag). Their corners are that word's
// texels, the first column of the word to the right, the first row of the word above and the first
// texel of the word above and to the right. A block whose bits are all clear returns at once; the
// others read the depths of their covered texels (the others are far without a read), and for
// each quad that is not all on the far plane append its triangles, as texel indices, at an
// atomically taken offset of `indices`: the two sheet triangles and, with drawCap, their reversed
// copies on the far plane (a block of 32 kept quads has its cap as one fan instead, capFan), with
// the vertex order of volume_gpu.geom's strips (fixed B-D: ABD, DBC
// and ADB, BDC; flipped A-C: BCA, ACD and BAC, CAD), so that both rasterise alike. Index
// t = j * W + i is texel (i, j) on the sheet, W * H + t the same texel on the far plane; a far sheet
// vertex is its own cap copy (index t), so the two are one vertex. volume_index.vert places the
// vertices. The triangles' order varies from frame to frame; the wrapping stencil does not depend
// on it. Past `capacity` indices nothing is written but the count still grows, so the renderer can
// grow the buffer and run the pass again. At most 32 quads per block (one bit each in keptMask);
// keep kBlock in step with renderer_gpu_volume.cpp and light_mark.frag (the GL tests compare the counts with
// the other ways of drawing). With skipRefined (the refined GPU volume) a quad with a boundary side
// is left out: volume_refined.comp lists it, so
// a block holding one never gets the fan cap (boundaryFlags: refine_common.glsl's bits).
const ivec2 kBlock = ivec2(8, 4);
layout(std430, binding = 0) buffer Count { uint indexCount; uint quadCount; };
layout(std430, binding = 1) writeonly buffer Indices { uint indices[]; };
uniform int capacity;          // indices the buffer holds
uniform usampler2D occupancy;  // light_mark.frag's bits
uniform int skipRefined;       // 1: leave out the quads with a boundary side (boundaryFlags)
layout(std430, binding = 5) readonly buffer BoundaryFlags { uint boundaryFlags[]; };  // refine_common.glsl's bits

bool refinedQuad(ivec2 q0) {
  if (skipRefined == 0) return false;
  uint a = boundaryFlags[q0.y * size.x + q0.x], b = boundaryFlags[q0.y * size.x + q0.x + 1];
  uint d = boundaryFlags[(q0.y + 1) * size.x + q0.x];
  return ((a & 3u) | (b & 2u) | (d & 1u)) != 0u;  // sides 0 and 3, side 1, side 2
}

// Vertex indices (volume_index.vert): texel t on the sheet, and its copy on the far plane, which
// for a far texel (sheet depth d on the far plane) is the sheet vertex itself.
uint sheetIndex(ivec2 t) { return uint(t.y * size.x + t.x); }
uint capIndex(ivec2 t, float d) { return d < farPlane ? uint(size.x * size.y) + sheetIndex(t) : sheetIndex(t); }

uint occupancyWord(ivec2 b) {
  return all(lessThan(b, textureSize(occupancy, 0))) ? texelFetch(occupancy, b, 0).r : 0u;
}

// The far cap of a block whose 32 quads are all kept: the rectangle over its texels on the far
// plane as a fan of kFanTriangles (24) around its texel (4, 2), through every texel of its border in
// turn, so that it meets its neighbours' caps and the sheet's far edges at the same vertices (no
// T-junction) with 24 triangles instead of 64. Its triangles turn the way the per-quad cap
// triangles do (clockwise in texel coordinates, away from the light). `d` is the block's sheet
// depths as in main (a far texel is its own cap vertex).
const uint kFanTriangles = uint(2 * (kBlock.x + kBlock.y));
ivec2 borderTexel(int k) {  // counterclockwise from texel (0, 0): bottom, right, top, left
  if (k < kBlock.x) return ivec2(k, 0);
  if (k < kBlock.x + kBlock.y) return ivec2(kBlock.x, k - kBlock.x);
  if (k < 2 * kBlock.x + kBlock.y) return ivec2(2 * kBlock.x + kBlock.y - k, kBlock.y);
  return ivec2(0, 2 * (kBlock.x + kBlock.y) - k);
}
void capFan(ivec2 q0, float d[(kBlock.x + 1) * (kBlock.y + 1)], uint v) {
  ivec2 c = kBlock / 2;
  uint centre = capIndex(q0 + c, d[c.y * (kBlock.x + 1) + c.x]);
  for (int k = 0; k < int(kFanTriangles); ++k) {
    ivec2 a = borderTexel(k), b = borderTexel((k + 1) % int(kFanTriangles));
    uint ia = capIndex(q0 + a, d[a.y * (kBlock.x + 1) + a.x]);
    uint ib = capIndex(q0 + b, d[b.y * (kBlock.x + 1) + b.x]);
    indices[v] = centre; indices[v + 1u] = ib; indices[v + 2u] = ia;
    v += 3u;
  }
}

void main() {
  ivec2 b = ivec2(gl_FragCoord.xy);
  ivec2 q0 = b * kBlock;  // corner A of the block's first quad
  // The block's texels and those of its neighbours it shares.
  uint here = occupancyWord(b), right = occupancyWord(b + ivec2(1, 0));
  uint above = occupancyWord(b + ivec2(0, 1)), aboveRight = occupancyWord(b + ivec2(1, 1));
  if (here == 0u && (right & 0x01010101u) == 0u && (above & 0xffu) == 0u && (aboveRight & 1u) == 0u) return;
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
      if (any(greaterThanEqual(q0 + ivec2(x, y), size - 1)) || refinedQuad(q0 + ivec2(x, y))) continue;
      if (d[k] < farPlane || d[k + 1] < farPlane || d[k + kBlock.x + 1] < farPlane || d[k + kBlock.x + 2] < farPlane) {
        keptMask |= 1u << uint(y * kBlock.x + x);
        ++kept;
      }
    }
  if (kept == 0u) return;
  // A block of 32 kept quads gets its far cap as one fan (capFan) instead of two triangles per quad.
  bool fan = drawCap != 0 && keptMask == 0xffffffffu;
  uint n = drawCap != 0 && !fan ? 12u : 6u;  // per quad; drawCap = 0 (z-pass): the sheet alone
  uint total = n * kept + (fan ? 3u * kFanTriangles : 0u);
  uint v = atomicAdd(indexCount, total);
  atomicAdd(quadCount, kept);
  if (v + total > uint(capacity)) return;
  if (fan) {
    capFan(q0, d, v);
    v += 3u * kFanTriangles;
  }
  for (int y = 0; y < kBlock.y; ++y)
    for (int x = 0; x < kBlock.x; ++x) {
      if ((keptMask & (1u << uint(y * kBlock.x + x))) == 0u) continue;
      uint s[4], f[4];
      vec3 p[4];
      for (int c = 0; c < 4; ++c) {
        ivec2 o = ivec2(x, y) + kCornerOffset[c];
        float dc = d[o.y * (kBlock.x + 1) + o.x];
        ivec2 t = q0 + o;
        s[c] = sheetIndex(t);
        f[c] = capIndex(t, dc);
        p[c] = lightViewPoint(t, dc);
      }
      bool cap = n == 12u;
      if (perfect == 0 || !flipDiagonal(p[0], p[1], p[2], p[3])) {
        indices[v] = s[0]; indices[v + 1u] = s[1]; indices[v + 2u] = s[3];
        indices[v + 3u] = s[3]; indices[v + 4u] = s[1]; indices[v + 5u] = s[2];
        if (cap) {
          indices[v + 6u] = f[0]; indices[v + 7u] = f[3]; indices[v + 8u] = f[1];
          indices[v + 9u] = f[1]; indices[v + 10u] = f[3]; indices[v + 11u] = f[2];
        }
      } else {
        indices[v] = s[1]; indices[v + 1u] = s[2]; indices[v + 2u] = s[0];
        indices[v + 3u] = s[0]; indices[v + 4u] = s[2]; indices[v + 5u] = s[3];
        if (cap) {
          indices[v + 6u] = f[1]; indices[v + 7u] = f[0]; indices[v + 8u] = f[2];
          indices[v + 9u] = f[2]; indices[v + 10u] = f[0]; indices[v + 11u] = f[3];
        }
      }
      v += n;
    }
}
