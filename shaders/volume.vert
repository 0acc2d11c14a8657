#version 330 core
// Explicit shadow volume (VolumeMesh uploaded from the CPU): world -> camera clip.
layout(location = 0) in vec3 position;  // world
uniform mat4 worldToClip;
void main() { gl_Position = worldToClip * vec4(position, 1.0); }
