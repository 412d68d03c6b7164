#include "libfit/fit/catalog_summary.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "libfit/base/number_text.hpp"
#include "libfit/base/sample_statistics.hpp"
#include "libfit/base/version.hpp"

namespace metalfit {
namespace {

std::string percent(double x) { return std::isnan(x) ? "—" : fixed_text(100 * x, 2); }

}  // namespace

Spread spread_of_defined(const std::vector<double>& values) {
    std::vector<double> defined;
    for (double v : values)
        if (!std::isnan(v)) defined.push_back(v);
    if (defined.empty()) return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
    return {median(defined), *std::max_element(defined.begin(), defined.end())};
}

void CatalogSummaryBuilder::add(const MaterialFit& f) {
    if (summary_.materials.empty())
        for (const ModelResult& r : f.models) summary_.models.push_back({r.model, {}, {}, {}});
    summary_.materials.push_back(f.material.id);
    if (f.models.size() != summary_.models.size())
        throw std::logic_error("summarize_catalog: " + f.material.id + " was fitted with other models");
    for (std::size_t m = 0; m < f.models.size(); ++m) {
        const ModelResult& r = f.models[m];
        if (r.model != summary_.models[m].model)
            throw std::logic_error("summarize_catalog: " + f.material.id + " was fitted with other models");
        summary_.models[m].fit_worst.push_back(worst_channel(r.fit.value.metrics.rel_rms));
        summary_.models[m].closed_worst.push_back(
            r.best_closed ? worst_channel(r.closed_forms[*r.best_closed].value->metrics.rel_rms)
                          : std::numeric_limits<double>::quiet_NaN());
    }
}

CatalogSummary CatalogSummaryBuilder::summary() const {
    CatalogSummary summary = summary_;
    for (ModelSummary& m : summary.models) m.fit = spread_of_defined(m.fit_worst);
    return summary;
}

CatalogSummary summarize_catalog(const std::vector<MaterialFit>& fits) {
    CatalogSummaryBuilder builder;
    for (const MaterialFit& f : fits) builder.add(f);
    return builder.summary();
}

std::string catalog_summary_markdown(const CatalogSummary& summary, const FitRecordContext& context) {
    std::ostringstream s;
    const ErrorSettings& e = context.error;
    s << "Worst-channel `rel_rms` in %, fit / best closed form; " << context.space << ", "
      << to_string(context.illuminant) << ", " << to_string(context.observer) << ", adaptation "
      << describe_adaptation(context.adaptation, context.adapted, context.illuminant) << ", convention "
      << to_string(context.convention) << ", " << to_string(context.spectral.interpolation) << " interpolation, "
      << to_string(e.metric) << " metric, " << to_string(e.weight) << " weight, " << e.nodes << " nodes (metalfit "
      << METALFIT_VERSION << ").\n\n";
    s << "| material |";
    for (const ModelSummary& m : summary.models) s << " " << m.model->id() << " |";
    s << "\n|---|";
    for (std::size_t m = 0; m < summary.models.size(); ++m) s << "---|";
    s << "\n";
    for (std::size_t i = 0; i < summary.materials.size(); ++i) {
        s << "| " << summary.materials[i] << " |";
        for (const ModelSummary& m : summary.models)
            s << " " << percent(m.fit_worst[i]) << " / " << percent(m.closed_worst[i]) << " |";
        s << "\n";
    }
    s << "| **median fit** |";
    for (const ModelSummary& m : summary.models) s << " " << percent(m.fit.median) << " |";
    s << "\n| **worst fit** |";
    for (const ModelSummary& m : summary.models) s << " " << percent(m.fit.worst) << " |";
    s << "\n";
    return s.str();
}

}  // namespace metalfit
