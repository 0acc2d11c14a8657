#version 330 core
// The refined GPU cube volume's face mask (docs/gpu.md "The refined GPU cube volume"): a
// full-screen triangle whose fragments survive on the pixels of the face image (cube_face_id.frag)
// that lie on another face than `face` (and on the background, 255), where the stencil pass sets
// bit 7. Texel for pixel: the image has the camera targets' size.
uniform usampler2D faceImage;
uniform uint face;

void main() {
  if (texelFetch(faceImage, ivec2(gl_FragCoord.xy), 0).r == face) discard;
}
