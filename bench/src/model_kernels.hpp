// Each registered model's float evaluation (its C++ definition in libfit/models/, inlined) with the material's fitted
// parameters: the form a CPU evaluates over arrays. Its source is built without errno and without trapping math, as
// exact_real_kernel.cpp is, so that the array loops of the models with square roots (conductor-rgb, gulbrandsen)
// vectorise; values are unchanged.
#pragma once

#include <vector>

#include "metalfit_bench/eval_kernels.hpp"

namespace metalfit::bench {

// One kernel per model, in all_models() order.
std::vector<EvalKernel> model_kernels(const PreparedMaterial& material);

}  // namespace metalfit::bench
