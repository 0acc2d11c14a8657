#version 330 core
// Entry capture's first layer (the light pass draws every face; resolve.frag keeps it where a back
// face lies behind): a face lit nearly edge-on, whose cosine with the light's ray is below
// grazingCos (kEntryGrazingCos, depth_map.h), is passed over, so the back face behind it is
// recorded there, as the Embree capture's entryFilter does (depth_capture.cpp).
in vec3 worldPos;            // light.vert
uniform int lightType;       // LightType: 0 spot, 1 directional (a point light's faces are spot lights)
uniform vec3 lightPosition;  // world, spot apex
uniform vec3 lightDirection; // world, the way the light shines
uniform float grazingCos;

void main() {
  // The flat face normal from the derivatives (as scene.frag), taken outside the branch.
  vec3 n = cross(dFdx(worldPos), dFdy(worldPos));
  vec3 d = lightType != 1 ? worldPos - lightPosition : lightDirection;
  if (gl_FrontFacing && abs(dot(n, d)) < grazingCos * length(n) * length(d)) discard;
}
