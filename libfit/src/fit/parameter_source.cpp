#include "libfit/fit/parameter_source.hpp"

#include "libfit/fit/fit.hpp"

namespace metalfit {

std::string to_string(ParameterSource source) { return std::string(kParameterSourceNames.name(source)); }

ParameterSource parse_parameter_source(const std::string& text) { return kParameterSourceNames.parse(text); }

std::optional<ChosenParameters> choose_parameters(const ModelResult& result, ParameterSource source) {
    if (source == ParameterSource::fit) return ChosenParameters{&result.fit.value, "fit"};
    if (!result.best_closed) return std::nullopt;
    const ClosedFormResult& best = result.closed_forms[*result.best_closed];
    return ChosenParameters{&*best.value, "closed " + best.id};
}

std::string undefined_closed_forms(const ModelResult& result) {
    std::string reasons;
    for (const ClosedFormResult& form : result.closed_forms)
        reasons += (reasons.empty() ? "" : "; ") + form.id + ": " + form.undefined;
    return reasons;
}

}  // namespace metalfit
