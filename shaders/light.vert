#version 330 core
// Light depth pass: world-space scene vertices -> light clip space.
layout(location = 0) in vec3 position;  // world
uniform mat4 worldToLightClip;           // P_light * V_light, composed in double on the CPU
out vec3 worldPos;                       // for light_entry.frag's facing test
void main() {
  worldPos = position;
  gl_Position = worldToLightClip * vec4(position, 1.0);
}
