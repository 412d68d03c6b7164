// JSON export: the fit record (schema metalfit.fit/1, docs/fit-record.md) of the exported materials and models, each
// model with an "export" member holding the parameters as written and their error figures.
#include "export/export_formats.hpp"

namespace metalfit::detail {

namespace {

using Json = nlohmann::ordered_json;

Json written_json(const WrittenParameters& w, GamutPolicy gamut) {
    Json j = {{"from", w.origin}, {"gamut", to_string(gamut)}, {"out_of_gamut", w.gamut}};
    j.update(evaluated_record(*w.model, {w.params, w.metrics}));
    return j;
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
