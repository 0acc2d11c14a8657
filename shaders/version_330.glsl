#version 330 core
// The first source string of the GL 3.3 programs that share volume_common.glsl.
