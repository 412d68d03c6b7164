#include <algorithm>
#include <stdexcept>
#include <string>
#include <tuple>

#include "libfit/base/errors.hpp"
#include "libfit/models/model.hpp"
#include "libfit/models/registry.hpp"
#include "models/fit_channel.hpp"
#include "shader_files.hpp"

namespace metalfit {

namespace {

// The runtime view of a model struct M (see libfit/models/).
template <class M>
class ModelAdapter final : public Model {
public:
    std::string_view id() const override { return M::kId; }
    std::string_view title() const override { return M::kTitle; }
    std::span<const Parameter> parameters() const override { return M::kParameters; }
    double evaluate(std::span<const double> p, double mu) const override { return M::evaluate(p.data(), mu); }
    float evaluate(std::span<const float> p, float mu) const override { return M::evaluate(p.data(), mu); }
    void evaluate(std::span<const double> p, std::span<const double> mu, std::span<double> out) const override {
        if (out.size() != mu.size())
            throw std::logic_error(std::string(M::kId) + ": " + std::to_string(mu.size()) + " values of mu, room for " +
                                   std::to_string(out.size()));
        for (std::size_t i = 0; i < mu.size(); ++i) out[i] = M::evaluate(p.data(), mu[i]);
    }
    std::vector<ClosedForm> closed_forms(const ClosedFormInput& input) const override { return M::closed_forms(input); }
    std::vector<ChannelParameters> neutral_starts() const override { return M::neutral_starts(); }
    std::vector<ChannelParameters> target_starts(const ChannelTarget& target) const override {
        if constexpr (requires { M::target_starts(target); })
            return M::target_starts(target);
        else
            return {};
    }
    std::string_view starts_from() const override {
        if constexpr (requires { M::kStartsFrom; })
            return M::kStartsFrom;
        else
            return {};
    }
    ChannelParameters start_from(const ChannelParameters& related) const override {
        if constexpr (requires { M::start_from(related); })
            return M::start_from(related);
        else
            return {};
    }
    ChannelFit fit(const ChannelTarget& target, std::span<const NamedStart> starts,
                   const ChannelConstraints& constraints) const override {
        return detail::fit_channel<M>(target, starts, constraints);
    }
    using Model::fit;
    std::string inadmissible(std::span<const double> p) const override {
        if constexpr (CheckedCurve<M>)
            return M::inadmissible(p.data());
        else
            return {};
    }
    bool can_pin_f0() const override { return PinnableF0<M>; }
    std::size_t pinned_parameter() const override {
        if constexpr (PinnableF0<M>)
            return M::kPinnedParameter;
        else
            throw std::logic_error(std::string(M::kId) + " cannot pin F0");
    }
    void pin_f0(std::span<double> params, double F0) const override {
        if constexpr (PinnableF0<M>)
            params[M::kPinnedParameter] = M::pinned_value(params.data(), F0);
        else
            throw std::logic_error(std::string(M::kId) + " cannot pin F0");
    }
    std::string_view glsl_function() const override { return M::kGlslFunction; }
    std::span<const std::string_view> glsl_files() const override { return M::kGlslFiles; }
    std::optional<ChannelParameters> f82_tint_of(std::span<const double> p) const override {
        if constexpr (F82TintCurve<M>) {
            const std::array<double, 2> f82 = M::to_f82_tint(p.data());
            return ChannelParameters(f82.begin(), f82.end());
        } else {
            return std::nullopt;
        }
    }
    bool is_f82_tint_curve() const override { return F82TintCurve<M>; }
    MaterialxForm materialx_form() const override { return M::kMaterialx; }
    std::string_view materialx_stand_in_reason() const override {
        if constexpr (M::kMaterialx == MaterialxForm::stand_in)
            return M::kMaterialxStandIn;
        else
            return {};
    }
};

// One adapter per registry entry, and the table of them in registry order.
template <class List>
struct ModelTable;
template <class... M>
struct ModelTable<ModelList<M...>> {
    std::tuple<ModelAdapter<M>...> adapters;
    std::array<const Model*, sizeof...(M)> models =
        std::apply([](const auto&... a) { return std::array<const Model*, sizeof...(M)>{&a...}; }, adapters);
};
const ModelTable<Registry> kTable;
const auto& kModels = kTable.models;

std::string known_ids() {
    std::string ids;
    for (const Model* m : kModels) ids += (ids.empty() ? "" : ", ") + std::string(m->id());
    return ids;
}

}  // namespace

RGB Model::evaluate(const ModelParameters& params, double mu) const {
    return {evaluate(std::span<const double>(params[0]), mu), evaluate(std::span<const double>(params[1]), mu),
            evaluate(std::span<const double>(params[2]), mu)};
}

std::string Model::glsl_source() const {
    const Model* self = this;
    return glsl_library(std::span<const Model* const>(&self, 1));
}

std::span<const Model* const> all_models() { return kModels; }

const Model& find_model(std::string_view id) {
    for (const Model* m : kModels)
        if (m->id() == id) return *m;
    throw UsageError("unknown model '" + std::string(id) + "' (known: " + known_ids() + ", or all)");
}

std::vector<const Model*> parse_model_list(std::string_view list) {
    if (list == "all") return {kModels.begin(), kModels.end()};
    std::vector<const Model*> models;
    while (!list.empty()) {
        const auto comma = list.find(',');
        const std::string_view id = list.substr(0, comma);
        const Model* m = &find_model(id);
        if (std::find(models.begin(), models.end(), m) == models.end()) models.push_back(m);
        list = comma == std::string_view::npos ? std::string_view{} : list.substr(comma + 1);
    }
    if (models.empty()) throw UsageError("empty model list (known: " + known_ids() + ", or all)");
    return models;
}

std::string_view shader_file(std::string_view file) {
    for (const auto& [name, text] : detail::kShaderFiles)
        if (name == file) return text;
    throw std::out_of_range("no embedded shader file '" + std::string(file) + "'");
}

std::vector<std::string_view> shader_file_names(std::span<const Model* const> models) {
    std::vector<std::string_view> files;
    for (const Model* m : models)
        for (std::string_view f : m->glsl_files())
            if (std::find(files.begin(), files.end(), f) == files.end()) files.push_back(f);
    return files;
}

std::string glsl_library(std::span<const Model* const> models) {
    std::string text;
    for (std::string_view f : shader_file_names(models)) {
        if (!text.empty()) text += '\n';
        text += shader_file(f);
    }
    return text;
}

std::string wgsl_library(std::span<const Model* const> models) {
    std::string text;
    for (std::string_view f : shader_file_names(models)) {
        const auto it = std::find_if(detail::kWgslFiles.begin(), detail::kWgslFiles.end(),
                                     [&](const auto& file) { return file.first == f; });
        if (it == detail::kWgslFiles.end()) throw std::out_of_range("no embedded WGSL file '" + std::string(f) + "'");
        if (!text.empty()) text += '\n';
        text += it->second;
    }
    return text;
}

bool ClosedForm::defined() const {
    return std::all_of(channel.begin(), channel.end(), [](const ClosedFormChannel& c) { return c.params.has_value(); });
}

ModelParameters ClosedForm::params() const {
    if (!defined()) throw std::logic_error("closed form " + id + " is undefined: " + undefined_reason());
    return {*channel[0].params, *channel[1].params, *channel[2].params};
}

std::string ClosedForm::undefined_reason() const {
    std::string reason;
    for (int c = 0; c < 3; ++c)
        if (!channel[c].params)
            reason += (reason.empty() ? "" : "; ") + std::string(kChannelNames[c]) + ": " + channel[c].undefined;
    return reason;
}

}  // namespace metalfit
