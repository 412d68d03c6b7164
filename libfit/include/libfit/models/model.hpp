// Model: the runtime view of one cheap Fresnel model (its parameters, evaluation, closed forms, fit and GLSL).
// Each model is defined once, as one folder libfit/models/<model>/ (struct, closed forms, GLSL) and one line in libfit/models/registry.hpp; this interface is
// what the fitter, the exporters and the renderer use.
#pragma once

#include <array>
#include <complex>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "libfit/color/color.hpp"

namespace metalfit {

struct Parameter {
    std::string_view name;     // as in exports and JSON ("F0", "tint", "n", "k", "a", "alpha", "r", "g")
    double lower = 0.0;        // fit bounds: wide enough to keep out-of-gamut values (F0 > 1)
    double upper = 0.0;
    std::string_view meaning;  // one line for docs and export headers
};

// One channel's parameter values, in the order of Model::parameters().
using ChannelParameters = std::vector<double>;
// Values for R, G, B.
using RgbParameters = std::array<ChannelParameters, 3>;

// What closed forms are computed from.
struct ClosedFormInput {
    std::function<RGB(double mu)> reference;               // R_c(μ), white balanced
    std::function<std::complex<double>(double nm)> eta;    // measured η(λ)
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
    RgbParameters params() const;        // requires defined()
    std::string undefined_reason() const;  // "red: ...; blue: ..." (empty when defined)
};

// One channel of a reference curve at the quadrature nodes, ready for least squares:
// residual_i = scale_i (M(μ_i) − value_i) with scale_i = sqrt(W_i w(μ_i)) / (value_i for rel, 1 for abs),
// so that ½ Σ residual² = ½ (chosen rms)².
struct ChannelTarget {
    std::vector<double> mu;
    std::vector<double> value;
    std::vector<double> scale;
};

struct SolverSummary {
    std::string start;        // which start won ("closed r1", "neutral 2", ...)
    int iterations = 0;       // of the winning start
    std::string termination;  // Ceres termination type
    double initial_cost = 0;  // ½ Σ residual² at the winning start
    double final_cost = 0;
    int starts = 0;           // how many starts were tried
};

struct ChannelFit {
    ChannelParameters params;
    SolverSummary solver;
};

// A start of the fit: "closed r1", "neutral 1", ...
struct NamedStart {
    std::string name;
    ChannelParameters params;
};

class Model {
public:
    virtual ~Model() = default;

    virtual std::string_view id() const = 0;     // "f82-tint"
    virtual std::string_view title() const = 0;  // "F82-tint (Hoffman 2019; OpenPBR)"
    virtual std::span<const Parameter> parameters() const = 0;

    virtual double evaluate(std::span<const double> params, double mu) const = 0;
    virtual float evaluate(std::span<const float> params, float mu) const = 0;
    RGB evaluate(const RgbParameters& params, double mu) const;

    // Every closed form of the model (defined or not), in a fixed order.
    virtual std::vector<ClosedForm> closed_forms(const ClosedFormInput& input) const = 0;
    // Starts that do not depend on the data, tried next to the closed forms.
    virtual std::vector<ChannelParameters> neutral_starts() const = 0;
    // Starts computed from the target itself, where a model has parameters it is linear in (solved exactly for a grid
    // of the others: variable projection). Empty for most models.
    virtual std::vector<ChannelParameters> target_starts(const ChannelTarget& target) const = 0;
    // Ceres fit of one channel from each start (clamped into the bounds); the best result wins.
    virtual ChannelFit fit(const ChannelTarget& target, std::span<const NamedStart> starts) const = 0;

    // GLSL: the name of the model's function, vec3 <name>(vec3 param..., float mu), and the source text of it and
    // of every function it calls (the .glsl files of the model folders, embedded at build time).
    virtual std::string_view glsl_function() const = 0;
    std::string glsl_source() const;
    // Shader source files of this model in dependency order ("schlick", "f82_tint").
    virtual std::span<const std::string_view> glsl_files() const = 0;
};

// All models in a fixed order: schlick, lazanyi, lazanyi-comp, f82-tint, conductor-rgb, gulbrandsen.
std::span<const Model* const> all_models();
// Throws UsageError listing the known ids.
const Model& find_model(std::string_view id);
// "m1,m2" or "all" → models, in the order given (duplicates removed).
std::vector<const Model*> parse_model_list(std::string_view list);

// The embedded text of libfit/models/<model>/<file>.glsl; throws std::out_of_range for an unknown file.
std::string_view shader_file(std::string_view file);
// The GLSL of several models with each shared function once, in dependency order.
std::string glsl_library(std::span<const Model* const> models);

}  // namespace metalfit
