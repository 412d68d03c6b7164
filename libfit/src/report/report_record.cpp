// report.json (schema metalfit.report/1, docs/report.md): per material the provenance, the data, the curves the
// charts plot, every model's record (the same function as the fit record: the same numbers) and the colours of the
// stripes and swatches; per model the cost when one is given; the catalog summary; the chart specs.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "libfit/base/errors.hpp"
#include "libfit/base/file_digest.hpp"
#include "libfit/base/number_text.hpp"
#include "libfit/base/record_path.hpp"
#include "libfit/base/version.hpp"
#include "libfit/export/consumer_curve.hpp"
#include "libfit/fit/catalog_summary.hpp"
#include "libfit/fit/metal_table.hpp"
#include "libfit/fit/renderer_film_scores.hpp"
#include "libfit/io/layer_stack.hpp"
#include "libfit/optics/fresnel.hpp"
#include "libfit/optics/stack_reflectance.hpp"
#include "libfit/reference/reference_curve.hpp"
#include "libfit/reference/stack_grid.hpp"
#include "libfit/report/report.hpp"
#include "report/report_charts.hpp"
#include "report/report_pages.hpp"
#include "report/report_parts.hpp"

namespace metalfit {
namespace {

using Json = nlohmann::ordered_json;

constexpr int kThetaSteps = 90;  // θ = 0, 1, …, 90 degrees
constexpr double kVisibleMin = 360, kVisibleMax = 830;
constexpr double kSpectralStep = 5;       // nm, R(λ) at 0°, 60°, 80°
constexpr int kUntabulatedSamples = 200;  // n, k of formula materials over their range
constexpr int kLutSize = 256;             // the viewer's reference: R_c at μ = i / 255
const double kSpectralAngles[] = {0, 60, 80};

// Plotted values keep 6 significant digits (the metrics keep all of theirs).
double plotted(double v) {
    if (!std::isfinite(v) || v == 0) return v;
    return std::strtod(significant_text(v, 6).c_str(), nullptr);
}

Json rgb_json(const RGB& v) { return Json::array({v.r, v.g, v.b}); }

double mu_of_degrees(double theta) { return theta == 90 ? 0.0 : std::cos(theta * std::numbers::pi / 180); }

// Scene-linear colours of the working space's values (the display transform takes scene_linear), as #rrggbb.
class Swatches {
public:
    Swatches(const ReportInputs& in)
        : in_(in),
          scene_linear_(ColorSpaceConverter::create(in.converter.config())),
          same_space_(scene_linear_.space() == in.converter.space()) {}

