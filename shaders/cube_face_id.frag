// (version_330.glsl and cube_face.glsl come first.) The refined GPU cube volume's face image
// (docs/gpu.md "The refined GPU cube volume"): drawn with scene.vert at the camera pass's depth
// (GL_EQUAL), each pixel gets the cube face of a point light that its surface point lies on.
in vec3 worldPos;
uniform vec3 lightPosition;  // world
layout(location = 0) out uint faceOut;

void main() { faceOut = uint(cubeFaceOf(worldPos - lightPosition)); }
