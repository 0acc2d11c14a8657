#version 330 core
// The stencil methods' lighting pass (docs/gpu.md "Passes of one frame"): drawn over the light
// frustum's rectangle of the image with the stencil test != 0, it puts the camera pass's ambient
// term (scene.frag location 2, kept in a texture) over its lit colour where the volume's count
// says the pixel is in shadow. Texel for pixel: the texture has the camera targets' size.
uniform sampler2D ambientImage;
layout(location = 0) out vec4 fragColor;

void main() {
  fragColor = texelFetch(ambientImage, ivec2(gl_FragCoord.xy), 0);
}
