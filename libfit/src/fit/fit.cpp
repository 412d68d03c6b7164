#include "libfit/fit/fit.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <span>

#include "libfit/base/errors.hpp"
#include "libfit/base/number_text.hpp"

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

// err_f0 of docs/fitting.md: F(1) / R(1) − 1, NaN where R(1) ≤ 0.
double f0_error(double F1, double R1) { return R1 > 0 ? F1 / R1 - 1 : std::numeric_limits<double>::quiet_NaN(); }

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
    if ((constraints.pin_f0 || constraints.f0_tolerance) && !model.can_pin_f0())
        throw UsageError("--pin F0: model " + std::string(model.id()) + " cannot hold F(1) at a given value");
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
    // --f0-tolerance: per channel, why the constrained fit was not kept (it needs a parameter outside its bounds).
    std::array<std::string, 3> f0_refused;
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
        ChannelConstraints channel_constraints;
        channel_constraints.unit_range = constraints.gamut_fit;
        std::optional<ChannelFit> unpinned;  // --pin F0: kept where the pin needs a parameter outside its bounds
        if (constraints.pin_f0) {
            // The unconstrained optimum is the best start of the pinned fit (from the others alone LM stops in local
            // minima: rational on zinc, 19 % instead of 1.3 %).
            channel_constraints.pinned_f0 = R1[c];
            ChannelFit free = model.fit(target, starts);
            if (!free.params.empty()) {
                starts.insert(starts.begin(), NamedStart{"unpinned optimum", free.params});
                unpinned = std::move(free);
            }
        }
        std::optional<ChannelFit> kept, free_fit;
        if (constraints.f0_tolerance && R1[c] > 0) {
            // A channel whose unconstrained optimum meets the tolerance keeps it (the constrained optimum cannot be
            // lower); else F(1) is a bounded unknown, from the unconstrained optimum first and every start.
            const double T = *constraints.f0_tolerance;
            ChannelFit free = model.fit(target, starts);
            if (!free.params.empty() &&
                std::abs(f0_error(model.evaluate(std::span<const double>(free.params), 1.0), R1[c])) <= T)
                kept = std::move(free);
            else {
                if (!free.params.empty()) {
                    starts.insert(starts.begin(), NamedStart{"unconstrained optimum", free.params});
                    free_fit = std::move(free);
                }
                // A hair inside the interval, so that the F(1) computed back from the parameters stays within T.
                const double t = T * (1 - 1e-9);
                channel_constraints.f0_range = std::array<double, 2>{R1[c] * (1 - t), R1[c] * (1 + t)};
            }
        }
        ChannelFit channel = kept ? std::move(*kept) : model.fit(target, starts, channel_constraints);
        // The parameter computed from F(1) may need a value outside its bounds (gold's red R(1) = 1.038 in Linear
        // Rec.709 asks Gulbrandsen's r > 1): such parameters are never kept; the unconstrained fit stays, and the
        // record says that the model cannot meet the tolerance.
        if (channel_constraints.f0_range && free_fit) {
            if (channel.params.empty()) {
                f0_refused[c] = "a parameter outside its bounds from every start";
                channel = std::move(*free_fit);
            } else if (const std::string out = outside_bounds(model, channel.params); !out.empty()) {
                f0_refused[c] = out;
                channel = std::move(*free_fit);
            } else if (!(std::abs(f0_error(model.evaluate(std::span<const double>(channel.params), 1.0), R1[c])) <=
                         *constraints.f0_tolerance * (1 + 1e-9))) {
                f0_refused[c] = "an F(1) the model cannot take";  // lazanyi's k from n where R(1) > 1
                channel = std::move(*free_fit);
            }
        }
        // --pin F0 where F(1) = R(1) needs a parameter outside its bounds (gold's red R(1) = 1.038 asks Gulbrandsen's
        // r > 0.99999) or no start holds it: the pin is refused for this channel and the unpinned fit kept, said in
        // fit.refused and on stderr (an export must never carry parameters outside the model's own bounds).
        if (channel_constraints.pinned_f0) {
            std::string needs;
            if (channel.params.empty())
                needs = "parameters no start reaches inside the bounds";
            else if (const std::string out = outside_bounds(model, channel.params); !out.empty())
                needs = out;
            else if (const double F1 = model.evaluate(std::span<const double>(channel.params), 1.0);
                     !(std::abs(F1 - R1[c]) <= 1e-9))
                needs = "a value the model cannot take (F(1) = " + number(F1) + ")";
            if (!needs.empty() && unpinned) {
                fit.refused[c] = "--pin F0 refused: F(1) = R(1) = " + number(R1[c]) + " needs " + needs +
                                 "; the unpinned fit is kept (F(1) = " +
                                 number(model.evaluate(std::span<const double>(unpinned->params), 1.0)) + ")";
                channel = std::move(*unpinned);
            }
        }
        // Every start ended on parameters that are no curve (rational: a pole in [0, 1]): the first start that is
        // a curve inside the bounds is kept as it is, and the channel is reported as unrepresentable.
        if (channel.params.empty() && !constraints.gamut_fit)
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
                                     " fit converged" + (constraints.gamut_fit ? " inside [0, 1] (--gamut-fit)" : ""));
        fit.value.params[c] = channel.params;
        fit.solver[c] = channel.solver;
    }
    clock.charge(t.ceres);
    fit.value.metrics = compute_metrics(model, fit.value.params, reference);

    // Never worse than a closed form inside the bounds, channel by channel (a start clamped into the bounds can end up
    // worse). A closed form outside the bounds that fits better is not kept (exports would carry parameters the model
    // does not allow, issue 13 item 11): the record says that the model cannot represent the data.
    // Under --pin F0 only closed forms that meet the pin compete.
    const auto competes = [&](const ClosedFormResult& form, int c) {
        if (!form.value) return false;
        if (constraints.gamut_fit) return curve_excess_outside_unit_range(model, form.value->params[c]) == 0;
        if (constraints.f0_tolerance)
            return R1[c] > 0 ? std::abs(f0_error(model.evaluate(std::span<const double>(form.value->params[c]), 1.0),
                                                 R1[c])) <= *constraints.f0_tolerance
                             : true;
        if (!constraints.pin_f0 || !fit.refused[c].empty()) return true;  // a refused pin: the unpinned fit competes
        return std::abs(model.evaluate(std::span<const double>(form.value->params[c]), 1.0) - R1[c]) <= 1e-12;
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
        // The pin computes a parameter, which the data may push out of its bounds (F0 ≥ 1 for n, k models).
        if (!fit.refused[c].empty()) {
            fit.unrepresentable[c] = fit.refused[c] + ": the model cannot represent these data" +
                                     (constraints.pin_f0 ? " with F0 pinned" : "");
        } else if (constraints.pin_f0) {
            const std::string out = outside_bounds(model, fit.value.params[c]);
            const double F1 = model.evaluate(std::span<const double>(fit.value.params[c]), 1.0);
            if (!out.empty() || !(std::abs(F1 - R1[c]) <= 1e-9))
                fit.unrepresentable[c] =
                    "--pin F0: F(1) = R(1) = " + number(R1[c]) + " needs " +
                    (out.empty() ? "a value the model cannot take (F(1) = " + number(F1) + ")" : out) +
                    ": the model cannot represent these data with F0 pinned";
        }
        // The F(1) within the tolerance computes a parameter too, which may need a value outside its bounds.
        if (constraints.f0_tolerance) {
            const double err = fit.value.metrics.err_f0[c];
            if (!f0_refused[c].empty() || std::abs(err) > *constraints.f0_tolerance)
                fit.unrepresentable[c] =
                    "--f0-tolerance " + number(*constraints.f0_tolerance) + ": err_f0 = " + number(err) +
                    (f0_refused[c].empty()
                         ? std::string()
                         : " (the constrained fit needs " + f0_refused[c] + "; the unconstrained fit is kept)") +
                    ": the model cannot represent these data within the F0 tolerance";
        }
    }
    clock.charge(t.metrics);
    return result;
}

