// JSON export: the fit record (schema metalfit.fit/1, docs/fit-record.md) of the exported materials and models, each
// model with an "export" member holding the parameters as written and their error figures.
#include "export_formats.hpp"

namespace metalfit::detail {

namespace {

using Json = nlohmann::ordered_json;

Json per_channel(const PerChannel& v) { return Json::array({v[0], v[1], v[2]}); }

Json written_json(const WrittenParameters& w, GamutPolicy gamut) {
    Json params = Json::object();
    const auto parameters = w.model->parameters();
    for (std::size_t i = 0; i < parameters.size(); ++i)
        params[std::string(parameters[i].name)] = Json::array({w.params[0][i], w.params[1][i], w.params[2][i]});
    const Metrics& m = w.metrics;
    return {{"from", w.origin},
            {"gamut", to_string(gamut)},
            {"out_of_gamut", w.gamut},
            {"params", params},
            {"metrics",
             {{"rel_rms", per_channel(m.rel_rms)},
              {"abs_rms", per_channel(m.abs_rms)},
              {"max_rel", per_channel(m.max_rel)},
              {"max_abs", per_channel(m.max_abs)},
              {"de2000_mean", m.de2000_mean},
              {"de2000_max", m.de2000_max},
              {"albedo_err", per_channel(m.albedo_err)}}},
            {"metrics_at_mu",
             {{"max_rel", per_channel(m.max_rel_mu)}, {"max_abs", per_channel(m.max_abs_mu)}, {"de2000_max", m.de2000_max_mu}}}};
}

}  // namespace

std::vector<ExportFile> export_json(const std::vector<MaterialExport>& materials, const ExportContext& context) {
    std::vector<MaterialFit> fits;
    for (const MaterialExport& m : materials) {
        MaterialFit f = *m.fit;
        f.models.clear();  // only the models asked for (not a stand-in fitted for MaterialX / OpenPBR)
        for (const ModelExport& e : m.models)
            for (const ModelResult& r : m.fit->models)
                if (r.model == e.written.model) f.models.push_back(r);
        fits.push_back(std::move(f));
    }
    Json record = fit_record(fits, context.record);
    for (const MaterialExport& m : materials)
        for (const ModelExport& e : m.models)
            record["materials"][m.fit->material.id]["models"][std::string(e.written.model->id())]["export"] =
                written_json(e.written, context.request.gamut);
    return {{"metalfit_export.json", record.dump(2) + "\n"}};
}

}  // namespace metalfit::detail