    std::vector<std::string> operator()(const std::vector<RGB>& working) const {
        std::vector<float> pixels;
        for (const RGB& c : working) {
            const RGB s = same_space_ ? c : scene_linear_(in_.converter.to_xyz(c));
            pixels.insert(pixels.end(), {float(s.r), float(s.g), float(s.b)});
        }
        const std::vector<unsigned char> display = in_.display.apply(pixels, static_cast<int>(working.size()), 1);
        std::vector<std::string> out;
        for (std::size_t i = 0; i < working.size(); ++i)
            out.push_back(hex(Display8{display[3 * i], display[3 * i + 1], display[3 * i + 2]}));
        return out;
    }

private:
    const ReportInputs& in_;
    ColorSpaceConverter scene_linear_;
    bool same_space_;
};

// The catalog entry and source a material was loaded from (its data file is that source's), if it is one; a named
// finish's metal too (its id is the finish's: found by its layers and file).
std::pair<const CatalogEntry*, const CatalogSource*> catalog_source(const Material& material, const Catalog& catalog) {
    const auto in = [&material](const CatalogEntry* entry) -> std::pair<const CatalogEntry*, const CatalogSource*> {
        if (entry->primary.file == material.provenance.file) return {entry, &entry->primary};
        for (const CatalogSource& s : entry->alternates)
            if (s.file == material.provenance.file) return {entry, &s};
        return {nullptr, nullptr};
    };
    if (const CatalogEntry* entry = catalog.find(material.id); entry && entry->id == material.id) return in(entry);
    if (material.layers && material.layers->finish)
        for (const CatalogEntry& entry : catalog.entries())
            if (const auto found = in(&entry); found.first) return found;
    return {nullptr, nullptr};
}

Json nk_json(const Material& material, const SpectralOptions& spectral) {
    const WavelengthRange range = material.index.range();
    std::vector<double> nm;
    if (const Spectrum* table = material.index.n.tabulated())
        for (double w : table->wavelengths())
            if (range.contains(w)) nm.push_back(w);
    if (nm.empty())
        for (int i = 0; i < kUntabulatedSamples; ++i)
            nm.push_back(range.min_nm + (range.max_nm - range.min_nm) * i / (kUntabulatedSamples - 1));
    Json n = Json::array(), k = Json::array(), wavelengths = Json::array();
    for (double w : nm) {
        const auto eta = material.index(w, spectral.interpolation, OutOfRange::clamp);
        wavelengths.push_back(w);
        n.push_back(plotted(eta.real()));
        k.push_back(plotted(eta.imag()));
    }
    return {{"nm", wavelengths},
            {"n", n},
            {"k", k},
            {"measured", {range.min_nm, range.max_nm}},
            {"visible", {kVisibleMin, kVisibleMax}}};
}

Json spectral_reflectance_json(const Material& material, const SpectralOptions& spectral) {
    Json nm = Json::array(), R = Json::array(), angles = Json::array();
    for (double w = kVisibleMin; w <= kVisibleMax; w += kSpectralStep) nm.push_back(w);
    for (double theta : kSpectralAngles) {
        angles.push_back(theta);
        Json row = Json::array();
        for (double w = kVisibleMin; w <= kVisibleMax; w += kSpectralStep) {
            const double mu = mu_of_degrees(theta);
            if (material.layers && !material.layers->empty()) {  // the stack's R(λ), as the reference curve's
                const int nm = static_cast<int>(w);
                row.push_back(plotted(
                    stack_reflectance_unpolarized(mu, stack_optics_on_grid(material, nm, nm, spectral).front())));
            } else {
                row.push_back(plotted(fresnel(mu, material.index(w, spectral.interpolation, spectral.out_of_range))));
            }
        }
        R.push_back(row);
    }
    return {{"nm", nm}, {"theta_deg", angles}, {"R", R}};
}

Json channels_json(const std::vector<RGB>& values) {
    Json out = Json::array();
    for (int c = 0; c < 3; ++c) {
        Json channel = Json::array();
        for (const RGB& v : values) channel.push_back(plotted(v[c]));
        out.push_back(channel);
    }
    return out;
}

// F0 and F82 of every source of a catalog material with several, their spread (max − min per channel) and each
// model's error at the same two angles: how much the data disagree next to how much the model errs.
Json sources_json(const MaterialFit& fit, const ReportInputs& in) {
    const CatalogEntry* entry = catalog_source(fit.material, in.catalog).first;
    if (!in.compare_sources || !entry || entry->alternates.empty()) return nullptr;
    std::vector<const CatalogSource*> all{&entry->primary};
    for (const CatalogSource& s : entry->alternates) all.push_back(&s);
    Json sources = Json::array();
    RGB lo0{1e9, 1e9, 1e9}, hi0{-1e9, -1e9, -1e9}, lo82 = lo0, hi82 = hi0;
    int defined = 0;
    for (const CatalogSource* s : all) {
        Json j = {{"source", s->source}, {"reference", s->reference}, {"primary", s == &entry->primary}};
        try {
            Material m = load_material(in.catalog, entry->id, s->source);
            m.layers = fit.material.layers;  // every source under the same layers
            const ReferenceCurve curve(m, in.colorimetry, in.converter, in.fit.spectral);
            const RGB f0 = curve(1.0), f82 = curve(kMuF82);
            for (int c = 0; c < 3; ++c) {
                lo0[c] = std::min(lo0[c], f0[c]), hi0[c] = std::max(hi0[c], f0[c]);
                lo82[c] = std::min(lo82[c], f82[c]), hi82[c] = std::max(hi82[c], f82[c]);
            }
            ++defined;
            j["F0"] = rgb_json(f0);
            j["F82"] = rgb_json(f82);
        } catch (const InputError& e) {
            j["undefined"] = e.what();
        }
        sources.push_back(j);
    }
    Json spread = nullptr;
    if (defined > 1)
        spread = {{"F0", rgb_json({hi0.r - lo0.r, hi0.g - lo0.g, hi0.b - lo0.b})},
                  {"F82", rgb_json({hi82.r - lo82.r, hi82.g - lo82.g, hi82.b - lo82.b})}};
    return {{"sources", sources}, {"spread", spread}};
}

Json provenance_json(const MaterialFit& fit, const ReportInputs& in) {
    const Provenance& p = fit.material.provenance;
    Json j = {{"file", record_path(p.file, in.fit.data_dir)},
              {"sha256", p.sha256},
              {"format", p.format},
              {"data_type", p.data_type},
              {"reference", p.references},
              {"doi", nullptr},
              {"licence", nullptr},
              {"database_path", nullptr},
              {"kind", nullptr}};
    if (const auto [entry, source] = catalog_source(fit.material, in.catalog); entry) {
        j["doi"] = source->doi.empty() ? Json(nullptr) : Json(source->doi);
        j["licence"] = source->licence;
        j["database_path"] = source->database_path;
        j["kind"] = entry->kind;
    }
    if (fit.material.layers && !fit.material.layers->empty()) j["stack"] = stack_record(fit.material, in.fit.data_dir);
    return j;
}

// What the consumers that do not evaluate the model itself render for `model` of `fit` (docs/export.md, "What each
// consumer renders"): per format, the curve in words, the model it is, worst-channel rel_rms, F0 error and ΔE2000
// max. A format whose stand-in the report did not fit is left out.
Json consumers_json(const MaterialFit& fit, const Model& model) {
    static constexpr std::array kFormats{ExportFormat::mtlx, ExportFormat::openpbr, ExportFormat::gltf,
                                         ExportFormat::blender};
    ExportRequest request;
    request.models = {&model};
    for (ExportFormat format : kFormats) {
        ExportRequest one = request;
        one.formats = {format};
        const auto needed = models_to_fit(one);
        const bool fitted = std::all_of(needed.begin(), needed.end(), [&](const Model* m) {
            return std::any_of(fit.models.begin(), fit.models.end(),
                               [&](const ModelResult& r) { return r.model == m; });
        });
        if (fitted) request.formats.push_back(format);
    }
    Json out = Json::object();
    for (const ConsumerCurve& c : consumer_curves(fit, model, request)) {
        Json j = {{"curve", c.curve}};
        if (c.rendered) {
            const Metrics& m = c.rendered->metrics;
            j["model"] = c.rendered->model->id();
            j["worst_rel_rms"] = worst_channel(m.rel_rms);
            double worst_f0 = 0;
            for (int k = 0; k < 3; ++k) worst_f0 = std::max(worst_f0, std::abs(m.err_f0[k]));
            j["worst_f0_err"] = worst_f0;
            j["de2000_max"] = m.de2000_max;
        } else {
            j["not_evaluated"] = c.not_evaluated;
        }
        out[to_string(c.format)] = std::move(j);
    }
    return out;
}

// What each renderer's thin film draws for a filmed material at its thickness against the stack: the record `metalfit
// table METAL --film FILM --thickness D --renderers --format json` writes (the same function, with the report's
// colour and error settings); under a coat, why it is not scored (docs/colour.md, "What renderers draw for a thin
// film").
Json renderer_film_json(const Material& material, const ReportInputs& in) {
    const LayerStack& layers = *material.layers;
    if (layers.coat) return {{"not_scored", std::string(kRendererFilmUnderCoat)}};
    return renderer_film_scores_json(
        renderer_film_scores({material, layers.film->material, {layers.film->thickness_nm}, in.fit.error},
                             in.colorimetry, in.converter, in.fit.spectral));
}

Json material_json(const MaterialFit& fit, const ReportInputs& in, const Swatches& swatches,
                   std::optional<int> render_row) {
    const Material& material = fit.material;
    const ReferenceCurve curve(material, in.colorimetry, in.converter, in.fit.spectral);
    const SampledReference& reference = *fit.reference;

    std::vector<double> theta, mu;
    for (int i = 0; i <= kThetaSteps; ++i) {
        theta.push_back(i * 90.0 / kThetaSteps);
        mu.push_back(mu_of_degrees(theta.back()));
    }
    std::vector<RGB> exact;
    for (double m : mu) exact.push_back(curve(m));
    const std::vector<Lab> exact_lab = reference.lab(exact);
    Json mu_json = Json::array();
    for (double m : mu) mu_json.push_back(plotted(m));

    std::vector<RGB> lut;
    for (int i = 0; i < kLutSize; ++i) lut.push_back(curve(double(i) / (kLutSize - 1)));

    const RGB f0 = curve(1.0), f82 = curve(kMuF82);
    const std::vector<std::string> swatch = swatches({f0, f82});
    Json models = Json::object();
    for (const ModelResult& r : fit.models) {
        const Model& model = *r.model;
        std::vector<RGB> values;
        for (double m : mu) values.push_back(model.evaluate(r.fit.value.params, m));
        const std::vector<Lab> labs = reference.lab(values);
        Json de = Json::array();
        for (std::size_t i = 0; i < mu.size(); ++i) de.push_back(plotted(ciede2000(exact_lab[i], labs[i])));
        const RGB m0 = model.evaluate(r.fit.value.params, 1.0), m82 = model.evaluate(r.fit.value.params, kMuF82);
        Json j = model_record(r);
        j["worst_rel_rms"] = worst_channel(r.fit.value.metrics.rel_rms);
        j["error_at"] = {
            {"F0", rgb_json({std::abs(m0.r - f0.r), std::abs(m0.g - f0.g), std::abs(m0.b - f0.b)})},
            {"F82", rgb_json({std::abs(m82.r - f82.r), std::abs(m82.g - f82.g), std::abs(m82.b - f82.b)})}};
        j["curve"] = channels_json(values);
        j["de2000"] = de;
        j["stripe"] = swatches(values);
        j["consumers"] = consumers_json(fit, model);
        models[std::string(model.id())] = std::move(j);
    }
    Json recommendation = nullptr;
    if (const auto it = in.cost.recommendations.find(material.id); it != in.cost.recommendations.end())
        recommendation = recommendation_record(it->second);
    Json choice = nullptr;
    if (const auto it = in.cost.choices.find(material.id); it != in.cost.choices.end())
        choice = {{"model", it->second.model ? Json(*it->second.model) : Json(nullptr)}, {"note", it->second.note}};

    Json out_of_gamut = Json::array();
    for (int c = 0; c < 3; ++c)
        if (fit.F0[c] > 1.0 || fit.F0[c] < 0.0) out_of_gamut.push_back(kChannelNames[c]);
    return {{"id", material.id},
            {"name", material.name},
            {"source", material.source},
            {"page", report_detail::material_page_file(material)},
            {"provenance", provenance_json(fit, in)},
            {"warnings", record_messages(material.warnings, material.provenance.file, in.fit.data_dir)},
            {"F0", rgb_json(f0)},
            {"F82", rgb_json(f82)},
            {"out_of_gamut_F0", out_of_gamut},
            {"swatch", {{"F0", swatch[0]}, {"F82", swatch[1]}}},
            {"nk", nk_json(material, in.fit.spectral)},
            {"spectral_reflectance", spectral_reflectance_json(material, in.fit.spectral)},
            {"curves",
             {{"theta_deg", theta}, {"mu", mu_json}, {"exact", channels_json(exact)}, {"stripe", swatches(exact)}}},
            {"lut", channels_json(lut)},
            {"models", models},
            {"data_sources", sources_json(fit, in)},
            {"budget_choice", choice},
            {"recommendation", recommendation},
            {"render_row", render_row ? Json(*render_row) : Json(nullptr)}};
}

// The models not dominated in (cost, median worst-channel rel_rms): no other model is at most as costly and at
// most as wrong, and better in one.
std::vector<bool> pareto_front(const std::vector<double>& cost, const std::vector<double>& error) {
    std::vector<bool> front(cost.size(), false);
    for (std::size_t i = 0; i < cost.size(); ++i) {
        if (std::isnan(cost[i]) || std::isnan(error[i])) continue;
        bool dominated = false;
        for (std::size_t j = 0; j < cost.size() && !dominated; ++j)
            dominated = j != i && !std::isnan(cost[j]) && !std::isnan(error[j]) && cost[j] <= cost[i] &&
                        error[j] <= error[i] && (cost[j] < cost[i] || error[j] < error[i]);
        front[i] = !dominated;
    }
    return front;
}

}  // namespace

namespace report_detail {

class ReportSwatches : public Swatches {
public:
    using Swatches::Swatches;
};

std::shared_ptr<const ReportSwatches> report_swatches(const ReportInputs& in) {
    return std::make_shared<const ReportSwatches>(in);
}

Json material_record(const MaterialFit& fit, const ReportInputs& in, const ReportSwatches& swatches) {
    std::optional<int> row;
    if (in.renders.rows)
        if (const auto r = in.renders.rows->row_of(fit.material.id)) row = static_cast<int>(*r);
    Json entry = material_json(fit, in, swatches, row);
    if (fit.material.layers && fit.material.layers->film) entry["renderer_film"] = renderer_film_json(fit.material, in);
    return entry;
}

Json report_record_without_materials(const CatalogSummary& summary, const ReportInputs& in) {
    const FitRecordContext& c = in.fit;

    Json models = Json::array();
    std::vector<double> cost, median;
    for (const ModelSummary& m : summary.models) {
        const auto value = in.cost.costs ? in.cost.costs->of(m.model->id()) : std::nullopt;
        cost.push_back(value.value_or(std::nan("")));
        median.push_back(m.fit.median);
    }
    const std::vector<bool> front = pareto_front(cost, median);
    for (std::size_t i = 0; i < summary.models.size(); ++i) {
        const ModelSummary& m = summary.models[i];
        Json names = Json::array();
        for (const Parameter& p : m.model->parameters()) names.push_back(p.name);
        models.push_back(
            {{"id", m.model->id()},
             {"title", m.model->title()},
             {"parameters", names},
             {"cost", std::isnan(cost[i]) ? Json(nullptr) : Json(cost[i])},
             {"pareto_front", in.cost.costs ? Json(bool(front[i])) : Json(nullptr)},
             {"fit_worst_rel_rms", {{"per_material", m.fit_worst}, {"median", m.fit.median}, {"worst", m.fit.worst}}},
             {"closed_worst_rel_rms", m.closed_worst},
             // The viewer's shader calls the model's GLSL, the text the GLSL export writes.
             {"glsl", {{"function", m.model->glsl_function()}, {"source", m.model->glsl_source()}}}});
    }

    Json materials = Json::array();  // report_record fills them in, or ReportStream writes them one by one

    Json renders;
    if (in.renders.rows) {
        const SphereRowImages& s = *in.renders.rows;
        renders = {
            {"by", "glpreview --sheet --sheet-models --sheet-rows (data/scenes/sheet.json): distance impostor in a "
                   "procedural room, mirror spheres; one image per material, labels drawn by glpreview"},
            {"cell", {s.cell_width, s.cell_height}},
            {"columns", {"reference (exact Fresnel)", "model", "model / reference − 1 (false colour, log scale)"}},
            {"labels", "none in the images: the page captions each cell (material, model, roughness, image RMSE, "
                       "the error view's scale)"},
            {"models", s.models},
            {"rows", Json::array()}};
        for (std::size_t r = 0; r < s.materials.size(); ++r) {
            Json models = Json::array();
            for (std::size_t m = 0; m < s.models.size(); ++m) {
                Json cells = Json::array();
                for (const SphereSheetCells& c : s.cells[r][m])
                    cells.push_back({{"roughness", c.roughness},
                                     {"reference", c.reference},
                                     {"model", c.model},
                                     {"difference", c.difference},
                                     {"image_rmse", c.image_rmse},
                                     {"error_view", {c.error_smallest, c.error_largest}}});
                models.push_back({{"model", s.models[m]}, {"cells", cells}});
            }
            renders["rows"].push_back(
                {{"material", s.materials[r]}, {"image", render_image_file(s.materials[r])}, {"models", models}});
        }
    } else {
        renders = {{"skipped", in.renders.skipped}};
    }

    const ErrorSettings& e = c.error;
    Json constraints = nullptr;  // the F0 tolerance the fits were held to (the recommendation's), if any
    if (c.constraints.f0_tolerance) constraints = {{"f0_tolerance", *c.constraints.f0_tolerance}};
    Json costs = nullptr;
    if (in.cost.costs) costs = {{"source", in.cost.costs->source}, {"unit", in.cost.costs->unit}};
    return {{"schema", kReportSchema},
            {"provenance",
             {{"metalfit_version", METALFIT_VERSION},
              {"color_space", c.space},
              {"cmf", to_string(c.observer)},
              {"illuminant", to_string(c.illuminant)},
              {"ocio_config",
               {{"file", record_path(c.config.path, c.data_dir)},
                {"origin", c.config.origin},
                {"sha256", sha256_file(c.config.path)}}},
              {"display", in.display.description()},
              {"interpolation", to_string(c.spectral.interpolation)},
              {"out_of_range", to_string(c.spectral.out_of_range)},
              {"white_balance", "R_c = RGB_c(F) / RGB_c(perfect reflector)"},
              {"nodes", e.nodes},
              {"quadrature", "Gauss-Legendre on [0, 1]"},
              {"metric", to_string(e.metric)},
              {"weight", to_string(e.weight)},
              {"fitted_parameters", "Ceres fit per channel (never worse than the best closed form on the metric)"},
              {"constraints", constraints}}},
            {"costs", costs},
            {"budget", in.cost.budget ? Json(*in.cost.budget) : Json(nullptr)},
            {"models", models},
            {"materials", materials},
            {"renders", renders},
            {"charts", report_detail::chart_specs(in.cost.costs.has_value())}};
}

}  // namespace report_detail

Json report_record(const std::vector<MaterialFit>& fits, const ReportInputs& in) {
    Json record = report_detail::report_record_without_materials(summarize_catalog(fits), in);
    const auto swatches = report_detail::report_swatches(in);
    Json materials = Json::array();
    for (const MaterialFit& fit : fits) materials.push_back(report_detail::material_record(fit, in, *swatches));
    record["materials"] = std::move(materials);
    return record;
}

}  // namespace metalfit
