// Model: the runtime view of one cheap Fresnel model (its parameters, evaluation, closed forms, fit, GLSL and what
// the exporters need to know of it). Each model is defined once, as one folder libfit/models/<model>/ (struct, closed
// forms, GLSL) and one line in libfit/models/registry.hpp; this interface, derived from the struct, is what the
// fitter, the exporters, the benchmarks and the renderer use.
#pragma once

#include <array>
#include <complex>
#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "libfit/color/color.hpp"
#include "libfit/reference/channel_target.hpp"

namespace metalfit {

// What a parameter is, for the exporters: a colour (a reflectance or a ratio of reflectances, to which the gamut
// policy applies and which colour-managed consumers tag), an optical index (n, k: never changed), or a shape
// parameter of the curve (an amplitude or exponent: never changed). Every parameter must state one.
enum class ParameterKind { unstated, colour, index, shape };

struct Parameter {
    std::string_view name;  // as in exports and JSON ("F0", "tint", "n", "k", "a", "alpha", "r", "g")
    double lower = 0.0;     // fit bounds: wide enough to keep out-of-gamut values (F0 > 1)
    double upper = 0.0;
    std::string_view meaning;  // one line for docs and export headers
    ParameterKind kind = ParameterKind::unstated;
};

// How a model is written as MaterialX 1.39 (a trait of the model, checked at compile time in registry.hpp):
//   generalized_schlick: the model is an F82-tint curve (it has to_f82_tint), generalized_schlick_bsdf;
//   conductor_bsdf:      parameters n, k → conductor_bsdf ior, extinction;
//   artistic_ior:        parameters r, g → artistic_ior (reflectivity, edge_color) feeding conductor_bsdf;
//   stand_in:            MaterialX cannot express the model: its closest expressible fit (f82-tint) is written,
//                        with the reason the model states (kMaterialxStandIn) and both errors in the header.
enum class MaterialxForm { generalized_schlick, conductor_bsdf, artistic_ior, stand_in };

// One channel's parameter values, in the order of Model::parameters().
using ChannelParameters = std::vector<double>;

// The parameters of a model for R, G and B: by channel (what a model evaluates) or by parameter (an RGB colour per
// parameter, what exports write), without transposing by hand.
class ModelParameters {
public:
    ModelParameters() = default;
    ModelParameters(ChannelParameters red, ChannelParameters green, ChannelParameters blue)
        : channels_{std::move(red), std::move(green), std::move(blue)} {}

    // Channel c (0 red, 1 green, 2 blue); throws std::out_of_range otherwise.
    const ChannelParameters& operator[](int c) const { return channels_.at(static_cast<std::size_t>(c)); }
    ChannelParameters& operator[](int c) { return channels_.at(static_cast<std::size_t>(c)); }
    // Parameter i of every channel as a colour; throws std::out_of_range for an index a channel does not have.
    RGB parameter(std::size_t i) const { return {channels_[0].at(i), channels_[1].at(i), channels_[2].at(i)}; }
    void set_parameter(std::size_t i, const RGB& value) {
        for (int c = 0; c < 3; ++c) (*this)[c].at(i) = value[c];
    }
    // Parameters per channel (that of red; all channels of a model have the same count).
    std::size_t size() const { return channels_[0].size(); }
    bool operator==(const ModelParameters&) const = default;

private:
    std::array<ChannelParameters, 3> channels_;
};

// What closed forms are computed from.
struct ClosedFormInput {
    std::function<RGB(double mu)> reference;             // R_c(μ), white balanced
    std::function<std::complex<double>(double nm)> eta;  // measured η(λ); empty where the target has none
};

// One closed form of a model: parameters per channel, or why it is undefined there.
struct ClosedFormChannel {
    std::optional<ChannelParameters> params;
    std::string undefined;  // reason, when params is empty
};
struct ClosedForm {
    std::string id;           // "r1", "nk-700-550-435", ...
    std::string description;  // one line
    std::array<ClosedFormChannel, 3> channel;

    bool defined() const;
    ModelParameters params() const;        // requires defined()
    std::string undefined_reason() const;  // "red: ...; blue: ..." (empty when defined)
};

struct SolverSummary {
    std::string method;       // how the parameters were solved (the record's `solver.solver`; kCeresSolve, ...)
    std::string start;        // which start won ("closed r1", "neutral 2", ...)
    int iterations = 0;       // of the winning start
    std::string termination;  // Ceres termination type
    double initial_cost = 0;  // ½ Σ residual² at the winning start
    double final_cost = 0;
    int starts = 0;  // how many starts were tried
};

// The methods a fit's parameters are solved by (docs/fit-record.md, `solver.solver`).
inline constexpr const char* kCeresSolve = "Ceres Levenberg-Marquardt, dense QR, bounds";
inline constexpr const char* kProjectedLineSolve =
    "bounded line minimisation of the non-linear parameter (bracketing, then Brent's root search on the derivative); "
    "the linear ones by variable projection";
inline constexpr const char* kProjectedLmSolve =
    "bounded Levenberg-Marquardt on the two non-linear parameters (Kaufman's Jacobian); the linear ones by variable "
    "projection";
inline constexpr const char* kLinearSolve = "linear least squares (variable projection): no iterative solve";

struct ChannelFit {
    ChannelParameters params;
    SolverSummary solver;
    int discarded = 0;          // starts that ended on parameters that are no curve (Model::inadmissible), not kept
    std::string discarded_why;  // the first of them's reason
};

// A start of the fit: "closed r1", "neutral 1", ...
struct NamedStart {
    std::string name;
    ChannelParameters params;
};

// Constraints of one channel's fit (from FitConstraints, whose check_combination has passed: never both).
struct ChannelConstraints {
    // --pin F0: F(1) equals this value exactly (the pinned parameter is computed from the others, Model::pin_f0).
    std::optional<double> pinned_f0;
    // --gamut-fit: the fitted curve stays in [0, 1] at every μ (a penalty on a 4097-point grid, stiffened and
    // tightened until that grid holds it), fitted under that constraint rather than clipped after.
    bool unit_range = false;
    // --f0-tolerance: F(1) within [lower, upper] (R(1)(1 ∓ T)), a true constraint: the pinned parameter is computed
    // from the others and F(1), and F(1) is a free unknown of the solve bounded to this interval.
    std::optional<std::array<double, 2>> f0_range;
};

class Model {
public:
    virtual ~Model() = default;

