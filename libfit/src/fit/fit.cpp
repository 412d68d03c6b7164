#include "libfit/fit/fit.hpp"

#include <chrono>
#include <limits>
#include <memory>

#include "libfit/base/errors.hpp"

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

// Adds the seconds since the last call (or construction) to a phase.
class PhaseClock {
public:
    void charge(double& phase) {
        const auto now = std::chrono::steady_clock::now();
        phase += std::chrono::duration<double>(now - last_).count();
        last_ = now;
    }

private:
    std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace

FitTimings& FitTimings::operator+=(const FitTimings& o) {
    reference += o.reference;
    closed_forms += o.closed_forms;
    ceres += o.ceres;
    metrics += o.metrics;
    return *this;
}

ClosedFormInput closed_form_input(const ReferenceCurve& curve, const Material& material, SpectralOptions options) {
    return {[&curve](double mu) { return curve(mu); },
            [&material, options](double nm) { return material.index(nm, options.interpolation, options.out_of_range); }};
}

ModelResult fit_model(const Model& model, const SampledReference& reference, const ClosedFormInput& input,
                      FitTimings* timings) {
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
        ClosedFormResult r{form.id, form.description, {}, {}};
        if (form.defined()) {
            const ModelParameters params = form.params();
            r.value = EvaluatedParameters{params, compute_metrics(model, params, reference)};
            const double worst = worst_channel(r.value->metrics.rms(metric));
            if (worst < best_worst) best_worst = worst, result.best_closed = result.closed_forms.size();
        } else {
            r.undefined = form.undefined_reason();
        }
        result.closed_forms.push_back(std::move(r));
    }

    clock.charge(t.metrics);
    FitResult& fit = result.fit;
    for (int c = 0; c < 3; ++c) {
        const ChannelTarget target = reference.target(c);
        const auto starts = starts_for_channel(model, result.closed_forms, c, target);
        ChannelFit channel = model.fit(target, starts);
        fit.value.params[c] = channel.params;
        fit.solver[c] = channel.solver;
    }
    clock.charge(t.ceres);
    fit.value.metrics = compute_metrics(model, fit.value.params, reference);

    // Never worse than a closed form, channel by channel (a start clamped into the bounds can end up worse).
    bool replaced = false;
    for (int c = 0; c < 3; ++c) {
        double best = fit.value.metrics.rms(metric)[c];
        for (const ClosedFormResult& form : result.closed_forms)
            if (form.value && form.value->metrics.rms(metric)[c] < best) {
                best = form.value->metrics.rms(metric)[c];
                fit.value.params[c] = form.value->params[c];
                fit.fallback[c] = form.id;
                replaced = true;
            }
    }
    if (replaced) fit.value.metrics = compute_metrics(model, fit.value.params, reference);
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
        throw InputError(InputLocation(material.provenance.file),
                         "relative error undefined for " + material.id + ": " + *reference.rel_undefined() +
                             " (use the abs error metric)");
    MaterialFit result{material, curve.raw_white(), curve(1.0), {}, {}, shared_reference};
    // What --extrapolate did travels with the material's own warnings: the record, the CLI and the exports say it.
    result.material.warnings.insert(result.material.warnings.end(), curve.held_constant().begin(), curve.held_constant().end());
    const ClosedFormInput input = closed_form_input(curve, material, request.spectral);
    for (const Model* model : request.models) result.models.push_back(fit_model(*model, reference, input, &timings));
    result.timings = timings;
    return result;
}

}  // namespace metalfit
