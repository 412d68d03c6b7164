#include "fit_error_effect.hpp"

#include <memory>

#include "glpreview/io/image_io.hpp"
#include "glpreview/render/delta_e_view.hpp"
#include "glpreview/render/error_view.hpp"
#include "glpreview/render/exr_metadata.hpp"
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

struct Empty {};

// A pass making a view of the error (`make`: its image and the label's text, from the resources it reads) and the
// pass writing it as `file` (PNG: its pixels are colours, drawn after the exposure).
void add_view_pass(graph::PassGraph& graph, const std::string& name, const std::string& file,
                   const std::string& description, std::function<void(Builder&)> reads,
                   std::function<std::pair<Image, std::string>(Resources&)> make, PreviewRun* run) {
    const Handle<Image> view = graph
                                   .add_pass<Out<Image>>(
                                       {name, description, Processor::cpu},
                                       [&](Builder& b, Out<Image>& d) {
                                           reads(b);
                                           d.out = b.produce<Image>(name + "-image");
                                       },
                                       [make](const Out<Image>& d, Resources& r) {
                                           auto [image, text] = make(r);
                                           draw_view_label(r.emplace(d.out, std::move(image)), text);
                                       })
                                   .out;
    add_image_file_pass(graph, file, view, run, PngExposure::already_applied);
}

// A pass writing the signed error view of `model` against `reference` as `file`.
void add_error_view_pass(graph::PassGraph& graph, const std::string& name, const std::string& file,
                         const std::string& what, Handle<Image> model,
                         std::function<const Image&(Resources&)> reference,
                         std::function<void(Builder&)> read_reference, PreviewRun* run) {
    add_view_pass(
        graph, name, file,
        what + ": signed relative luminance error in false colour, log scale from the data, colour bar",
        [model, read_reference](Builder& b) {
            b.read(model);
            read_reference(b);
        },
        [model, reference, what, run](Resources& r) {
            ErrorScale scale;
            Image view = error_view_image(r.get(model), reference(r), run->luminance, scale);
            return std::pair{std::move(view), what + ", " + scale_label(scale)};
        },
        run);
}

class FitErrorEffect final : public Effect {
    // ΔE2000 of beauty against the traced reference per pixel (render/delta_e_view): delta-e.exr (one float
    // channel) and delta-e.png (its sequential view, colour bar, label).
    static void add_delta_e_passes(PreviewGraph& g) {
        PreviewRun* run = g.run;
        const Outputs& o = g.scene.outputs;
        const Handle<Image> beauty = g.handles.beauty;
        const Handle<ReferenceRender> reference = g.handles.reference;
        const Handle<std::vector<double>> delta_e =
            g.graph
                .add_pass<Out<std::vector<double>>>(
                    {"delta-e",
                     "CIEDE2000 of beauty against the traced reference per pixel (L*a*b* on the white Y = 1)",
                     Processor::cpu},
                    [&](Builder& b, Out<std::vector<double>>& d) {
                        b.read(beauty);
                        b.read(reference);
                        d.out = b.produce<std::vector<double>>("delta-e-values");
                    },
                    [run, beauty, reference](const Out<std::vector<double>>& d, Resources& r) {
                        r.emplace(d.out, delta_e_2000(r.get(beauty), r.get(reference).image, run->delta_e));
                    })
                .out;
        if (o.exr)
            g.graph.add_pass<Empty>(
                {"write delta-e.exr", "one float channel, ΔE2000", Processor::cpu},
                [&](Builder& b, Empty&) {
                    b.read(delta_e);
                    b.write_file("delta-e.exr");
                },
                [run, delta_e](const Empty&, Resources& r) {
                    if (run->output_dir.empty()) return;
                    const Scene& scene = run->scene;
                    const std::vector<double>& values = r.get(delta_e);
                    write_exr_channel(run->output_file("delta-e.exr"), scene.width, scene.height,
                                      std::vector<float>(values.begin(), values.end()), "deltaE",
                                      image_metadata(run->exr_metadata, "delta-e.exr"));
                });
        if (!o.png) return;
        add_view_pass(
            g.graph, "delta-e-view", "delta-e.png",
            "ΔE2000 per pixel in a sequential colour map, linear scale, colour bar",
            [delta_e](Builder& b) { b.read(delta_e); },
            [delta_e, run](Resources& r) {
                DeltaEScale scale;
                Image view = delta_e_view_image(r.get(delta_e), run->scene.width, run->scene.height, scale);
                return std::pair{std::move(view),
                                 "dE2000 beauty vs traced reference (white Y = 1), " + delta_e_scale_label(scale)};
            },
            run);
    }

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
        add_delta_e_passes(g);
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