    virtual std::string_view id() const = 0;     // "f82-tint"
    virtual std::string_view title() const = 0;  // "F82-tint (Hoffman 2019; OpenPBR)"
    virtual std::span<const Parameter> parameters() const = 0;

    virtual double evaluate(std::span<const double> params, double mu) const = 0;
    virtual float evaluate(std::span<const float> params, float mu) const = 0;
    // The curve at every μ of mu into out (out[i] = evaluate(params, mu[i]), bit for bit): the model's own definition
    // in one loop, one virtual call for all of them. Requires out.size() == mu.size().
    virtual void evaluate(std::span<const double> params, std::span<const double> mu, std::span<double> out) const = 0;
    RGB evaluate(const ModelParameters& params, double mu) const;

    // Every closed form of the model (defined or not), in a fixed order.
    virtual std::vector<ClosedForm> closed_forms(const ClosedFormInput& input) const = 0;
    // Starts that do not depend on the data, tried next to the closed forms.
    virtual std::vector<ChannelParameters> neutral_starts() const = 0;
    // Starts computed from the target itself, where a model has parameters it is linear in (solved exactly for a grid
    // of the others: variable projection). Empty for most models.
    virtual std::vector<ChannelParameters> target_starts(const ChannelTarget& target) const = 0;
    // The model whose fitted curve this model can also draw (the same curves in other coordinates: gulbrandsen's are
    // conductor-rgb's), "" where none: the fit starts from that model's optimum, mapped by start_from, first.
    virtual std::string_view starts_from() const { return {}; }
    virtual ChannelParameters start_from(const ChannelParameters& /*related*/) const { return {}; }
    // Ceres fit of one channel from each start (clamped into the bounds); the best result wins.
    virtual ChannelFit fit(const ChannelTarget& target, std::span<const NamedStart> starts,
                           const ChannelConstraints& constraints) const = 0;
    ChannelFit fit(const ChannelTarget& target, std::span<const NamedStart> starts) const {
        return fit(target, starts, ChannelConstraints{});
    }

    // --pin F0: whether the model can hold F(1) at a given value, which parameter it computes for it, and that value
    // written into params (which may then lie outside the parameter's bounds: the data need another F(1)).
    // Why a channel's parameters are no curve a shader may evaluate although inside their bounds (rational: a root
    // of the denominator in [0, 1], a pole), or "" when they are one. The fit never keeps such parameters.
    virtual std::string inadmissible(std::span<const double> /*params*/) const { return {}; }
    virtual bool can_pin_f0() const = 0;
    virtual std::size_t pinned_parameter() const = 0;                    // requires can_pin_f0()
    virtual void pin_f0(std::span<double> params, double F0) const = 0;  // requires can_pin_f0()

    // GLSL: the name of the model's function, vec3 <name>(vec3 param..., float mu), and the source text of it and
    // of every function it calls (the .glsl files of the model folders, embedded at build time).
    virtual std::string_view glsl_function() const = 0;
    virtual std::string glsl_source() const;
    // Shader source files of this model in dependency order ("schlick", "f82_tint").
    virtual std::span<const std::string_view> glsl_files() const = 0;

    // Export traits. The same curve as F82-tint parameters (F0, tint) where the model is an F82-tint curve
    // (Schlick is tint 1), else empty: what MaterialX's generalized_schlick_bsdf and OpenPBR's metal evaluate.
    virtual std::optional<ChannelParameters> f82_tint_of(std::span<const double> params) const = 0;
    virtual bool is_f82_tint_curve() const = 0;
    virtual MaterialxForm materialx_form() const = 0;
    // Why MaterialX cannot express the model (materialx_form() == stand_in), else empty.
    virtual std::string_view materialx_stand_in_reason() const = 0;
};

// All models, in the order of the registry (libfit/models/registry.hpp).
std::span<const Model* const> all_models();
// Throws UsageError listing the known ids.
const Model& find_model(std::string_view id);
// "m1,m2" or "all" → models, in the order given (duplicates removed).
std::vector<const Model*> parse_model_list(std::string_view list);

// The embedded text of libfit/models/<model>/<file>.glsl; throws std::out_of_range for an unknown file.
std::string_view shader_file(std::string_view file);
// The GLSL of several models with each shared function once, in dependency order.
std::string glsl_library(std::span<const Model* const> models);
// The same in WGSL: the <file>.wgsl beside each of those GLSL files, in the same order.
std::string wgsl_library(std::span<const Model* const> models);
// The GLSL files of several models, each once, in dependency order (what glsl_library and wgsl_library join).
std::vector<std::string_view> shader_file_names(std::span<const Model* const> models);

}  // namespace metalfit
