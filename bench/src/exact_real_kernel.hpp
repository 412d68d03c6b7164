// The exact conductor Fresnel of the RGB n,k in libfit's real, branch-free form (optics/fresnel_real.hpp, float),
// with conductor-rgb's fitted n,k: the form a CPU evaluates over arrays. Its source is built without errno and
// without trapping math so that the array loop vectorises (square roots and selects in SIMD).
#pragma once

#include "metalfit_bench/eval_kernels.hpp"

namespace metalfit::bench {

EvalKernel exact_real_kernel(const PreparedMaterial& material);

}  // namespace metalfit::bench
