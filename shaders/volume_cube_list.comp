// (version_430.glsl, light_window_depth.glsl, volume_common.glsl and cube_common.glsl come
// first.) The indexed way of the GPU cube volume (GpuVolumeDraw::Indexed; docs/gpu.md "The GPU
// cube volume"): each invocation lists one cell's triangles as vertex indices at an atomically
// taken offset of `indices`, with the count in the draw's indirect command (no read-back);
// volume_cube_indexed.vert places the vertices. Index 2 t is texel t on the sheet, 2 t + 1 the
// same texel on the far plane; a far sheet vertex is its own cap copy (2 t).
// The triangles are volume_cube.geom's, in its strips' vertex order (fixed sheet ABD, DBC and cap
// ADB, BDC; flipped sheet BCA, ACD and cap BAC, CAD; a corner triangle ABD and ADB), but a sheet
// triangle with three far corners is left out with its cap image (the two would cancel in the
// stencil), as buildCubeVolume drops it. Two dispatches:
//   - blocks (blockMode = 1): work group (x, y, f) takes face f's inner quads of a 16 x 16 block,
//     in four quadrants of 8 x 8; a quadrant whose 64 cells all keep both triangles has its cap as
//     one fan of 32 triangles around its middle texel (4, 4), through every texel of its border in
//     turn, instead of 128 (its cap is the whole square in the face's far plane; the fan meets the
//     neighbours' caps at the same border vertices, so there is no T-junction);
//   - the seam cells (blockMode = 0): one invocation per cell across the cube's edges and corners.
// Their order varies from frame to frame; the wrapping stencil does not depend on it. The
// renderer sizes `indices` for every cell's 12 (capacity); past it nothing is written, and the
// renderer draws the geometry-shader way instead for sizes whose worst case would not fit.
layout(local_size_x = 256) in;
layout(std430, binding = 0) buffer Command {
  uint indexCount;  // DrawElementsIndirectCommand: count, primCount, firstIndex, baseVertex, baseInstance
  uint instanceCount;
  uint firstIndex;
  int baseVertex;
  uint baseInstance;
  uint cellsKept;   // cells that listed a triangle
};
layout(std430, binding = 1) writeonly buffer Indices { uint indices[]; };
layout(std430, binding = 2) readonly buffer SeamCells { ivec4 seamCells[]; };  // cube::Grid's after the inner quads
uniform int cellCount;  // every cell of cube::Grid
uniform int blockMode;  // 1: the inner quads by blocks; 0: the seam cells
uniform uint capacity;  // indices the buffer holds

// One global atomic per work group: each invocation takes its offset within the group's share
// from a shared counter, one invocation takes the share from the command's.
shared uint groupCount, groupCells, groupBase;
shared bool quadrantPartial[4];  // blocks: a cell of the quadrant is missing or drops a triangle

// The cell's sheet and cap triangles as index triples (volume_cube.geom's strips' vertex order:
// fixed sheet ABD, DBC and cap ADB, BDC; flipped sheet BCA, ACD and cap BAC, CAD; a corner's
// sheet ABD and cap ADB), and which are kept. Written out case by case, without indexing arrays
// by variables (llvmpipe spills those to memory).
struct CellTriangles {
  uvec3 sheet0, cap0, sheet1, cap1;
  bool kept0, kept1;
};

uint cellIndexCount(CellTriangles t) { return (t.kept0 ? 6u : 0u) + (t.kept1 ? 6u : 0u); }

CellTriangles cellTriangles(ivec4 cell) {
  CellTriangles t;
  t.kept0 = t.kept1 = false;
  bool triangle = cell.z < 0;
  // A corner triangle's A, B, D as corners 0, 1, 2 (and 3, a copy of D, unused).
  ivec4 id = triangle ? ivec4(cell.x, cell.y, cell.w, cell.w) : cell;
  ivec3 ta = cubeTexel(id.x), tb = cubeTexel(id.y), tc = cubeTexel(id.z), td = cubeTexel(id.w);
  vec4 d = vec4(cubeSheetDepth(ta), cubeSheetDepth(tb), cubeSheetDepth(tc), cubeSheetDepth(td));
  bvec4 far = not(lessThan(d, vec4(farPlane)));
  if (all(far)) return t;
  uvec4 s = 2u * uvec4(id);
  uvec4 f = s + uvec4(not(far));  // a far texel is its own cap copy
  if (triangle) {
    t.sheet0 = s.xyz;
    t.cap0 = f.xzy;
    t.kept0 = true;  // not all far: the copy of D repeats corner 2
    return t;
  }
  bool flip = perfect != 0 && flipDiagonal(d.x * cubeDirection(ta), d.y * cubeDirection(tb), d.z * cubeDirection(tc),
                                           d.w * cubeDirection(td));
  if (flip) {
    t.sheet0 = s.yzx;  // BCA
    t.cap0 = f.yxz;    // BAC
    t.sheet1 = s.xzw;  // ACD
    t.cap1 = f.zxw;    // CAD
    t.kept0 = !(far.y && far.z && far.x);
    t.kept1 = !(far.x && far.z && far.w);
  } else {
    t.sheet0 = s.xyw;  // ABD
    t.cap0 = f.xwy;    // ADB
    t.sheet1 = s.wyz;  // DBC
    t.cap1 = f.ywz;    // BDC
    t.kept0 = !(far.x && far.y && far.w);
    t.kept1 = !(far.w && far.y && far.z);
  }
  return t;
}

