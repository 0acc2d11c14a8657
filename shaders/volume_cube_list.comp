// (version_430.glsl, light_window_depth.glsl, volume_common.glsl and cube_common.glsl come
// first.) The indexed way of the GPU cube volume (GpuVolumeDraw::Indexed; docs/gpu.md "The GPU
// cube volume"): one invocation per cell of cube::Grid lists the cell's triangles as vertex
// indices at an atomically taken offset of `indices`, with the count in the draw's indirect
// command (no read-back); volume_cube_indexed.vert places the vertices. Index 2 t is texel t on
// the sheet, 2 t + 1 the same texel on the far plane; a far sheet vertex is its own cap copy (2 t).
// The triangles are volume_cube.geom's, in its strips' vertex order (fixed sheet ABD, DBC and cap
// ADB, BDC; flipped sheet BCA, ACD and cap BAC, CAD; a corner triangle ABD and ADB), but a sheet
// triangle with three far corners is left out with its cap image (the two would cancel in the
// stencil), as buildCubeVolume drops it. Their order varies from frame to frame; the wrapping
// stencil does not depend on it. The renderer sizes `indices` for every cell's 12 (capacity);
// past it nothing is written, and the renderer draws the geometry-shader way instead for sizes
// whose worst case would not fit.
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
uniform int rowLength;  // invocations per row of the dispatch (gl_NumWorkGroups.x * 256)
uniform uint capacity;  // indices the buffer holds

// One global atomic per work group: each invocation takes its offset within the group's share
// from a shared counter, one invocation takes the share from the command's.
shared uint groupCount, groupCells, groupBase;

// The cell's sheet and cap triangles as index triples (volume_cube.geom's strips' vertex order:
// fixed sheet ABD, DBC and cap ADB, BDC; flipped sheet BCA, ACD and cap BAC, CAD; a corner's
// sheet ABD and cap ADB), and which are kept. Written out case by case, without indexing arrays
// by variables (llvmpipe spills those to memory).
struct CellTriangles {
  uvec3 sheet0, cap0, sheet1, cap1;
  bool kept0, kept1;
};

uint cellIndexCount(CellTriangles t) { return (t.kept0 ? 6u : 0u) + (t.kept1 ? 6u : 0u); }

CellTriangles cellTriangles(int c) {
  CellTriangles t;
  t.kept0 = t.kept1 = false;
  if (c >= cellCount) return t;
  int inner = cubeInnerCells();
  ivec4 cell = c < inner ? cubeInnerCell(c) : seamCells[c - inner];
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

void main() {
  if (gl_LocalInvocationIndex == 0u) groupCount = groupCells = 0u;
  barrier();
  CellTriangles t = cellTriangles(int(gl_GlobalInvocationID.y) * rowLength + int(gl_GlobalInvocationID.x));
  uint count = cellIndexCount(t), local = 0u;
  if (count > 0u) {
    local = atomicAdd(groupCount, count);
    atomicAdd(groupCells, 1u);
  }
  barrier();
  if (gl_LocalInvocationIndex == 0u && groupCount > 0u) {
    groupBase = atomicAdd(indexCount, groupCount);
    atomicAdd(cellsKept, groupCells);
  }
  barrier();
  if (count == 0u) return;
  uint at = groupBase + local;
  if (at + count > capacity) return;
  if (t.kept0) put(at, t.sheet0, t.cap0);
  if (t.kept1) put(at, t.sheet1, t.cap1);
}
