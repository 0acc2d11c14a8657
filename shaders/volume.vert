#version 330 core
// Explicit shadow volume (VolumeMesh uploaded from the CPU): world -> camera clip.
layout(location = 0) in vec3 position;  // world
uniform mat4 worldToClip;
// invariant, with the same expression as scene.vert: the silhouette volume's light cap (the
// occluders' own lit triangles) gets exactly the depths of the camera pass, so z-fail counts it.
invariant gl_Position;
void main() { gl_Position = worldToClip * vec4(position, 1.0); }
