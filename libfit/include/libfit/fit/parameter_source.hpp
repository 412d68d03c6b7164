// Which parameters of a fitted model a consumer uses (an export, a rendered sphere): the Ceres fit, or the model's
// best defined closed form (ModelResult::best_closed). One choice, one rule, for `metalfit export --params` and
// glpreview's `"params"`.
#pragma once

#include <optional>
#include <string>

#include "libfit/base/enum_names.hpp"

namespace metalfit {

struct EvaluatedParameters;  // libfit/fit/fit.hpp
struct ModelResult;

enum class ParameterSource { fit, closed };
inline constexpr EnumNames kParameterSourceNames{
    "parameter source", KnownNamesWording::alternatives,
    std::array{EnumName<ParameterSource>{ParameterSource::fit, "fit"},
               EnumName<ParameterSource>{ParameterSource::closed, "closed"}}};
std::string to_string(ParameterSource source);                    // "fit" | "closed"
ParameterSource parse_parameter_source(const std::string& text);  // "fit" | "closed", else UsageError

// The parameters `source` picks from `result`, and where they come from: "fit", or "closed <form id>".
struct ChosenParameters {
    const EvaluatedParameters* value = nullptr;  // points into `result`
    std::string origin;
};
// Nothing when closed parameters are asked and no closed form of the model is defined for the material (then
// undefined_closed_forms says why).
std::optional<ChosenParameters> choose_parameters(const ModelResult& result, ParameterSource source);
// Why no closed form is defined: "<form id>: <reason>; …" over every closed form of `result`.
std::string undefined_closed_forms(const ModelResult& result);

}  // namespace metalfit