void put(inout uint at, uvec3 sheet, uvec3 cap) {
  indices[at] = sheet.x; indices[at + 1u] = sheet.y; indices[at + 2u] = sheet.z;
  indices[at + 3u] = cap.x; indices[at + 4u] = cap.y; indices[at + 5u] = cap.z;
  at += 6u;
}

// Quadrant border texel k (0..31) counterclockwise from its corner (0, 0): bottom, right, top, left.
ivec2 borderTexel(int k) {
  if (k < 8) return ivec2(k, 0);
  if (k < 16) return ivec2(8, k - 8);
  if (k < 24) return ivec2(24 - k, 8);
  return ivec2(0, 32 - k);
}

uint capIndex(int face, ivec2 texel) {
  int id = (face * cubeSize + texel.y) * cubeSize + texel.x;
  return 2u * uint(id) + (cubeSheetDepth(ivec3(texel, face)) < farPlane ? 1u : 0u);
}

void main() {
  uint l = gl_LocalInvocationIndex;
  if (l == 0u) groupCount = groupCells = 0u;
  if (l < 4u) quadrantPartial[l] = false;
  barrier();
  ivec2 local = ivec2(int(l % 16u), int(l / 16u));
  int face = int(gl_WorkGroupID.z), quadrant = local.x / 8 + 2 * (local.y / 8);
  ivec2 cellAt = ivec2(gl_WorkGroupID.xy) * 16 + local;  // blocks: corner A's texel
  bool inRange;
  ivec4 cell;
  if (blockMode != 0) {
    inRange = cellAt.x < cubeSize - 1 && cellAt.y < cubeSize - 1;
    cell = cubeQuadAt(face, cellAt.x, cellAt.y);
  } else {
    int c = cubeInnerCells() + int(gl_GlobalInvocationID.x);
    inRange = c < cellCount;
    cell = inRange ? seamCells[c - cubeInnerCells()] : ivec4(0);
  }
  CellTriangles t;
  t.kept0 = t.kept1 = false;
  if (inRange) t = cellTriangles(cell);
  if (blockMode != 0 && !(t.kept0 && t.kept1)) quadrantPartial[quadrant] = true;  // the same value from all
  barrier();
  bool fan = blockMode != 0 && !quadrantPartial[quadrant];
  // Within a quadrant, invocation k < 32 (row-major in the quadrant) lists fan triangle k.
  int inQuadrant = (local.y % 8) * 8 + local.x % 8;
  bool fanTriangle = fan && inQuadrant < 32;
  uint sheetCount = (t.kept0 ? 3u : 0u) + (t.kept1 ? 3u : 0u);
  uint count = fan ? sheetCount + (fanTriangle ? 3u : 0u) : 2u * sheetCount;
  uint offset = 0u;
  if (count > 0u) offset = atomicAdd(groupCount, count);
  if (sheetCount > 0u) atomicAdd(groupCells, 1u);
  barrier();
  if (l == 0u && groupCount > 0u) {
    groupBase = atomicAdd(indexCount, groupCount);
    atomicAdd(cellsKept, groupCells);
  }
  barrier();
  if (count == 0u) return;
  uint at = groupBase + offset;
  if (at + count > capacity) return;
  if (fan) {
    if (t.kept0) { indices[at] = t.sheet0.x; indices[at + 1u] = t.sheet0.y; indices[at + 2u] = t.sheet0.z; at += 3u; }
    if (t.kept1) { indices[at] = t.sheet1.x; indices[at + 1u] = t.sheet1.y; indices[at + 2u] = t.sheet1.z; at += 3u; }
    if (fanTriangle) {  // (middle, p_k+1, p_k): clockwise in texel coordinates, away from the light
      ivec2 origin = ivec2(gl_WorkGroupID.xy) * 16 + (local / 8) * 8;
      indices[at] = capIndex(face, origin + ivec2(4, 4));
      indices[at + 1u] = capIndex(face, origin + borderTexel((inQuadrant + 1) % 32));
      indices[at + 2u] = capIndex(face, origin + borderTexel(inQuadrant));
    }
    return;
  }
  if (t.kept0) put(at, t.sheet0, t.cap0);
  if (t.kept1) put(at, t.sheet1, t.cap1);
}
