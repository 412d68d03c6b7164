// `metalfit bench`'s layers section (issue 28, goal 10): what a stack costs next to the bare metal, measured in the
// same run. Per stack (a coat, a thin film, both) of one metal, the reference curve — built from the spectral data
// (the optics on the colour grid and OCIO) and sampled at the fit's quadrature nodes — and a fit of one model to it,
// each timed interleaved with the bare metal's and printed as a ratio (median over rounds, ± half the interquartile
// range). No time is asserted anywhere.
#pragma once

#include <string>
#include <vector>

#include "libfit/base/interleaved_timer.hpp"
#include "metalfit_bench/environment.hpp"

namespace metalfit::bench {

struct LayersRow {
    std::string id;     // "bare", "coat", "film", "coat+film"
    std::string stack;  // describe_stack: "gold under a coat n = 1.5 over a TiO2 (Siefke) film of 80 nm"
    double reference_ms = 0;
    Ratio reference_ratio;  // to the bare metal's, same run
    double fit_ms = 0;
    Ratio fit_ratio;
};

struct LayersBench {
    std::string material;
    std::string model;  // the model fitted
    std::vector<LayersRow> rows;
};

// `material` under --coat 1.5, --film TiO2:80nm and both; `model` fitted (default f82-tint). Throws what libfit
// throws for a bad data folder.
LayersBench layers_bench(const Environment& env, const std::string& material, const TimingOptions& timing,
                         const std::string& model = "f82-tint");

}  // namespace metalfit::bench
