// What a light's depth map will miss, said before it is captured: one sentence per problem,
// naming the object, for the command line's warnings and the validation report.
#pragma once

#include <string>
#include <vector>

#include "shadowvol/depth_map.h"
#include "shadowvol/scene.h"

namespace shadowvol {

/// Warnings for capturing `scene`'s light at W x H texels by `capture`:
///  - back capture and an open mesh (an object of type "mesh" that is not closed, neither as
///    stored nor after welding vertices at equal positions): light passes through its openings,
///    so its shadow leaks; front or midpoint capture record it;
///  - an object that covers no texel centre (its light-view bounds lie between two neighbouring
///    texel centres along an axis): it casts no shadow at this resolution; the message gives the
///    smallest N x N map whose texel spacing is below its extent. With hiddenSearchGrid = S > 1 (the
///    volume is refined on an S x S sub-grid that searches for hidden surfaces, volume_builder.h
///    nearerSurfaces) the sub-grid's nodes, every 1/S texel, count as well: an object that covers
///    one of them is walled round and casts its shadow. An object whose triangles have no area in
///    the light's view (seen exactly edge-on, or zero-area triangles only) is named too, whatever
///    its bounds. Objects wholly or partly behind a spot light's apex plane are not judged; under
///    a point light, each object that lies on one face of its cube is judged on that N x N face
///    (W = N), with sizes up to the cube's limit, and one over several faces is not;
///  - an object with vertices inside the light's window but nearer than its near plane (a given
///    near too far out, or fitted planes stretched by an outlier vertex far away): the near plane
///    clips them, so they cast no shadow;
///  - a spot or directional light whose frustum holds no object at all (it points away from the
///    scene, or a given near/far range holds nothing): the map sees nothing and the volume is
///    empty (said when no object is named as clipped by the near plane).
/// The objects of one kind come together (those with vertices clipped by the near plane, then those
/// that cover no texel centre), the first 20 of each named and one more line counting the rest.
std::vector<std::string> captureWarnings(const Scene& scene, int width, int height, CaptureMode capture,
                                         int hiddenSearchGrid = 1);

}  // namespace shadowvol
