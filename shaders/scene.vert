#version 330 core
// Camera pass: world-space scene vertices with a per-vertex albedo. gl_Position is invariant, as
// in volume.vert with the same expression, so volume faces that lie on the scene's surfaces get
// the scene's depths.
layout(location = 0) in vec3 position;  // world
layout(location = 1) in vec3 albedo;    // linear RGB in [0, 1]
uniform mat4 worldToClip;               // P_camera * V_camera
out vec3 worldPos;
out vec3 color;
invariant gl_Position;
void main() {
  worldPos = position;
  color = albedo;
  gl_Position = worldToClip * vec4(position, 1.0);
}
