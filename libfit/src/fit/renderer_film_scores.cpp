#include "libfit/fit/renderer_film_scores.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "libfit/base/number_text.hpp"
#include "libfit/base/version.hpp"
#include "libfit/fit/fit.hpp"
#include "libfit/fit/fit_record.hpp"
#include "libfit/reference/stack_grid.hpp"

namespace metalfit {
namespace {

// An RGB curve seen as a model with one parameter per channel, the channel's index: what compute_metrics evaluates.
// Nothing but evaluate is ever called on it (it is no fit family).
class CurveAsModel final : public Model {
public:
    explicit CurveAsModel(const std::function<RGB(double)>& curve) : curve_(curve) {}
    std::string_view id() const override { return "rgb-curve"; }
    std::string_view title() const override { return "an RGB curve"; }
    std::span<const Parameter> parameters() const override { return kParameters; }
    double evaluate(std::span<const double> params, double mu) const override {
        return curve_(mu)[static_cast<int>(params[0])];
    }
    float evaluate(std::span<const float> params, float mu) const override {
        return static_cast<float>(curve_(mu)[static_cast<int>(params[0])]);
    }
    void evaluate(std::span<const double> params, std::span<const double> mu, std::span<double> out) const override {
        for (std::size_t i = 0; i < mu.size(); ++i) out[i] = evaluate(params, mu[i]);
    }
    std::vector<ClosedForm> closed_forms(const ClosedFormInput&) const override { return {}; }
    std::vector<ChannelParameters> neutral_starts() const override { return {}; }
    std::vector<ChannelParameters> target_starts(const ChannelTarget&) const override { return {}; }
    ChannelFit fit(const ChannelTarget&, std::span<const NamedStart>, const ChannelConstraints&) const override {
        throw std::logic_error("an RGB curve is not fitted");
    }
    bool can_pin_f0() const override { return false; }
    std::size_t pinned_parameter() const override { throw std::logic_error("an RGB curve has no pin"); }
    void pin_f0(std::span<double>, double) const override { throw std::logic_error("an RGB curve has no pin"); }
    std::string_view glsl_function() const override { return {}; }
    std::span<const std::string_view> glsl_files() const override { return {}; }
    std::optional<ChannelParameters> f82_tint_of(std::span<const double>) const override { return std::nullopt; }
    bool is_f82_tint_curve() const override { return false; }
    MaterialxForm materialx_form() const override { return MaterialxForm::stand_in; }
    std::string_view materialx_stand_in_reason() const override { return "an RGB curve"; }

private:
    static constexpr std::array<Parameter, 1> kParameters{
        {{"channel", 0.0, 2.0, "the channel of the curve", ParameterKind::shape}}};
    const std::function<RGB(double)>& curve_;
};

Material with_film(const Material& metal, const LayerMaterial& film, double d) {
    Material m = metal;
    auto stack = std::make_shared<LayerStack>();
    stack->film = ThinFilm{film, d};
    m.layers = std::move(stack);
    return m;
}

Material bare(const Material& metal) {
    Material m = metal;
    m.layers = nullptr;
    return m;
}

std::string number(double v) { return significant_text(v, 6); }
std::string fixed4(double v) { return fixed_text(v, 4); }
std::string defined4(double v) { return std::isnan(v) ? "—" : fixed4(v); }
std::string defined2(double v) { return std::isnan(v) ? "—" : fixed_text(v, 2); }

// A mean over the defined values, saying over how many rows when some were not.
struct Mean {
    double sum = 0;
    double count = 0;
    void add(double v) {
        if (!std::isnan(v)) sum += v, count += 1;
    }
    std::string text(std::size_t rows, int decimals = 4) const {
        if (count == 0) return "—";
        std::string t = fixed_text(sum / count, decimals);
        if (count < static_cast<double>(rows)) t += " (" + number(count) + " rows)";
        return t;
    }
};

// The channel with the largest |err_f0|, signed.
double worst_signed(const PerChannel& v) {
    double w = v[0];
    for (double x : v)
        if (std::isnan(x) || std::abs(x) > std::abs(w)) w = x;
    return w;
}

}  // namespace

std::string_view film_renderer_id(FilmRenderer r) {
    switch (r) {
        case FilmRenderer::materialx: return "materialx";
        case FilmRenderer::materialx_nk: return "materialx-nk";
        case FilmRenderer::belcour_barla: return "belcour-barla";
        case FilmRenderer::belcour_barla_working: return "belcour-barla-working";
        case FilmRenderer::three_wavelength: return "airy-3";
    }
    return {};
}

std::string_view film_renderer_title(FilmRenderer r) {
    switch (r) {
        case FilmRenderer::materialx:
            return "MaterialX 1.39.4 mx_fresnel_airy (conductor-rgb n, k; film n(550 nm); CIE 1931 RGB)";
        case FilmRenderer::materialx_nk:
            return "MaterialX 1.39.4 mx_fresnel_airy with the metal's n, k at 650, 550, 450 nm";
        case FilmRenderer::belcour_barla:
            return "Belcour & Barla 2017, per channel (conductor-rgb n, k; film n(550 nm); CIE 1931 RGB)";
        case FilmRenderer::belcour_barla_working:
            return "Belcour & Barla 2017 as above, XYZ into the working space (white E balanced) for CIE 1931 RGB";
        case FilmRenderer::three_wavelength: return "exact Airy at 650, 550, 450 nm (the stack's own n, k there)";
    }
    return {};
}

RGB renderer_film_curve(FilmRenderer renderer, const RendererFilmConstants& k,
                        const std::array<StackOptics<double>, 3>& three, double thickness_nm, double mu) {
    ChannelReflectance r{};
    switch (renderer) {
        case FilmRenderer::materialx: r = materialx_thin_film(mu, k.metal, k.film_ior, thickness_nm); break;
        case FilmRenderer::materialx_nk:
            r = materialx_thin_film(mu, k.metal_at_wavelengths, k.film_ior, thickness_nm);
            break;
        case FilmRenderer::belcour_barla: r = belcour_barla_thin_film(mu, k.metal, k.film_ior, thickness_nm); break;
        case FilmRenderer::belcour_barla_working:
            r = belcour_barla_thin_film(mu, k.metal, k.film_ior, thickness_nm, k.xyz_to_working);
            break;
        case FilmRenderer::three_wavelength: r = three_wavelength_airy(mu, three); break;
    }
    return {r[0], r[1], r[2]};
}

Metrics curve_metrics(const std::function<RGB(double)>& curve, const SampledReference& reference) {
    const CurveAsModel model(curve);
    return compute_metrics(model, ModelParameters({0.0}, {1.0}, {2.0}), reference);
}

RendererFilmScores renderer_film_scores(const RendererFilmInputs& in, const Colorimetry& colorimetry,
                                        const ColorSpaceConverter& working, SpectralOptions spectral) {
    RendererFilmScores out;
    out.metal_id = in.metal.id;
    out.film_id = in.film.id;
    out.film_name = in.film.name;
    out.space = working.space();
    const double first = in.thicknesses_nm.empty() ? 0 : in.thicknesses_nm.front();
    const double last = in.thicknesses_nm.empty() ? 0 : in.thicknesses_nm.back();
    out.description = describe_stack(with_film(in.metal, in.film, first));
    const std::string one = " film of " + number(first) + " nm";
    if (first != last)
        if (const std::size_t at = out.description.rfind(one); at != std::string::npos)
            out.description.replace(at, one.size(), " film of " + number(first) + "–" + number(last) + " nm");

    // The metal as MaterialX's conductor_bsdf is given it: the bare metal's conductor-rgb fit.
    const Material metal = bare(in.metal);
    const ReferenceCurve bare_curve(metal, colorimetry, working, spectral);
    const SampledReference bare_reference(bare_curve, in.error);
    const ModelResult conductor =
        fit_model(find_model("conductor-rgb"), bare_reference, closed_form_input(bare_curve, metal, spectral));
    for (int c = 0; c < 3; ++c)
        out.constants.metal[static_cast<std::size_t>(c)] = {conductor.fit.value.params[c][0],
                                                            conductor.fit.value.params[c][1]};
    out.constants.film_ior = layer_index_summary(in.film).n;
    for (std::size_t c = 0; c < 3; ++c)
        out.constants.metal_at_wavelengths[c] =
            metal.index(kThreeWavelengthsNm[c], spectral.interpolation, spectral.out_of_range);
    for (int j = 0; j < 3; ++j) {
        const RGB column = working(XYZ{j == 0 ? 1.0 : 0.0, j == 1 ? 1.0 : 0.0, j == 2 ? 1.0 : 0.0});
        for (int i = 0; i < 3; ++i) out.constants.xyz_to_working[i][j] = column[i];
    }
    for (auto& row : out.constants.xyz_to_working) {
        const double white = row[0] + row[1] + row[2];
        for (double& v : row) v /= white;
    }

    for (const double d : in.thicknesses_nm) {
        RendererScoreRow row;
        row.thickness_nm = d;
        const Material m = with_film(in.metal, in.film, d);
        const ReferenceCurve curve(m, colorimetry, working, spectral);
        const SampledReference reference(curve, in.error);
        std::array<StackOptics<double>, 3> three;
        for (std::size_t c = 0; c < 3; ++c) {
            const int nm = static_cast<int>(kThreeWavelengthsNm[c]);
            three[c] = stack_optics_on_grid(m, nm, nm, spectral).front();
        }
        row.truth_f0 = curve(1.0);
        row.truth_f82 = curve(kMuF82);
        const std::vector<RGB> truth{row.truth_f0, row.truth_f82};
        const std::vector<Lab> truth_lab = reference.lab(truth);
        row.truth_shift_de2000 = ciede2000(truth_lab[0], truth_lab[1]);
        for (const FilmRenderer r : kFilmRenderers) {
            const std::function<RGB(double)> approximation = [&](double mu) {
                return renderer_film_curve(r, out.constants, three, d, mu);
            };
            RendererScore s;
            s.renderer = r;
            s.metrics = curve_metrics(approximation, reference);
            s.f0 = approximation(1.0);
            s.f82 = approximation(kMuF82);
            const std::vector<RGB> own{s.f0, s.f82};
            const std::vector<Lab> own_lab = reference.lab(own);
            s.shift_de2000 = ciede2000(own_lab[0], own_lab[1]);
            row.scores.push_back(s);
        }
        out.rows.push_back(std::move(row));
    }
    return out;
}

std::string renderer_film_scores_markdown(const RendererFilmScores& s) {
    std::ostringstream o;
    const auto& k = s.constants;
    o << s.description << ": what each renderer's thin film draws, against the stack's spectral curve (linear "
      << s.space << "). MaterialX and Belcour & Barla are given the bare metal's conductor-rgb fit (n "
      << fixed4(k.metal[0].real()) << ", " << fixed4(k.metal[1].real()) << ", " << fixed4(k.metal[2].real()) << "; k "
      << fixed4(k.metal[0].imag()) << ", " << fixed4(k.metal[1].imag()) << ", " << fixed4(k.metal[2].imag())
      << ") and the film's n(550 nm) = " << fixed4(k.film_ior)
      << "; airy-3 the stack's own indices at 650, 550 and 450 nm. rel_rms: worst channel; err_f0: the channel "
         "furthest from the truth, signed; shift: CIEDE2000 between the F0 and F82 colours (the truth's in the "
         "second column).\n\n";
    o << "| d (nm) | truth shift | renderer | rel_rms | abs_rms | err_f0 | ΔE00 mean | ΔE00 max | shift |\n"
         "|---|---|---|---|---|---|---|---|---|\n";
    for (const RendererScoreRow& r : s.rows)
        for (const RendererScore& x : r.scores)
            o << "| " << number(r.thickness_nm) << " | " << fixed_text(r.truth_shift_de2000, 2) << " | "
              << film_renderer_id(x.renderer) << " | " << defined4(worst_channel(x.metrics.rel_rms)) << " | "
              << defined4(worst_channel(x.metrics.abs_rms)) << " | " << defined4(worst_signed(x.metrics.err_f0))
              << " | " << defined2(x.metrics.de2000_mean) << " | " << defined2(x.metrics.de2000_max) << " | "
              << defined2(x.shift_de2000) << " |\n";
    if (!s.rows.empty()) {
        o << "\nMean over the " << s.rows.size()
          << " thicknesses (each over the rows where it is defined, —: rel_rms and err_f0 are undefined where a "
             "channel of the truth is ≤ 0 somewhere, a colour outside the space's gamut):\n\n| renderer | rel_rms | "
             "abs_rms | mean abs err_f0 | ΔE00 mean | ΔE00 max |\n|---|---|---|---|---|---|\n";
        for (std::size_t i = 0; i < kFilmRenderers.size(); ++i) {
            Mean rel, abs_rms, f0, de, de_max;
            for (const RendererScoreRow& r : s.rows) {
                const Metrics& m = r.scores[i].metrics;
                rel.add(worst_channel(m.rel_rms));
                abs_rms.add(worst_channel(m.abs_rms));
                f0.add(std::abs(worst_signed(m.err_f0)));
                de.add(m.de2000_mean);
                de_max.add(m.de2000_max);
            }
            o << "| " << film_renderer_id(kFilmRenderers[i]) << " | " << rel.text(s.rows.size()) << " | "
              << abs_rms.text(s.rows.size()) << " | " << f0.text(s.rows.size()) << " | " << de.text(s.rows.size(), 2)
              << " | " << de_max.text(s.rows.size(), 2) << " |\n";
        }
        o << "\n";
        for (const FilmRenderer r : kFilmRenderers)
            o << "- " << film_renderer_id(r) << ": " << film_renderer_title(r) << "\n";
    }
    return o.str();
}

std::string renderer_film_scores_csv(const RendererFilmScores& s) {
    std::ostringstream o;
    o << "thickness_nm,renderer,rel_rms_r,rel_rms_g,rel_rms_b,abs_rms_r,abs_rms_g,abs_rms_b,err_f0_r,err_f0_g,err_f0_b,de2000_mean,de2000_max,"
         "de2000_max_mu,f0_r,f0_g,f0_b,f82_r,f82_g,f82_b,shift_de2000,truth_f0_r,truth_f0_g,truth_f0_b,"
         "truth_f82_r,truth_f82_g,truth_f82_b,truth_shift_de2000\n";
    const auto g = [](double v) { return significant_text(v, 8); };
    for (const RendererScoreRow& r : s.rows)
        for (const RendererScore& x : r.scores) {
            const Metrics& m = x.metrics;
            o << number(r.thickness_nm) << ',' << film_renderer_id(x.renderer);
            for (double v : m.rel_rms) o << ',' << g(v);
            for (double v : m.abs_rms) o << ',' << g(v);
            for (double v : m.err_f0) o << ',' << g(v);
            o << ',' << g(m.de2000_mean) << ',' << g(m.de2000_max) << ',' << g(m.de2000_max_mu);
            for (const RGB* v : {&x.f0, &x.f82}) o << ',' << g(v->r) << ',' << g(v->g) << ',' << g(v->b);
            o << ',' << g(x.shift_de2000);
            for (const RGB* v : {&r.truth_f0, &r.truth_f82}) o << ',' << g(v->r) << ',' << g(v->g) << ',' << g(v->b);
            o << ',' << g(r.truth_shift_de2000) << '\n';
        }
    return o.str();
}

nlohmann::ordered_json renderer_film_scores_json(const RendererFilmScores& s) {
    using Json = nlohmann::ordered_json;
    const auto triple = [](const auto& v) {
        Json a = Json::array();
        for (int c = 0; c < 3; ++c) {
            const double x = v[c];
            a.push_back(std::isfinite(x) ? Json(x) : Json(nullptr));
        }
        return a;
    };
    const auto colour = [](const RGB& v) { return Json::array({v.r, v.g, v.b}); };
    const RendererFilmConstants& k = s.constants;
    Json matrix = Json::array();
    for (const auto& row : k.xyz_to_working) matrix.push_back(Json::array({row[0], row[1], row[2]}));
    Json renderers = Json::array();
    for (const FilmRenderer r : kFilmRenderers)
        renderers.push_back({{"id", film_renderer_id(r)}, {"title", film_renderer_title(r)}});
    Json rows = Json::array();
    for (const RendererScoreRow& r : s.rows) {
        Json scores = Json::array();
        for (const RendererScore& x : r.scores)
            scores.push_back({{"renderer", film_renderer_id(x.renderer)},
                              {"metrics", metrics_record(x.metrics)},
                              {"err_f0", triple(x.metrics.err_f0)},
                              {"metrics_at_mu",
                               {{"max_rel", triple(x.metrics.max_rel_mu)},
                                {"max_abs", triple(x.metrics.max_abs_mu)},
                                {"de2000_max", x.metrics.de2000_max_mu}}},
                              {"F0", colour(x.f0)},
                              {"F82", colour(x.f82)},
                              {"shift_de2000", x.shift_de2000}});
        rows.push_back(
            {{"thickness_nm", r.thickness_nm},
             {"truth",
              {{"F0", colour(r.truth_f0)}, {"F82", colour(r.truth_f82)}, {"shift_de2000", r.truth_shift_de2000}}},
             {"scores", std::move(scores)}});
    }
    return {
        {"schema", "metalfit.renderer-film-scores/1"},
        {"metalfit_version", METALFIT_VERSION},
        {"description", s.description},
        {"metal", s.metal_id},
        {"film", {{"material", s.film_id}, {"name", s.film_name}}},
        {"space", s.space},
        {"mu_f82", kMuF82},
        {"constants",
         {{"conductor_n", Json::array({k.metal[0].real(), k.metal[1].real(), k.metal[2].real()})},
          {"conductor_k", Json::array({k.metal[0].imag(), k.metal[1].imag(), k.metal[2].imag()})},
          {"metal_n_at_wavelengths", Json::array({k.metal_at_wavelengths[0].real(), k.metal_at_wavelengths[1].real(),
                                                  k.metal_at_wavelengths[2].real()})},
          {"metal_k_at_wavelengths", Json::array({k.metal_at_wavelengths[0].imag(), k.metal_at_wavelengths[1].imag(),
                                                  k.metal_at_wavelengths[2].imag()})},
          {"film_ior", k.film_ior},
          {"film_ior_at_nm", kLayerIndexWavelengthNm},
          {"three_wavelengths_nm",
           Json::array({kThreeWavelengthsNm[0], kThreeWavelengthsNm[1], kThreeWavelengthsNm[2]})},
          {"xyz_to_working", std::move(matrix)}}},
        {"renderers", std::move(renderers)},
        {"rows", std::move(rows)}};
}

}  // namespace metalfit
