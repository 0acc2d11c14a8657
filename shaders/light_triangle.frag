// (version_330.glsl and light_triangle.glsl come first.) The light pass of the explicit volume
// refined by the walk.
void main() { recordTriangle(); }
