// How far the beauty frame is from the reference and what it costs: |beauty − reference| (difference), the frame
// times (timing) and metrics.json per sphere (metrics: RMSE and mean |difference| inside each sphere, the impostor's
// effort, the reference's noise).
#pragma once

#include "glpreview/effects/effect.hpp"

namespace metalfit::glpreview {

const Effect& metrics_effect();

}  // namespace metalfit::glpreview
