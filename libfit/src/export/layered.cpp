// A layered material (a coat and/or a thin film over a metal) in the formats that layer them themselves: OpenPBR
// (coat_*, thin_film_*), MaterialX (layer of a dielectric_bsdf over the metal's BSDF; thinfilm_* on it) and glTF
// (KHR_materials_clearcoat, KHR_materials_iridescence). They take one index per layer: its n at 550 nm
// (kLayerIndexWavelengthNm); what they cannot express is said, never hidden (docs/export.md, Layered exports).
#include <cmath>

#include "export/export_formats.hpp"
#include "libfit/base/number_text.hpp"
#include "libfit/io/layer_stack.hpp"

namespace metalfit::detail {

namespace {

std::string short_number(double v) { return significant_text(v, 6); }

// glTF KHR_materials_clearcoat: "The clearcoat layer's index of refraction is fixed at 1.5" (F0 = 0.04).
constexpr double kGltfClearcoatIor = 1.5;

double dielectric_f0(double n) { return std::pow((n - 1.0) / (n + 1.0), 2.0); }

}  // namespace

std::optional<LayeredParameters> layered_parameters(const Material& material) {
    if (!material.layers || material.layers->empty()) return std::nullopt;
    const LayerStack& s = *material.layers;
    LayeredParameters p;
    if (s.coat) {
        p.coat = true;
        p.coat_index = layer_index_summary(s.coat->material);
        p.coat_ior = p.coat_index.n;
        p.coat_absorbs = s.coat->thickness_nm && *s.coat->thickness_nm > 0.0 && p.coat_index.absorbing();
    }
    if (s.film) {
        p.film = true;
        p.film_index = layer_index_summary(s.film->material);
        p.film_ior = p.film_index.n;
        p.film_thickness_nm = s.film->thickness_nm;
        p.film_thickness_um = s.film->thickness_nm / 1000.0;
    }
    return p;
}

std::vector<std::string> layered_notes(const LayeredParameters& p, ExportFormat format) {
    std::vector<std::string> notes;
    const bool gltf = format == ExportFormat::gltf;
    const bool openpbr = format == ExportFormat::openpbr;
    std::string how = "layers: the base is the bare metal's fit (not the stack's), under ";
    if (openpbr)
        how += std::string(p.coat ? "coat_weight 1, coat_ior" : "") + (p.coat && p.film ? " and " : "") +
               (p.film ? "thin_film_weight 1, thin_film_thickness (micrometres), thin_film_ior" : "");
    else if (gltf)
        how += std::string(p.coat ? "KHR_materials_clearcoat" : "") + (p.coat && p.film ? " and " : "") +
               (p.film ? "KHR_materials_iridescence (thickness in nanometres)" : "");
    else
        how += std::string(p.coat ? "a layer with a dielectric_bsdf (the coat) over it" : "") +
               (p.coat && p.film ? " and " : "") +
               (p.film ? "thinfilm_thickness (nanometres) and thinfilm_ior on its BSDF" : "");
    notes.push_back(how + ": the renderer's own layering reproduces the stack");
    if (p.coat) {
        notes.push_back("coat index: n(550 nm) = " + short_number(p.coat_ior) +
                        (p.coat_index.dispersive()
                             ? " (the coat is dispersive: n " + short_number(p.coat_index.n_min) + "-" +
                                   short_number(p.coat_index.n_max) + " over 380-780 nm; one index is written)"
                             : ""));
        if (gltf && std::abs(p.coat_ior - kGltfClearcoatIor) > 1e-12)
            notes.push_back("CANNOT EXPRESS: glTF's clearcoat index is fixed at 1.5 (F0 0.04); this coat's n = " +
                            short_number(p.coat_ior) + " has F0 " + short_number(dielectric_f0(p.coat_ior)) +
                            ": a glTF renderer draws a coat of 1.5, and the base under it is the bare metal's");
        if (p.coat_absorbs)
            notes.push_back("CANNOT EXPRESS: the coat absorbs (k up to " + short_number(p.coat_index.k_max) +
                            " over 380-780 nm through its thickness); " +
                            (openpbr ? "coat_color is left white" : "the coat is written clear") +
                            ": metalfit does not derive a coat colour from k yet, so the renderer's coat is clear");
    }
    if (p.film) {
        notes.push_back("film: " + short_number(p.film_thickness_nm) + " nm (" + short_number(p.film_thickness_um) +
                        " um), index n(550 nm) = " + short_number(p.film_ior));
        if (p.film_index.dispersive())
            notes.push_back("APPROXIMATION: the film is dispersive (n " + short_number(p.film_index.n_min) + "-" +
                            short_number(p.film_index.n_max) +
                            " over 380-780 nm); the format takes one index, its n at 550 nm");
        if (p.film_index.absorbing())
            notes.push_back("CANNOT EXPRESS: the film absorbs (k(550 nm) = " + short_number(p.film_index.k) +
                            ", up to " + short_number(p.film_index.k_max) +
                            " over 380-780 nm); the format's thin film is a clear dielectric (k = 0)");
        if (gltf && p.coat)
            notes.push_back("APPROXIMATION: KHR_materials_iridescence's film sits under the clearcoat but its "
                            "interference is defined against air (outside index 1), not the coat");
    }
    return notes;
}

}  // namespace metalfit::detail
