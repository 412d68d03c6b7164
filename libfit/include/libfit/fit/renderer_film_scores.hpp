// What each renderer's thin-film approximation draws for a metal under a film, scored against the stack's spectral
// reference curve with the fits' metrics (`metalfit table METAL --film FILM --thickness A:B:Cnm --renderers`).
// The approximations are optics/renderer_thin_film.hpp's; docs/colour.md, "What renderers draw for a thin film".
#pragma once

#include <nlohmann/json.hpp>

#include <array>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "libfit/fit/metrics.hpp"
#include "libfit/io/layer_stack.hpp"
#include "libfit/optics/renderer_thin_film.hpp"
#include "libfit/reference/reference_curve.hpp"
#include "libfit/reference/sampled_reference.hpp"

namespace metalfit {

// belcour_barla_working: Belcour & Barla with XYZ converted into the working space (white E balanced to 1) instead
// of CIE 1931 RGB: what the hard-coded CIE 1931 RGB of the other two costs.
// materialx_nk: MaterialX given the metal's measured n, k at 650, 550 and 450 nm instead of the conductor-rgb fit
// (whose n, k match the bare metal's reflectance, not its phase).
enum class FilmRenderer { materialx, materialx_nk, belcour_barla, belcour_barla_working, three_wavelength };
inline constexpr std::array<FilmRenderer, 5> kFilmRenderers{
    FilmRenderer::materialx, FilmRenderer::materialx_nk, FilmRenderer::belcour_barla,
    FilmRenderer::belcour_barla_working, FilmRenderer::three_wavelength};
// "materialx", "materialx-nk", "belcour-barla", "belcour-barla-working", "airy-3"
std::string_view film_renderer_id(FilmRenderer r);
std::string_view film_renderer_title(FilmRenderer r);  // one line: what it evaluates

// Why a film under a coat is not scored (the report says it where the scores would be; `table --renderers` refuses
// --coat): the formulas put air above the film.
inline constexpr std::string_view kRendererFilmUnderCoat =
    "not scored: a coat lies over the film, and MaterialX's and Belcour & Barla's thin-film formulas take air above "
    "the film (as metalfit table --renderers, which refuses --coat)";

// What the approximations are given, as a user of each renderer would give it.
struct RendererFilmConstants {
    // The metal per RGB channel for MaterialX and Belcour & Barla: the bare metal's fitted conductor-rgb n, k (what
    // metalfit's MaterialX export writes into conductor_bsdf: MaterialX's own conductor Fresnel with them is the
    // closest it draws the bare metal).
    ChannelIndices metal{};
    ChannelIndices metal_at_wavelengths{};  // the metal's n, k at kThreeWavelengthsNm (materialx-nk's)
    double film_ior = 1.0;  // their one film index: the film's n at kLayerIndexWavelengthNm (550 nm), k dropped
    // XYZ (white E) → the working space's RGB, each row scaled so that XYZ (1, 1, 1) gives (1, 1, 1): the working
    // space as belcour_barla_working's output (the converter's matrix, probed with the unit vectors).
    XyzToRgbMatrix xyz_to_working = kXyzToCie1931Rgb;
};

struct RendererScore {
    FilmRenderer renderer{};
    Metrics metrics;
    RGB f0, f82;              // the approximation at μ = 1 and μ = 1/7
    double shift_de2000 = 0;  // CIEDE2000 between its own F0 and F82 colours (the angle's colour shift it draws)
};

struct RendererScoreRow {
    double thickness_nm = 0;
    RGB truth_f0, truth_f82;
    double truth_shift_de2000 = 0;      // CIEDE2000 between the truth's F0 and F82 colours
    std::vector<RendererScore> scores;  // in kFilmRenderers' order
};

struct RendererFilmScores {
    std::string description;  // "titanium under a TiO2 (Siefke) film of 0–300 nm"
    std::string metal_id, space;
    std::string film_id, film_name;
    RendererFilmConstants constants;
    std::vector<RendererScoreRow> rows;
};

struct RendererFilmInputs {
    Material metal;  // bare (its layers are replaced)
    LayerMaterial film;
    std::vector<double> thicknesses_nm;
    ErrorSettings error;  // the metrics' nodes, metric and weight (as fit's)
};

// The metal's constants (a conductor-rgb fit of the bare metal) and, per thickness, each approximation's metrics
// against the stack's reference curve. Throws InputError as the oxide chart does (a film not covering the range).
RendererFilmScores renderer_film_scores(const RendererFilmInputs& inputs, const Colorimetry& colorimetry,
                                        const ColorSpaceConverter& working, SpectralOptions spectral);

// One approximation's RGB curve at μ for a metal under `film` of `thickness_nm` (the stack's own optics at 650, 550
// and 450 nm for airy-3).
RGB renderer_film_curve(FilmRenderer renderer, const RendererFilmConstants& constants,
                        const std::array<StackOptics<double>, 3>& three_wavelengths, double thickness_nm, double mu);

// The scores of an RGB curve against a sampled reference: libfit's compute_metrics on the curve as a model.
Metrics curve_metrics(const std::function<RGB(double)>& curve, const SampledReference& reference);

std::string renderer_film_scores_markdown(const RendererFilmScores& scores);
std::string renderer_film_scores_csv(const RendererFilmScores& scores);
nlohmann::ordered_json renderer_film_scores_json(const RendererFilmScores& scores);  // schemas/renderer-film-scores

}  // namespace metalfit
