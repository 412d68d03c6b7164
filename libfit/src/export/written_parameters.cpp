// The parameters an export writes: the fit or the best closed form (fit/parameter_source), the gamut policy applied
// to colour parameters, the error figures recomputed on what is written; and the F82-tint form of the same curve.
#include <algorithm>

#include "export/export_formats.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/models/registry.hpp"

namespace metalfit {

namespace {

// Applies the gamut policy to the colour parameters; returns one note per parameter that was outside [0, 1].
std::vector<std::string> apply_gamut(const Model& model, ModelParameters& params, GamutPolicy policy) {
    std::vector<std::string> notes;
    const auto parameters = model.parameters();
    for (std::size_t i = 0; i < parameters.size(); ++i) {
        if (parameters[i].kind != ParameterKind::colour) continue;  // the gamut policy applies to colours only
        const std::string name(parameters[i].name);
        const RGB colour = params.parameter(i);
        std::string outside;
        double max = 0;
        for (int c = 0; c < 3; ++c) {
            const double v = colour[c];
            max = std::max(max, v);
            if (v > 1.0 || v < 0.0)
                outside += (outside.empty() ? "" : ", ") + std::string(kChannelNames[c]) + " " + detail::number(v);
        }
        if (outside.empty()) continue;
        switch (policy) {
            case GamutPolicy::keep: notes.push_back(name + " outside [0, 1] (" + outside + "): kept"); break;
            case GamutPolicy::clip:
                params.set_parameter(i, {std::clamp(colour.r, 0.0, 1.0), std::clamp(colour.g, 0.0, 1.0),
                                         std::clamp(colour.b, 0.0, 1.0)});
                notes.push_back(name + " outside [0, 1] (" + outside + "): clipped to [0, 1]");
                break;
            case GamutPolicy::scale:
                for (int c = 0; c < 3; ++c) params[c][i] = std::max(0.0, max > 1.0 ? colour[c] / max : colour[c]);
                notes.push_back(
                    name + " outside [0, 1] (" + outside + "): " +
                    (max > 1.0 ? "scaled by 1/" + detail::number(max) : std::string("negative values set to 0")));
                break;
        }
    }
    return notes;
}

}  // namespace

std::string to_string(GamutPolicy policy) { return std::string(kGamutPolicyNames.name(policy)); }

GamutPolicy parse_gamut_policy(const std::string& text) { return kGamutPolicyNames.parse(text); }

WrittenParameters written_parameters(const ModelResult& result, const SampledReference& reference,
                                     ParameterSource source, GamutPolicy gamut, const std::string& material_id) {
    const Model& model = *result.model;
    WrittenParameters w;
    w.model = &model;
    const std::optional<ChosenParameters> chosen = choose_parameters(result, source);
    if (!chosen)
        throw UsageError(material_id + ": " + std::string(model.id()) + ": no closed form is defined (" +
                         undefined_closed_forms(result) + "); export the fitted parameters instead");
    w.origin = chosen->origin;
    w.params = chosen->value->params;
    w.gamut = apply_gamut(model, w.params, gamut);
    w.metrics = compute_metrics(model, w.params, reference);
    return w;
}

const Model& expressible_stand_in() { return model_of<StandInModel>(); }

namespace detail {

std::optional<WrittenParameters> as_f82_tint(const WrittenParameters& written, const SampledReference& reference) {
    const Model& model = *written.model;
    if (&model == &expressible_stand_in()) return written;
    if (!model.is_f82_tint_curve()) return std::nullopt;
    WrittenParameters w = written;
    w.model = &expressible_stand_in();
    bool tint_one = true;
    for (int c = 0; c < 3; ++c) {
        w.params[c] = *model.f82_tint_of(written.params[c]);
        tint_one = tint_one && w.params[c][1] == 1.0;
    }
    w.origin = written.origin + " of " + std::string(model.id()) + ", written as " + std::string(w.model->id()) +
               (tint_one ? " with tint 1" : "") + " (the same curve)";
    w.metrics = compute_metrics(*w.model, w.params, reference);
    return w;
}

}  // namespace detail
}  // namespace metalfit
