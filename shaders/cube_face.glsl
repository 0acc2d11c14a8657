// (After a version_*.glsl file.) The face of a point light's cube that an offset from it falls on,
// as cube_map.h's cubeLookup chooses it: the axis of the largest |coordinate| (ties to the lower
// axis, x before y before z), then + (face 2 axis) or - (2 axis + 1). Shared by scene.frag (the
// cube shadow map's taps) and cube_face_id.frag (the refined GPU cube volume's face image).
int cubeFaceOf(vec3 o) {
  vec3 a = abs(o);
  int axis = (a.x >= a.y && a.x >= a.z) ? 0 : (a.y >= a.z ? 1 : 2);
  return 2 * axis + (o[axis] < 0.0 ? 1 : 0);
}
