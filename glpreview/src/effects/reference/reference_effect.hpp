// The ground truth every preview compares with: the analytic CPU ray tracing of the same scene (cpu-reference: exact
// mirror reflections, same Fresnel, same camera) and, for rough spheres, their GGX lobe by Monte Carlo
// (monte-carlo-reference) with its standard error.
#pragma once

#include "glpreview/effects/effect.hpp"

namespace metalfit::glpreview {

const Effect& reference_effect();

}  // namespace metalfit::glpreview
