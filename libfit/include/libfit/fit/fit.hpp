// Fitting one material: every closed form of a model, evaluated, and a Ceres fit per channel that is never worse
// than any of them on the chosen metric.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "libfit/base/phase_clock.hpp"
#include "libfit/color/colorimetry.hpp"
#include "libfit/fit/fit_target.hpp"
#include "libfit/fit/metrics.hpp"
#include "libfit/io/material.hpp"
#include "libfit/models/model.hpp"
#include "libfit/reference/reference_curve.hpp"
#include "libfit/reference/sampled_reference.hpp"

namespace metalfit {

struct EvaluatedParameters {
    ModelParameters params;
    Metrics metrics;
};

struct ClosedFormResult {
    std::string id;
    std::string description;
    std::optional<EvaluatedParameters> value;  // empty when undefined
    std::string undefined;                     // why ("red: alpha undefined: ...")
    // Where a defined closed form lies outside the model's fit bounds ("red: g = 1.03 outside [0, 1]"), else empty:
    // such a form is reported, never taken as the fit's fallback.
    std::string outside_bounds;
};

struct FitResult {
    EvaluatedParameters value;
    std::array<SolverSummary, 3> solver;
    // Per channel: the closed form kept because no start of the fit beat it ("" when the fit won). Only a closed
    // form inside the model's bounds is kept.
    std::array<std::string, 3> fallback;
    // Per channel: a closed form outside the bounds that fits better than the fit, i.e. the model cannot represent the
    // data within its bounds ("closed nk-650-550-450 fits better (rel_rms 0.0123 against 0.0150) but g = 1.03 is
    // outside [0, 1]"); "" otherwise.
    std::array<std::string, 3> unrepresentable;
    // Per channel: what the fit refused and what it kept instead, "" when nothing was refused: --pin F0 where the
    // pinned F(1) needs a parameter outside its bounds (the unpinned fit is kept), every start ending with a pole
    // (rational: the best pole-free start is kept, or the first pole-free start when none ends pole-free). Said on
    // stderr by fit and export, and in the record (fit.refused); such a channel is unrepresentable too.
    std::array<std::string, 3> refused;
};

// Where a channel's parameters leave the model's bounds ("g = 1.03 outside [0, 1]"), or "" when they are inside.
std::string outside_bounds(const Model& model, const ChannelParameters& params);
// Which of a channel's parameters sit on a finite bound of the model (within 1e-9 of its width, or of 1 for an
// unbounded side), "n = 0.001 at its lower bound, k = 10000 at its upper bound", or "" when none does: a fit that ends
// there is the best the model allows inside its bounds, not a free optimum (the record's fit.at_bound).
std::string at_bound(const Model& model, const ChannelParameters& params);
// How far a channel's curve leaves [0, 1] on a 4097-point grid of μ (0 inside; at μ = 0, where every model's F is 1
// by construction, 1e-15 of rounding is allowed): what --gamut-fit holds.
double curve_excess_outside_unit_range(const Model& model, const ChannelParameters& params);

struct ModelResult {
    const Model* model = nullptr;
    std::vector<ClosedFormResult> closed_forms;
    // The defined closed form with the lowest worst-channel chosen metric, if any is defined, inside the bounds or not
    // (its outside_bounds says): what `--params closed` exports. Never the fit's fallback by itself: FitResult::fallback
    // takes only forms inside the bounds, channel by channel.
    std::optional<std::size_t> best_closed;
    FitResult fit;
};

// Where the time of a fit goes (seconds of one thread), for `metalfit fit --timings`; never written to records.
// CPU time (the fitting thread's own CPU clock) and wall time of each phase (base/phase_clock.hpp).
struct FitTimings {
    PhaseTime reference;     // spectral integration + OCIO at the nodes and the dense grid
    PhaseTime closed_forms;  // closed forms (their spectral samples included)
    PhaseTime ceres;         // Ceres solves, all starts
    PhaseTime metrics;       // metrics of closed forms and fits
    FitTimings& operator+=(const FitTimings& o);
    PhaseTime total() const;
};

// The closed-form input of a material: its reference curve and its measured η(λ).
ClosedFormInput closed_form_input(const ReferenceCurve& curve, const Material& material, SpectralOptions options);

// Constraints of a fit (docs/fitting.md, "Constraints").
struct FitConstraints {
    // --pin F0: F(1) = R(1) exactly in every channel (the convention of physicallybased.info and Adobe's tables);
    // closed forms that do not meet it are never kept as fallbacks.
    bool pin_f0 = false;
    // --gamut-fit: every channel's fitted curve stays in [0, 1] at every μ (4097-point grid), fitted under that
    // constraint; closed forms outside it are never kept as fallbacks. Not together with pin_f0 (UsageError).
    bool gamut_fit = false;
    // --f0-tolerance T: |err_f0| = |F(1)/R(1) − 1| ≤ T in every channel, a constraint of the solve (F(1) a bounded
    // unknown, the pinned parameter computed from it: ChannelConstraints::f0_range). A channel whose unconstrained fit
    // meets it keeps that fit. Not with pin_f0 (which is T = 0) nor gamut_fit; T finite and ≥ 0.
    std::optional<double> f0_tolerance;
    bool operator==(const FitConstraints&) const = default;
    // The one place that says which constraints combine: a UsageError for a combination that cannot be met (pin_f0
    // with gamut_fit, f0_tolerance with either) or a tolerance that is not a finite number ≥ 0. fit_model calls it; a
    // command line calls it before any work.
    void check_combination() const;
};

// Requires the chosen metric to be defined on the reference (see SampledReference::rel_undefined). A model that
// starts from another model's fit (Model::starts_from: gulbrandsen from conductor-rgb) takes `related` where it is
// that model's result on the same reference and constraints, and fits that model itself otherwise (the result is the
// same either way).
ModelResult fit_model(const Model& model, const SampledReference& reference, const ClosedFormInput& input,
                      FitTimings* timings = nullptr, const FitConstraints& constraints = {},
                      const ModelResult* related = nullptr);

// Every model of `models`, in that order, fitted to one target (fit/fit_target.hpp: a spectral metal, a layered
// stack, a measured reflectance): its closed forms from the target's closed_form_input, then fit_model on its
// sampled reference. Throws InputError at the target's location when the chosen metric is relative and undefined on it.
std::vector<ModelResult> fit_models(const FitTarget& target, std::span<const Model* const> models,
                                    const FitConstraints& constraints = {}, FitTimings* timings = nullptr);

struct MaterialFitRequest {
    SpectralOptions spectral;
    ErrorSettings error;
    std::vector<const Model*> models;
    FitConstraints constraints = {};
};

struct MaterialFit {
    Material material;
    RGB raw_white;
    RGB F0;  // R(1), for the out-of-gamut flag
    std::vector<ModelResult> models;
    FitTimings timings;
    // The sampled reference the metrics were computed on, so that exports can re-evaluate the parameters they write.
    std::shared_ptr<const SampledReference> reference;
    // A layered material being exported: the fit of its metal alone (layers removed, the same request), which the
    // formats that layer a coat or film themselves (OpenPBR, MaterialX, glTF) write as the base; null otherwise
    // (export/export.hpp, attach_bare_metal_fits).
    std::shared_ptr<const MaterialFit> bare_metal = nullptr;
};

// Everything for one material: its MaterialTarget (fit/material_target.hpp) through fit_models. Throws InputError naming the material's file when the data do not cover the
// visible range or the relative metric is undefined (R_c ≤ 0 somewhere: use the absolute metric).
MaterialFit fit_material(const Material& material, const Colorimetry& colorimetry, const ColorSpaceConverter& converter,
                         const MaterialFitRequest& request);

}  // namespace metalfit
