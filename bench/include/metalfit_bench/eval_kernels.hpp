// The things being timed: ways of computing the RGB reflectance R(μ) (3 channels per evaluation) of one material.
// - each model's float evaluation (the C++ definition in libfit/models/, inlined) with the material's fitted
//   parameters;
// - the exact conductor Fresnel of the RGB n,k in libfit's complex form (fresnel(), double), with conductor-rgb's
//   fitted n,k, and in libfit's real branch-free form (fresnel_real(), float), the one that vectorises;
// - the exact spectral reference: per-wavelength complex Fresnel × CMF integration + the OCIO conversion and white
//   balance (ReferenceCurve, double): the true cost of "exact";
// - a 1D LUT of the exact curve with linear interpolation at 64 and 256 entries.
// Each kernel has two loops over an array of μ: `scalar` evaluates one μ at a time behind an optimisation barrier on
// μ (no vectorisation across μ; the cost of one call, as a shader pays per pixel), `array` is a plain loop the
// compiler may vectorise. Both the Google Benchmark suite and `metalfit bench` time exactly these functions.
#pragma once

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "metalfit_bench/environment.hpp"

namespace metalfit::bench {

struct EvalKernel {
    std::string id;           // model id, "exact-complex", "exact-real", "spectral-reference", "lut-64", "lut-256"
    std::string kind;         // "model", "exact" or "lut"
    std::string description;  // one line
    std::optional<int> params_per_channel;  // model parameters, LUT entries; none for the spectral reference
    std::size_t batch = 1024;               // μ values per timed call (fewer for the slow spectral reference)
    // Evaluate at every μ of `mu`; out has 3 · mu.size() floats (scalar: interleaved RGB; array: planar R…, G…, B…).
    std::function<void(std::span<const float> mu, std::span<float> out)> scalar;
    std::function<void(std::span<const float> mu, std::span<float> out)> array;
};

// The baseline of every ratio: the exact conductor Fresnel of fitted RGB n,k, as a model (real form, float).
inline constexpr const char* kBaselineKernel = "conductor-rgb";

// Every model in all_models() order, then exact-complex, exact-real, lut-64, lut-256, spectral-reference.
std::vector<EvalKernel> eval_kernels(const PreparedMaterial& material);

// `count` μ values spread over (0, 1]: μ_i = (i + 1) / count, in a fixed shuffled order (so that branch predictors
// see no pattern that a renderer would not).
std::vector<float> bench_mu(std::size_t count);

}  // namespace metalfit::bench
