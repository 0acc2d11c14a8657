#version 330 core
// The GPU-built volume (volume_mesh.comp's light-view triangle list) to camera clip space.
layout(location = 0) in vec3 lightViewPosition;
uniform mat4 lightViewToClip;  // P_camera * V_camera * inverse(V_light), composed in double
void main() {
  gl_Position = lightViewToClip * vec4(lightViewPosition, 1.0);
}