MaterialFit fit_material(const Material& material, const Colorimetry& colorimetry, const ColorSpaceConverter& converter,
                         const MaterialFitRequest& request) {
    PhaseClock clock;
    FitTimings timings;
    const ReferenceCurve curve(material, colorimetry, converter, request.spectral);
    auto shared_reference = std::make_shared<const SampledReference>(curve, request.error);
    const SampledReference& reference = *shared_reference;
    clock.charge(timings.reference);
    if (request.error.metric == ErrorMetric::rel && reference.rel_undefined())
        throw InputError(InputLocation(material.provenance.file), "relative error undefined for " + material.id + ": " +
                                                                      *reference.rel_undefined() +
                                                                      " (use the abs error metric)");
    MaterialFit result{material, curve.raw_white(), curve(1.0), {}, {}, shared_reference};
    // What --extrapolate did travels with the material's own warnings: the record, the CLI and the exports say it.
    result.material.warnings.insert(result.material.warnings.end(), curve.held_constant().begin(),
                                    curve.held_constant().end());
    const ClosedFormInput input = closed_form_input(curve, material, request.spectral);
    for (const Model* model : request.models) {
        // A model that starts from another's fit takes it from this material's results where it was fitted already.
        const ModelResult* related = nullptr;
        for (const ModelResult& done : result.models)
            if (!model->starts_from().empty() && done.model->id() == model->starts_from()) related = &done;
        result.models.push_back(fit_model(*model, reference, input, &timings, request.constraints, related));
    }
    result.timings = timings;
    return result;
}

}  // namespace metalfit
