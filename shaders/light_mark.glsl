// (version_430.glsl comes first; light_mark.frag and light_mark_triangle.frag call markOccupancy.)
// Light depth pass of the frames whose GPU volume is indexed (volume_index.frag): besides the
// depth, every fragment that passes the depth test when it is drawn (early fragment tests) sets its
// texel's bit in an occupancy image of one 32-bit word per block of 8 x 4 texels (bit x + 8 * y for
// texel (x, y) of the block), so that the listing pass reads depths only where the scene covers the
// map. The fragment that a texel keeps passed the test when it was drawn, so every texel with a
// hit has its bit; the listing pass still reads each marked texel's depth and applies the sheet
// rule (volume_common.glsl) to it.
layout(early_fragment_tests) in;
layout(r32ui, binding = 0) uniform coherent uimage2D occupancy;
void markOccupancy() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  imageAtomicOr(occupancy, p / ivec2(8, 4), 1u << uint((p.x & 7) + 8 * (p.y & 3)));
}
