#include "rim_effect.hpp"

#include "glpreview/render/preview_passes.hpp"
#include "glpreview/render/rim_view.hpp"

namespace metalfit::glpreview {
namespace {

using graph::Builder;
using graph::Handle;
using graph::Out;
using graph::Processor;
using graph::Resources;

class RimEffect final : public Effect {
public:
    std::string_view name() const override { return "rim"; }

    void add_output_passes(PreviewGraph& g) const override {
        if (!g.scene.outputs.rim) {
            g.graph.skip("rim", "outputs.rim is off");
            return;
        }
        PreviewRun* run = g.run;
        const PreviewHandles& h = g.handles;
        const Handle<Image> view =
            g.graph
                .add_pass<Out<Image>>(
                    {"rim",
                     "per sphere: the outer 10 % of the radius unwrapped (model, reference, signed error) beside "
                     "F(mu) with the rim's mu range",
                     Processor::cpu},
                    [&](Builder& b, Out<Image>& d) {
                        b.read(h.beauty);
                        b.read(h.reference);
                        if (h.fit_reference) b.read(*h.fit_reference);
                        d.out = b.produce<Image>("rim-image");
                    },
                    [run, beauty = h.beauty, reference = h.reference, fit = h.fit_reference](const Out<Image>& d,
                                                                                             Resources& r) {
                        const RimInputs in{
                            run->scene,   r.get(beauty),          r.get(reference), fit ? &r.get(*fit) : nullptr,
                            run->fresnel, run->reference_fresnel, run->luminance,   run->exposure,
                            true};
                        r.emplace(d.out, rim_view_image(in));
                    })
                .out;
        add_image_file_pass(g.graph, "rim.png", view, run, PngExposure::already_applied);
    }
};

}  // namespace

const Effect& rim_effect() {
    static const RimEffect effect;
    return effect;
}

}  // namespace metalfit::glpreview
