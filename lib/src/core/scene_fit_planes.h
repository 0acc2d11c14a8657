// Internal to the scene fitting: the light's near and far planes fitted again after its frustum
// changed (light_view_fit.cpp), by fitLightAndCamera's rule; they only move inwards.
#pragma once

#include "shadowvol/scene.h"

namespace shadowvol::detail {

void refitLightPlanes(Scene& scene);

}  // namespace shadowvol::detail
