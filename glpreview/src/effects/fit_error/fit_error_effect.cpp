#include "fit_error_effect.hpp"

#include <memory>

#include "glpreview/io/image_text.hpp"
#include "glpreview/render/error_view.hpp"
#include "glpreview/render/frame_inputs.hpp"
#include "glpreview/render/gpu_renderer.hpp"
#include "glpreview/render/preview_passes.hpp"
#include "libfit/base/text.hpp"

namespace metalfit::glpreview {
namespace {

using graph::Builder;
using graph::Handle;
using graph::Out;
using graph::Processor;
using graph::Resources;

// The view's label, in a band at the top of the image (white text, OpenImageIO's render_text).
void label(Image& view, const std::string& text) {
    const int band = std::clamp(view.height / 12, 8, 28);
    draw_text(view, {{0, 0, view.width, band, text, band - 2}});
}

// A pass writing the signed error view of `model` against `reference` as `file` (PNG: its pixels are colours).
void add_error_view_pass(graph::PassGraph& graph, const std::string& name, const std::string& file,
                         const std::string& what, Handle<Image> model,
                         std::function<const Image&(Resources&)> reference,
                         std::function<void(Builder&)> read_reference, PreviewRun* run) {
    const Handle<Image> view =
        graph
            .add_pass<Out<Image>>(
                {name, what + ": signed relative luminance error in false colour, log scale from the data, colour bar",
                 Processor::cpu},
                [&](Builder& b, Out<Image>& d) {
                    b.read(model);
                    read_reference(b);
                    d.out = b.produce<Image>(name + "-image");
                },
                [model, reference, what, run](const Out<Image>& d, Resources& r) {
                    ErrorScale scale;
                    Image& out = r.emplace(d.out, error_view_image(r.get(model), reference(r), run->luminance, scale));
                    label(out, what + ", " + scale_label(scale));
                })
            .out;
    add_image_file_pass(graph, file, view, run, PngExposure::already_applied);
}

class FitErrorEffect final : public Effect {
public:
    std::string_view name() const override { return "fit-error"; }

    void add_output_passes(PreviewGraph& g) const override {
        if (!g.features.fit_error) {
            g.graph.skip("reference-lut-frame", g.features.model_fits ? "no difference or metrics asked for"
                                                                      : "no sphere uses a libfit model");
            return;
        }
        PreviewRun* run = g.run;
        PreviewHandles& h = g.handles;
        const FrameInputs& frame = g.frame;
        const Handle<Image> exact =
            g.graph
                .add_pass<Out<Image>>(
                    {"reference-lut-frame",
                     "the beauty frame with every sphere's Fresnel its material's exact reference curve (the same "
                     "localization and lobes): beauty minus it is the models' fit error alone",
                     Processor::gpu},
                    [&](Builder& b, Out<Image>& d) {
                        frame.declare(b);
                        d.out = b.produce<Image>("reference-lut-frame-image");
                    },
                    [run, frame](const Out<Image>& d, Resources& r) {
                        Scene exact_scene = run->scene;
                        for (Sphere& s : exact_scene.spheres) s.fresnel = ReferenceFresnel{};
                        GpuRenderer gpu(exact_scene, plan_features(exact_scene), run->reference_fresnel, nullptr,
                                        &run->context->programs());
                        frame.bind(gpu, r);
                        r.emplace(d.out, gpu.render());
                    })
                .out;
        h.fit_reference = exact;
        const Outputs& o = g.scene.outputs;
        if (!o.difference) return;
        const Handle<Image> signed_difference =
            g.graph
                .add_pass<Out<Image>>(
                    {"fit-error", "beauty - reference-lut-frame per pixel, signed, linear", Processor::cpu},
                    [&](Builder& b, Out<Image>& d) {
                        b.read(h.beauty);
                        b.read(exact);
                        d.out = b.produce<Image>("fit-error-image");
                    },
                    [beauty = h.beauty, exact](const Out<Image>& d, Resources& r) {
                        Image& out = r.emplace(d.out, r.get(beauty));
                        const Image& e = r.get(exact);
                        for (std::size_t i = 0; i < out.rgb.size(); ++i) out.rgb[i] -= e.rgb[i];
                    })
                .out;
        if (o.exr) add_image_file_pass(g.graph, "fit-error.exr", signed_difference, run);
        if (!o.png) return;
        add_error_view_pass(
            g.graph, "fit-error-view", "fit-error.png", "fit error: model / exact curve - 1", h.beauty,
            [exact](Resources& r) -> const Image& { return r.get(exact); }, [exact](Builder& b) { b.read(exact); },
            run);
        add_error_view_pass(
            g.graph, "error-view", "error.png", "total error: model / traced reference - 1", h.beauty,
            [reference = h.reference](Resources& r) -> const Image& { return r.get(reference).image; },
            [reference = h.reference](Builder& b) { b.read(reference); }, run);
    }
};

}  // namespace

const Effect& fit_error_effect() {
    static const FitErrorEffect effect;
    return effect;
}

}  // namespace metalfit::glpreview
