// The scene's surfaces a rasteriser may draw at a pixel although the ray through its centre does
// not meet them: triangles whose image comes within kImagePlaneTie pixels of the centre (a sliver's
// tip, an edge), where the rasteriser's snapped vertices can put the centre inside. The four rays
// of imagePlaneTieCorners sample that square; a sliver thinner than it can pass between them (a
// probe's open wuson at 160 x 120, 2026-12-05: a triangle's edge 0.0015 px from a pixel centre and
// none of the corners inside it; the stencil counted behind it, the rays in front).
#pragma once

#include <cstddef>
#include <vector>

#include "shadowvol/camera.h"
#include "shadowvol/triangle_mesh.h"

namespace shadowvol {

/// For each of `pixels` (indices into the camera's image, rows top first): the depths along the
/// ray through its centre (the ray parameter of PrimaryRays, as CameraHits::depth) of the planes
/// of the triangles of `meshes` (in the camera's frame) whose image lies within `radius` pixels of
/// the centre, closed triangles included. Triangles with a corner at or behind the eye plane, and
/// those edge-on to the ray, are left out. One pass over the triangles; the pixels are few (those
/// a frame's validation could not otherwise admit).
std::vector<std::vector<double>> surfaceDepthsNearPixels(const std::vector<const TriangleMesh*>& meshes,
                                                         const Camera& camera, const std::vector<std::size_t>& pixels,
                                                         double radius);

}  // namespace shadowvol
