// JSON export: the fit record (schema metalfit.fit/1, docs/fit-record.md) of the exported materials and models, each
// model with an "export" member holding the parameters as written and their error figures.
#include "export/export_formats.hpp"

namespace metalfit::detail {

namespace {

using Json = nlohmann::ordered_json;

Json written_json(const WrittenParameters& w, GamutPolicy gamut, double roughness) {
    Json j = {{"from", w.origin}, {"gamut", to_string(gamut)}, {"out_of_gamut", w.gamut}, {"roughness", roughness}};
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
                written_json(e.written, context.request.gamut, context.request.roughness);
    // Only a prefix other than the default is recorded, so that a default export is what it was before --id-prefix.
    if (context.request.id_prefix != kDefaultIdPrefix) record["id_prefix"] = context.request.id_prefix;
    std::vector<ColourOutOfRange> outside;
    for (const MaterialExport& m : materials)
        for (const ModelExport& e : m.models)
            for (ColourOutOfRange& o : colours_out_of_range(m, e.written, e.written.model->id()))
                outside.push_back(std::move(o));
    return {{"metalfit_export.json", record.dump(2) + "\n", std::move(outside)}};
}

std::string merge_json_record(const std::string& existing, const std::string& mine) {
    Json old_record, new_record;
    try {
        old_record = Json::parse(existing);
    } catch (const Json::exception&) {
        throw std::invalid_argument("not a metalfit export record (invalid JSON)");
    }
    new_record = Json::parse(mine);
    if (!old_record.is_object() || old_record.value("schema", "") != new_record["schema"] ||
        !old_record.contains("materials") || !old_record["materials"].is_object())
        throw std::invalid_argument("not a " + new_record["schema"].get<std::string>() + " record");
    // One folder, one prefix: its record and index describe the identifiers of one prefix.
    const std::string old_prefix = old_record.value("id_prefix", std::string(kDefaultIdPrefix));
    const std::string new_prefix = new_record.value("id_prefix", std::string(kDefaultIdPrefix));
    if (old_prefix != new_prefix)
        throw std::invalid_argument("its identifiers have --id-prefix \"" + old_prefix + "\", this export's \"" +
                                    new_prefix + "\": one folder holds one prefix");
    for (const auto& [key, value] : new_record.items())
        if (key != "materials" && old_record[key] != value) {
            std::string differs;
            if (value.is_object())
                for (const auto& [k, v] : value.items())
                    if (!old_record[key].contains(k) || old_record[key][k] != v) {
                        differs = key + "." + k + " " + old_record[key].value(k, Json()).dump() + " there, " +
                                  v.dump() + " now";
                        break;
                    }
            throw std::invalid_argument("it was written with other settings (" + (differs.empty() ? key : differs) +
                                        "): one record cannot hold both");
        }
    Json& materials = old_record["materials"];
    for (const auto& [id, material] : new_record["materials"].items()) {
        if (!materials.contains(id)) {
            materials[id] = material;
            continue;
        }
        Json& old_material = materials[id];
        for (const auto& [key, value] : material.items())
            if (key != "models" && old_material[key] != value)
                throw std::invalid_argument("material " + id + " there was exported from other data (" + key +
                                            " differs): one record cannot hold both");
        for (const auto& [model, record] : material["models"].items()) old_material["models"][model] = record;
    }
    return old_record.dump(2) + "\n";
}

}  // namespace metalfit::detail
