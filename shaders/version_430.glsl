#version 430 core
// The first source string of the GL 4.3 programs that share volume_common.glsl.
