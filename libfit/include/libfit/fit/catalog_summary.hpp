// The catalog summary: per model, the worst-channel rel_rms of every material's fit and best closed form, and the
// median and worst of the fits over the materials. Computed once, here, for `metalfit fit --summary` (Markdown) and
// `metalfit bench` (its accuracy columns).
#pragma once

#include <string>
#include <vector>

#include "libfit/fit/fit.hpp"
#include "libfit/fit/fit_record.hpp"

namespace metalfit {

// The median and the worst (largest) of the defined values; NaN values (undefined) are left out; NaN when none is
// defined.
struct Spread {
    double median = 0;
    double worst = 0;
};
Spread spread_of_defined(const std::vector<double>& values);

struct ModelSummary {
    const Model* model = nullptr;
    std::vector<double> fit_worst;     // per material: worst-channel rel_rms of the fit (NaN if undefined)
    std::vector<double> closed_worst;  // per material: of the best defined closed form (NaN if none is defined)
    Spread fit;                        // over the materials
};

struct CatalogSummary {
    std::vector<std::string> materials;  // ids, in the order of the fits
    std::vector<ModelSummary> models;    // in the order of the first material's models
};

// The summary built one material at a time (as fit_materials_in_order hands them on), keeping only the ids and
// the worst-channel values. Every fit must hold the same models in the same order (as fit_materials gives them).
class CatalogSummaryBuilder {
public:
    void add(const MaterialFit& fit);
    CatalogSummary summary() const;  // with the spreads over the materials added so far

private:
    CatalogSummary summary_;
};

// Every fit must hold the same models in the same order (as fit_materials gives them).
CatalogSummary summarize_catalog(const std::vector<MaterialFit>& fits);

// A Markdown table: one row per material ("fit / closed" in %, "—" where undefined), then the median and worst fit;
// a first line states the colour pipeline and error settings of `context`.
std::string catalog_summary_markdown(const CatalogSummary& summary, const FitRecordContext& context);

}  // namespace metalfit
