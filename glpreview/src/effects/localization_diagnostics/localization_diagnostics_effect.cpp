#include "localization_diagnostics_effect.hpp"

#include "render/embedded_shaders.hpp"

namespace metalfit::glpreview {
namespace {

class LocalizationDiagnosticsEffect final : public Effect {
public:
    std::string_view name() const override { return "localization-diagnostics"; }
    // Last in the registry: its output replaces every lobe's.
    void declare_sphere(const SphereShader& shader, ShaderBuilder& builder) const override {
        if (!shader.diagnostics) return;
        builder.define("LOCALIZATION_DIAGNOSTICS")
            .source(shader_text("localization_diagnostics.glsl"))
            .radiance("localization_diagnostics(p, R)");
    }
};

}  // namespace

const Effect& localization_diagnostics_effect() {
    static const LocalizationDiagnosticsEffect effect;
    return effect;
}

}  // namespace metalfit::glpreview
