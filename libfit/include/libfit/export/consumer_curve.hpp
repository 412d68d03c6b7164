// What each export format's consumer actually evaluates for an exported model, and the error figures of that curve
// (docs/export.md, "What each consumer renders"): the shader formats and the JSON record evaluate the model itself;
// MaterialX the model's node (or the stand-in where the model has none); OpenPBR its F82-tint metal (the model's
// F82-tint form, or the stand-in); a glTF viewer Schlick from baseColorFactor, whatever the extras say. The format
// registry names each format's curve once; the export record, the glTF extras and the report read it.
#pragma once

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

#include "libfit/export/export.hpp"

namespace metalfit {

struct ConsumerCurve {
    ExportFormat format = ExportFormat::json;
    std::string curve;  // what the consumer evaluates, in words: "Schlick from baseColorFactor (…)"
    // The parameters the consumer evaluates, under the model it evaluates them with (the exported model, the
    // stand-in, or schlick for glTF), with the error figures of that curve; empty where metalfit does not evaluate the
    // consumer's curve (`not_evaluated` says why: a layered material under the format's own coat and film).
    std::optional<WrittenParameters> rendered;
    std::string not_evaluated;
};

// What each format of `request` renders for `model` of `fit`: one entry per requested format, in the request's
// order. `fit` holds the models of models_to_fit(request) (the stand-in where a format needs it).
std::vector<ConsumerCurve> consumer_curves(const MaterialFit& fit, const Model& model, const ExportRequest& request);

// {"curve", "model", "params", "metrics", "err_f0", "metrics_at_mu"} of the rendered curve, or {"curve",
// "not_evaluated"} (schemas/fit.schema.json, `consumers`).
nlohmann::ordered_json consumer_curve_record(const ConsumerCurve& curve);

}  // namespace metalfit
