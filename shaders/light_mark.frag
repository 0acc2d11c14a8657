// (version_430.glsl and light_mark.glsl come first.) The light pass of the indexed GPU volume.
void main() { markOccupancy(); }
