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

// The cell's triangles: `count` indices (0 for an all-far cell), its corners' texel ids, which
// corners are far, and its sheet triangles (corner numbers) with which of them are kept.
struct CellTriangles {
  uint count;
  int id[4];
  bool far[4];
  ivec3 tri[2];
  bool kept[2];
  int triangles;
};

CellTriangles cellTriangles(int c) {
  CellTriangles t;
  t.count = 0u;
  t.triangles = 0;
  if (c >= cellCount) return t;
  int inner = cubeInnerCells();
  ivec4 cell = c < inner ? cubeInnerCell(c) : seamCells[c - inner];
  bool triangle = cell.z < 0;
  int corners = triangle ? 3 : 4;
  t.id = int[4](cell.x, cell.y, triangle ? cell.w : cell.z, cell.w);
  float d[4];
  bool allFar = true;
  for (int k = 0; k < 4; ++k) {
    if (k >= corners) break;
    d[k] = cubeSheetDepth(cubeTexel(t.id[k]));
    t.far[k] = !(d[k] < farPlane);
    allFar = allFar && t.far[k];
  }
  if (allFar) return t;
  vec3 p[4];
  for (int k = 0; k < 4; ++k) {
    if (k >= corners) break;
    p[k] = d[k] * cubeDirection(cubeTexel(t.id[k]));
  }
  // Corners of each sheet triangle, in volume_cube.geom's strips' order.
  if (triangle) {
    t.tri[t.triangles++] = ivec3(0, 1, 2);
  } else if (perfect != 0 && flipDiagonal(p[0], p[1], p[2], p[3])) {
    t.tri[t.triangles++] = ivec3(1, 2, 0);
    t.tri[t.triangles++] = ivec3(0, 2, 3);
  } else {
    t.tri[t.triangles++] = ivec3(0, 1, 3);
    t.tri[t.triangles++] = ivec3(3, 1, 2);
  }
  for (int k = 0; k < t.triangles; ++k) {
    t.kept[k] = !(t.far[t.tri[k].x] && t.far[t.tri[k].y] && t.far[t.tri[k].z]);
    if (t.kept[k]) t.count += 6u;
  }
  return t;
}

void main() {
  if (gl_LocalInvocationIndex == 0u) groupCount = groupCells = 0u;
  barrier();
  CellTriangles t = cellTriangles(int(gl_GlobalInvocationID.y) * rowLength + int(gl_GlobalInvocationID.x));
  uint local = 0u;
  if (t.count > 0u) {
    local = atomicAdd(groupCount, t.count);
    atomicAdd(groupCells, 1u);
  }
  barrier();
  if (gl_LocalInvocationIndex == 0u && groupCount > 0u) {
    groupBase = atomicAdd(indexCount, groupCount);
    atomicAdd(cellsKept, groupCells);
  }
  barrier();
  if (t.count == 0u) return;
  uint at = groupBase + local;
  if (at + t.count > capacity) return;
  for (int k = 0; k < t.triangles; ++k) {
    if (!t.kept[k]) continue;
    uint s[3], f[3];
    for (int v = 0; v < 3; ++v) {
      int corner = t.tri[k][v];
      s[v] = 2u * uint(t.id[corner]);
      f[v] = t.far[corner] ? s[v] : s[v] + 1u;
    }
    // The cap's vertex order of volume_cube.geom's strips: ADB, BDC for ABD, DBC; BAC, CAD for
    // BCA, ACD; ADB for a corner's ABD: the sheet triangle's vertices 0, 2, 1 for a cell's first
    // triangle, 1, 0, 2 for a quad's second.
    indices[at++] = s[0]; indices[at++] = s[1]; indices[at++] = s[2];
    if (k == 1) {
      indices[at++] = f[1]; indices[at++] = f[0]; indices[at++] = f[2];
    } else {
      indices[at++] = f[0]; indices[at++] = f[2]; indices[at++] = f[1];
    }
  }
}
