#include "libfit/fit/fit.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <span>

#include "fit/constraints/fit_constraint.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/base/number_text.hpp"
#include "libfit/fit/material_target.hpp"

namespace metalfit {

namespace {

std::vector<NamedStart> starts_for_channel(const Model& model, const std::vector<ClosedFormResult>& closed, int c,
                                           const ChannelTarget& target) {
    std::vector<NamedStart> starts;
    for (const ClosedFormResult& form : closed)
        if (form.value) starts.push_back({"closed " + form.id, form.value->params[c]});
    const auto projected = model.target_starts(target);
    for (std::size_t i = 0; i < projected.size(); ++i)
        starts.push_back({"projected " + std::to_string(i + 1), projected[i]});
    const auto neutral = model.neutral_starts();
    for (std::size_t i = 0; i < neutral.size(); ++i) starts.push_back({"neutral " + std::to_string(i + 1), neutral[i]});
    return starts;
}

std::string number(double x) { return significant_text(x, 6); }

}  // namespace

std::string outside_bounds(const Model& model, const ChannelParameters& params) {
    const auto parameters = model.parameters();
    std::string text;
    for (std::size_t i = 0; i < parameters.size() && i < params.size(); ++i)
        if (!(params[i] >= parameters[i].lower && params[i] <= parameters[i].upper))
            text += (text.empty() ? "" : ", ") + std::string(parameters[i].name) + " = " + number(params[i]) +
                    " outside [" + number(parameters[i].lower) + ", " + number(parameters[i].upper) + "]";
    return text;
}

std::string at_bound(const Model& model, const ChannelParameters& params) {
    const auto parameters = model.parameters();
    std::string text;
    for (std::size_t i = 0; i < parameters.size() && i < params.size(); ++i) {
        const double lo = parameters[i].lower, hi = parameters[i].upper;
        const double tol = 1e-9 * (std::isfinite(hi - lo) ? hi - lo : 1.0);
        const char* side = std::isfinite(lo) && std::abs(params[i] - lo) <= tol   ? "lower"
                           : std::isfinite(hi) && std::abs(params[i] - hi) <= tol ? "upper"
                                                                                  : nullptr;
        if (side)
            text += (text.empty() ? "" : ", ") + std::string(parameters[i].name) + " = " + number(params[i]) +
                    " at its " + side + " bound";
    }
    return text;
}

double curve_excess_outside_unit_range(const Model& model, const ChannelParameters& params) {
    double excess = std::max(0.0, std::abs(model.evaluate(std::span<const double>(params), 0.0) - 1) - 1e-15);
    for (int j = 1; j <= 4096; ++j) {
        const double F = model.evaluate(std::span<const double>(params), j / 4096.0);
        excess = std::max({excess, F - 1, -F});
    }
    return excess;
}

FitTimings& FitTimings::operator+=(const FitTimings& o) {
    reference += o.reference;
    closed_forms += o.closed_forms;
    ceres += o.ceres;
    metrics += o.metrics;
    return *this;
}

PhaseTime FitTimings::total() const {
    PhaseTime t = reference;
    t += closed_forms;
    t += ceres;
    t += metrics;
    return t;
}

ClosedFormInput closed_form_input(const ReferenceCurve& curve, const Material& material, SpectralOptions options) {
    return {
        [&curve](double mu) { return curve(mu); },
        [&material, options](double nm) { return material.index(nm, options.interpolation, options.out_of_range); }};
}

void FitConstraints::check_combination() const {
    if (pin_f0 && gamut_fit)
        throw UsageError("--pin F0 and --gamut-fit together: F(1) = R(1) leaves [0, 1] wherever R(1) does; choose one");
    if (f0_tolerance) {
        if (!std::isfinite(*f0_tolerance) || *f0_tolerance < 0)
            throw UsageError("--f0-tolerance: give a finite number >= 0 (0.5% or 0.005)");
        if (pin_f0) throw UsageError("--f0-tolerance and --pin F0 together: --pin F0 holds F0 exactly; choose one");
        if (gamut_fit) throw UsageError("--f0-tolerance and --gamut-fit together are not supported; choose one");
    }
}

ModelResult fit_model(const Model& model, const SampledReference& reference, const ClosedFormInput& input,
                      FitTimings* timings, const FitConstraints& constraints, const ModelResult* related) {
    constraints.check_combination();
    const std::unique_ptr<const detail::FitConstraint> constraint = detail::make_fit_constraint(constraints);
    constraint->require(model);
    std::optional<ModelResult> own_related;
    if (!model.starts_from().empty() && !(related && related->model && related->model->id() == model.starts_from())) {
        own_related = fit_model(find_model(model.starts_from()), reference, input, timings, constraints);
        related = &*own_related;
    }
    if (model.starts_from().empty()) related = nullptr;
    const RGB R1 = reference.normal().value;  // R(1)
    const ErrorMetric metric = reference.settings().metric;
    FitTimings local;
    FitTimings& t = timings ? *timings : local;
    PhaseClock clock;
    ModelResult result;
    result.model = &model;

    double best_worst = std::numeric_limits<double>::infinity();
    const std::vector<ClosedForm> forms = model.closed_forms(input);
    clock.charge(t.closed_forms);
    for (const ClosedForm& form : forms) {
        ClosedFormResult r{form.id, form.description, {}, {}, {}};
        if (form.defined()) {
            const ModelParameters params = form.params();
            r.value = EvaluatedParameters{params, compute_metrics(model, params, reference)};
            for (int c = 0; c < 3; ++c)
                if (const std::string out = outside_bounds(model, params[c]); !out.empty())
                    r.outside_bounds +=
                        (r.outside_bounds.empty() ? "" : "; ") + std::string(kChannelNames[c]) + ": " + out;
            const double worst = worst_channel(r.value->metrics.rms(metric));
            if (worst < best_worst) best_worst = worst, result.best_closed = result.closed_forms.size();
        } else {
            r.undefined = form.undefined_reason();
        }
        result.closed_forms.push_back(std::move(r));
    }

    clock.charge(t.metrics);
    FitResult& fit = result.fit;
    // Per channel, why the constrained solution was not kept (--f0-tolerance: it needs a parameter outside its bounds).
    std::array<std::string, 3> unmet;
    for (int c = 0; c < 3; ++c) {
        const ChannelTarget target = reference.target(c);
        auto starts = starts_for_channel(model, result.closed_forms, c, target);
        // The related model's optimum, mapped: where it lies strictly inside this model's bounds it is this model's
        // optimum too (the same curve; any curve this model draws is one the related model can draw), so it is the
        // only start (polished); else it is the first.
        if (related && !related->fit.value.params[c].empty())
            if (ChannelParameters start = model.start_from(related->fit.value.params[c]); !start.empty()) {
                NamedStart mapped{"fit " + std::string(model.starts_from()), std::move(start)};
                if (outside_bounds(model, mapped.params).empty() && at_bound(model, mapped.params).empty())
                    starts = {std::move(mapped)};
                else
                    starts.insert(starts.begin(), std::move(mapped));
            }
        detail::ConstrainedChannel constrained = constraint->fit_channel(model, target, starts, R1[c]);
        ChannelFit channel = std::move(constrained.fit);
        fit.refused[c] = std::move(constrained.refused);
        unmet[c] = std::move(constrained.unmet);
        // Every start ended on parameters that are no curve (rational: a pole in [0, 1]): the first start that is
        // a curve inside the bounds is kept as it is, and the channel is reported as unrepresentable.
        if (channel.params.empty() && constraint->keeps_a_start_as_is())
            for (const NamedStart& start : starts)
                if (start.params.size() == model.parameters().size() && model.inadmissible(start.params).empty() &&
                    outside_bounds(model, start.params).empty()) {
                    const std::string why = channel.discarded_why;
                    channel.params = start.params;
                    channel.solver.method = kCeresSolve;
                    channel.solver.start = start.name;
                    channel.solver.termination = "NO_CONVERGENCE";
                    channel.solver.starts = static_cast<int>(starts.size());
                    fit.refused[c] = "every start of the fit ended on parameters that are no curve (" +
                                     std::string(why.empty() ? "a pole in [0, 1]" : "e.g. " + why) + "): start " +
                                     start.name + " kept as it is";
                    break;
                }
        if (channel.params.empty())
            throw std::runtime_error(std::string(model.id()) + ": no start of the " + kChannelNames[c] +
                                     " fit converged" + constraint->unsolved_qualifier());
        fit.value.params[c] = channel.params;
        fit.solver[c] = channel.solver;
    }
    clock.charge(t.ceres);
    fit.value.metrics = compute_metrics(model, fit.value.params, reference);

    // Never worse than a closed form inside the bounds, channel by channel (a start clamped into the bounds can end up
    // worse). A closed form outside the bounds that fits better is not kept (exports would carry parameters the model
    // does not allow, issue 13 item 11): the record says that the model cannot represent the data.
    // Only closed forms that meet the active constraint compete (--pin F0: the pin, unless refused for the channel).
    const auto competes = [&](const ClosedFormResult& form, int c) {
        return form.value && constraint->admits(model, form.value->params[c], R1[c], !fit.refused[c].empty());
    };
    bool replaced = false;
    for (int c = 0; c < 3; ++c) {
        double best = fit.value.metrics.rms(metric)[c];
        for (const ClosedFormResult& form : result.closed_forms)
            if (competes(form, c) && form.value->metrics.rms(metric)[c] < best &&
                outside_bounds(model, form.value->params[c]).empty()) {
                best = form.value->metrics.rms(metric)[c];
                fit.value.params[c] = form.value->params[c];
                fit.fallback[c] = form.id;
                replaced = true;
            }
    }
    if (replaced) fit.value.metrics = compute_metrics(model, fit.value.params, reference);
    for (int c = 0; c < 3; ++c) {
        const double fitted = fit.value.metrics.rms(metric)[c];
        double best = fitted;
        for (const ClosedFormResult& form : result.closed_forms) {
            if (!competes(form, c) || !(form.value->metrics.rms(metric)[c] < best)) continue;
            const std::string out = outside_bounds(model, form.value->params[c]);
            if (out.empty()) continue;
            best = form.value->metrics.rms(metric)[c];
            fit.unrepresentable[c] = "closed " + form.id + " fits better (" + to_string(metric) + "_rms " +
                                     number(best) + " against " + number(fitted) + ") but " + out +
                                     ": the model cannot represent these data within its bounds";
        }
        // A refused constraint, or parameters that do not meet it (the constraint says).
        if (!fit.refused[c].empty())
            fit.unrepresentable[c] =
                fit.refused[c] + ": the model cannot represent these data" + constraint->refused_qualifier();
        constraint->explain(fit.unrepresentable[c], model, fit.value.params[c], fit.value.metrics.err_f0[c], R1[c],
                            !fit.refused[c].empty(), unmet[c]);
    }
    clock.charge(t.metrics);
    return result;
}

std::vector<ModelResult> fit_models(const FitTarget& target, std::span<const Model* const> models,
                                    const FitConstraints& constraints, FitTimings* timings) {
    const SampledReference& reference = *target.reference();
    if (reference.settings().metric == ErrorMetric::rel && reference.rel_undefined())
        throw InputError(target.location(), "relative error undefined for " + target.id() + ": " +
                                                *reference.rel_undefined() + " (use the abs error metric)");
    const ClosedFormInput input = target.closed_form_input();
    std::vector<ModelResult> results;
    for (const Model* model : models) {
        // A model that starts from another's fit takes it from this target's results where it was fitted already.
        const ModelResult* related = nullptr;
        for (const ModelResult& done : results)
            if (!model->starts_from().empty() && done.model->id() == model->starts_from()) related = &done;
        results.push_back(fit_model(*model, reference, input, timings, constraints, related));
    }
    return results;
}

MaterialFit fit_material(const Material& material, const Colorimetry& colorimetry, const ColorSpaceConverter& converter,
                         const MaterialFitRequest& request) {
    PhaseClock clock;
    FitTimings timings;
    const MaterialTarget target(material, colorimetry, converter, request.spectral, request.error);
    clock.charge(timings.reference);
    const ReferenceCurve& curve = target.curve();
    MaterialFit result{material, curve.raw_white(), curve(1.0), {}, {}, target.reference()};
    // What --extrapolate did travels with the material's own warnings: the record, the CLI and the exports say it.
    result.material.warnings.insert(result.material.warnings.end(), curve.held_constant().begin(),
                                    curve.held_constant().end());
    result.models = fit_models(target, request.models, request.constraints, &timings);  // InputError: rel undefined
    result.timings = timings;
    return result;
}

}  // namespace metalfit
