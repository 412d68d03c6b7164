#include "localization_diagnostics_effect.hpp"

#include "glpreview/render/frame_inputs.hpp"
#include "glpreview/render/gpu_renderer.hpp"
#include "glpreview/render/preview_passes.hpp"
#include "render/embedded_shaders.hpp"

namespace metalfit::glpreview {
namespace {

using graph::Builder;
using graph::Out;
using graph::Processor;
using graph::Resources;

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

    void add_output_passes(PreviewGraph& g) const override {
        auto& graph = g.graph;
        PreviewRun* run = g.run;
        PreviewHandles& h = g.handles;
        const FrameInputs& frame = g.frame;
        // localization: the impostor's steps taken and final |ρ − 1| per pixel, one diagnostics frame.
        h.localization =
            graph
                .add_pass<Out<Image>>(
                    {"localization", "per pixel: the impostor's refinement steps taken and |ρ − 1| at its lookup point",
                     Processor::gpu},
                    [&](Builder& b, Out<Image>& d) {
                        frame.declare(b);
                        d.out = b.produce<Image>("localization-image");
                    },
                    [run, frame](const Out<Image>& d, Resources& r) {
                        r.emplace(d.out, (frame.bind(run->renderer(), r), run->renderer().render_localization()));
                    })
                .out;
    }
};

}  // namespace

const Effect& localization_diagnostics_effect() {
    static const LocalizationDiagnosticsEffect effect;
    return effect;
}

}  // namespace metalfit::glpreview
