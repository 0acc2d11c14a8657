// (version_430.glsl, light_mark.glsl and light_triangle.glsl come first.) The light pass of the
// refined GPU volume: the occupancy bits (volume_index.frag lists its unrefined quads) and the
// triangle record (silhouette_walk.comp).
void main() {
  markOccupancy();
  recordTriangle();
}
