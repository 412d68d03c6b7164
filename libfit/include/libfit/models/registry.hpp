// The model registry: the one list of metalfit's models. Everything that iterates over models — the runtime Model
// adapters (all_models(), find_model()), the benchmark kernels, the typed model tests, the shader embedding (the
// model folders) and the exporters (through the traits below) — is derived from it.
//
// Adding a model: a folder libfit/include/libfit/models/<model>/ with <model>.hpp (the struct, see ModelDefinition),
// <model>.cpp (its closed forms) and <model>.glsl (its GLSL), and one line in Registry below (the build includes
// the folder's header here by itself). Nothing else: a struct that lacks a trait an exporter needs does not compile
// (docs/development.md, "Adding a model").
#pragma once

#include <algorithm>
#include <array>
#include <concepts>
#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "libfit/models/model.hpp"
#include "libfit/models/model_headers.hpp"  // generated: the header of every model folder
#include "libfit/models/model_math.hpp"

namespace metalfit {

template <class... M>
struct ModelList {
    static constexpr std::size_t size = sizeof...(M);
};

// The registry, in the order of listings, records, exports and benchmark tables.
using Registry = ModelList<models::Schlick, models::Lazanyi, models::LazanyiComp, models::F82Tint, models::ConductorRgb,
                           models::Gulbrandsen, models::SchlickCompLinear, models::SchlickComp,
                           models::SchlickCompGeneral, models::Rational>;

// Calls f.template operator()<M>() for every model M of a list, in order.
template <class... M, class F>
constexpr void for_each_model(ModelList<M...>, F&& f) {
    (f.template operator()<M>(), ...);
}

namespace detail {

template <std::size_t N>
constexpr bool every_kind_stated(const std::array<Parameter, N>& parameters) {
    return std::all_of(parameters.begin(), parameters.end(),
                       [](const Parameter& p) { return p.kind != ParameterKind::unstated; });
}

template <std::size_t N>
constexpr bool parameters_are(const std::array<Parameter, N>& parameters, std::string_view first,
                              std::string_view second, ParameterKind kind) {
    return N == 2 && parameters[0].name == first && parameters[1].name == second && parameters[0].kind == kind &&
           parameters[1].kind == kind;
}

}  // namespace detail

// What a model struct must state. The fitter needs the evaluation (templated: float, double, Ceres Jets), bounds,
// closed forms and starts; the renderer and the shader exports its GLSL; the exporters its traits.
template <class M>
concept ModelDefinition = requires(const double* p, double mu, const float* pf, float muf,
                                   const ClosedFormInput& input) {
    { M::kId } -> std::convertible_to<std::string_view>;
    { M::kTitle } -> std::convertible_to<std::string_view>;
    { M::kParameters.size() } -> std::convertible_to<std::size_t>;
    { M::kGlslFunction } -> std::convertible_to<std::string_view>;
    {std::span<const std::string_view>(M::kGlslFiles)};
    { M::evaluate(p, mu) } -> std::same_as<double>;
    { M::evaluate(pf, muf) } -> std::same_as<float>;
    { M::closed_forms(input) } -> std::same_as<std::vector<ClosedForm>>;
    { M::neutral_starts() } -> std::same_as<std::vector<ChannelParameters>>;
    { M::kMaterialx } -> std::convertible_to<MaterialxForm>;
};

// Optional: `static std::string inadmissible(const double* p)`, why parameters inside their bounds are no curve a
// shader may evaluate (rational: a pole in [0, 1]), "" when they are one; the fit discards such starts.
template <class M>
concept CheckedCurve = requires(const double* p) {
    { M::inadmissible(p) } -> std::convertible_to<std::string>;
};

// Whether M can pin F(1) to a given F0 (--pin F0): parameter kPinnedParameter is then a function of the others and
// F0, pinned_value (templated like evaluate), with evaluate(p, 1) = F0 wherever the value lies inside the bounds.
template <class M>
concept PinnableF0 = requires(const double* p, double F0) {
    { M::kPinnedParameter } -> std::convertible_to<std::size_t>;
    { M::pinned_value(p, F0) } -> std::same_as<double>;
};

// Whether M gives its curve's gradient in the parameters in closed form (optional): the fits then use it as the
// Jacobian instead of autodiff. It must return what Ceres's Jets compute, value and derivatives, operation for
// operation (EveryModel.AnalyticGradientIsAutodiffs checks equality): the fits then take the same path. A model whose
// gradient is a closed form of its own (conductor-rgb, gulbrandsen) states kGradientTolerance instead: its
// derivatives agree with the Jets' to that fraction of the gradient's largest component, its value is evaluate's.
template <class M>
concept AnalyticGradient = requires(const double* p, const model_math::CurveNode& node, double* gradient) {
    { M::evaluate_with_gradient(p, node, gradient) } -> std::same_as<double>;
};

// Whether M is an F82-tint curve: it maps its parameters to (F0, tint) of the same curve.
template <class M>
concept F82TintCurve = requires(const double* p) {
    { M::to_f82_tint(p) } -> std::same_as<std::array<double, 2>>;
};

// The compile-time checks of a model's export traits; a model that fails one does not build.
template <ModelDefinition M>
constexpr bool check_model_traits() {
    static_assert(detail::every_kind_stated(M::kParameters),
                  "every parameter states its ParameterKind (colour, index or shape): the gamut policy needs it");
    static_assert(M::kMaterialx != MaterialxForm::generalized_schlick || F82TintCurve<M>,
                  "a model written as generalized_schlick_bsdf maps to F82-tint: give it to_f82_tint()");
    static_assert(M::kMaterialx != MaterialxForm::conductor_bsdf ||
                      detail::parameters_are(M::kParameters, "n", "k", ParameterKind::index),
                  "conductor_bsdf takes a model whose parameters are n, k (index)");
    static_assert(M::kMaterialx != MaterialxForm::artistic_ior ||
                      detail::parameters_are(M::kParameters, "r", "g", ParameterKind::colour),
                  "artistic_ior takes a model whose parameters are r, g (colour)");
    if constexpr (M::kMaterialx == MaterialxForm::stand_in) {
        static_assert(
            requires {
                { M::kMaterialxStandIn } -> std::convertible_to<std::string_view>;
            },
            "a model MaterialX cannot express states why (kMaterialxStandIn)");
        static_assert(!std::string_view(M::kMaterialxStandIn).empty(), "kMaterialxStandIn must say why");
    }
    return true;
}

template <class... M>
constexpr bool check_registry(ModelList<M...>) {
    return (check_model_traits<M>() && ...);
}
static_assert(check_registry(Registry{}));

// The stand-in the MaterialX and OpenPBR exports write where a model has no native form: F82-tint.
using StandInModel = models::F82Tint;

// The runtime model of a registry type.
template <ModelDefinition M>
const Model& model_of() {
    return find_model(M::kId);
}

}  // namespace metalfit
