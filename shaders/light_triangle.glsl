// (version_330.glsl or version_430.glsl comes first; light_triangle.frag and
// light_mark_triangle.frag call recordTriangle.)
// Light depth pass of frames that refine with the silhouette walk (silhouette_walk.comp): besides
// the depth, each texel keeps the index of the scene triangle it recorded, plus one (0 = none; the
// target is cleared to 0). The scene is one draw call, so gl_PrimitiveID is the triangle's index
// in Scene::merged() order.
layout(location = 0) out uint triangle;
void recordTriangle() { triangle = uint(gl_PrimitiveID) + 1u; }
