// What each format's consumer evaluates (consumer_curve.hpp): the registry's curve of each requested format for one
// model of one fit, and its record.
#include "libfit/export/consumer_curve.hpp"

#include <algorithm>
#include <stdexcept>

#include "export/export_formats.hpp"
#include "export/format_registry.hpp"
#include "libfit/fit/fit_record.hpp"

namespace metalfit {

namespace detail {

ConsumerCurve own_model_curve(const MaterialExport&, const ModelExport& model, GamutPolicy) {
    return {ExportFormat::json, "the model's own function (" + std::string(model.written.model->glsl_function()) + ")",
            model.written, ""};
}

}  // namespace detail

std::vector<ConsumerCurve> detail::consumer_curves(const MaterialExport& material, const ModelExport& model,
                                                   const ExportRequest& request) {
    const bool layered = material.fit->material.layers && !material.fit->material.layers->empty();
    std::vector<ConsumerCurve> curves;
    for (ExportFormat format : request.formats) {
        const ExportFormatEntry& entry = format_entry(format);
        ConsumerCurve c;
        if (layered && entry.layers_over_bare_metal) {
            c.curve = "the bare metal's constants under " + to_string(format) + "'s own coat and thin film";
            c.not_evaluated =
                "the consumer layers its own coat and film over the bare metal; metalfit does not evaluate its "
                "layering";
        } else {
            c = entry.consumer_curve(material, model, request.gamut);
        }
        c.format = format;
        curves.push_back(std::move(c));
    }
    return curves;
}

std::vector<ConsumerCurve> consumer_curves(const MaterialFit& fit, const Model& model, const ExportRequest& request) {
    ExportRequest one = request;
    one.models = {&model};
    const detail::MaterialExport material = detail::material_export(fit, one);
    return detail::consumer_curves(material, material.models.front(), request);
}

nlohmann::ordered_json consumer_curve_record(const ConsumerCurve& curve) {
    nlohmann::ordered_json j = {{"curve", curve.curve}};
    if (curve.rendered) {
        j["model"] = curve.rendered->model->id();
        j.update(evaluated_record(*curve.rendered->model, {curve.rendered->params, curve.rendered->metrics}));
    } else {
        j["not_evaluated"] = curve.not_evaluated;
    }
    return j;
}

}  // namespace metalfit
