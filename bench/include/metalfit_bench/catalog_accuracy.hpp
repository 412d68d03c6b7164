// Accuracy over the built-in catalog, computed with the definitions of libfit/fit/catalog_summary (`metalfit fit --all --summary`):
// per material the worst-channel rel_rms of each model's fit, then the median and the worst over the materials.
// Also the same figures for the reference LUTs (their rel_rms against the reference at the same nodes), and the
// time each model's fit_model() takes per material (closed forms, every Ceres start, metrics).
#pragma once

#include <functional>
#include <span>
#include <string>
#include <vector>

#include "metalfit_bench/environment.hpp"

namespace metalfit::bench {

struct AccuracySummary {
    std::string id;                     // model id or "lut-64", ...
    std::vector<double> worst_rel_rms;  // per material (catalog order); NaN where undefined
    double median = 0;                  // over materials with a defined value
    double worst = 0;
    double fit_seconds_median = 0;  // models only: fit_model() per material, median
};

struct CatalogAccuracy {
    std::vector<std::string> materials;   // ids, catalog order
    std::vector<AccuracySummary> models;  // all_models() order
    std::vector<AccuracySummary> luts;    // one per requested size
    const AccuracySummary* find(std::string_view id) const;
};

// Fits every catalog material with every model, one material after the other (so that fit times are not shared
// cores' times). `progress(i, count)` is called after each material, if given.
CatalogAccuracy catalog_accuracy(const Environment& env, std::span<const int> lut_entries,
                                 const std::function<void(std::size_t, std::size_t)>& progress = {});

// The median and worst of a summary's values (NaN ignored): libfit's spread_of_defined.
void summarise(AccuracySummary& summary);

}  // namespace metalfit::bench
