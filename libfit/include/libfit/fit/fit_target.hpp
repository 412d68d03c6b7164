// FitTarget: what a fit fits to. It gives the sampled reference curve (every channel at the quadrature nodes, and the
// grid of the maxima), the closed forms' input (R_c(μ) at any μ, and η(λ) where the target has a complex index) and
// the provenance a record or message names. The fitter (fit_models in fit/fit.hpp) needs nothing else: a spectral
// metal, a layered stack (fit/material_target.hpp) and a measured reflectance (fit/reflectance_target.hpp) are fitted
// by the same code. docs/fitting.md, "Targets and constraints".
#pragma once

#include <complex>
#include <functional>
#include <memory>
#include <string>

#include "libfit/base/errors.hpp"
#include "libfit/color/color.hpp"
#include "libfit/models/model.hpp"
#include "libfit/reference/sampled_reference.hpp"

namespace metalfit {

class FitTarget {
public:
    virtual ~FitTarget() = default;

    // The curve at the quadrature nodes and the grid, white balanced: what every model is fitted to and scored on
    // (shared: a MaterialFit keeps it for the exports).
    virtual std::shared_ptr<const SampledReference> reference() const = 0;
    // R_c(μ) at any μ in [0, 1], white balanced (the closed forms read F0, F82, ... from it).
    virtual RGB operator()(double mu) const = 0;
    // η(λ) where the target has one (a spectral metal); an empty function otherwise, and then the closed forms that
    // sample η are undefined ("the target has no complex index").
    virtual std::function<std::complex<double>(double nm)> eta() const { return {}; }
    // The id messages name ("Au", a measured file's stem), the provenance a record names (the material, the whole
    // stack top down, the measured file) and the place an error about the target's data points to.
    virtual std::string id() const = 0;
    virtual std::string describe() const = 0;
    virtual InputLocation location() const = 0;

    // What the closed forms are computed from: this target's curve and its η (valid while the target lives).
    ClosedFormInput closed_form_input() const {
        return {[this](double mu) { return (*this)(mu); }, eta()};
    }
};

}  // namespace metalfit
