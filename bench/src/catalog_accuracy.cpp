#include "metalfit_bench/catalog_accuracy.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "libfit/base/errors.hpp"
#include "libfit/base/interleaved_timer.hpp"
#include "libfit/fit/catalog_summary.hpp"
#include "libfit/fit/fit.hpp"
#include "metalfit_bench/reference_lut.hpp"

namespace metalfit::bench {

// The catalog summary's definitions (libfit/fit/catalog_summary.hpp), so that the bench and `metalfit fit --summary`
// print the same median and worst.
void summarise(AccuracySummary& s) {
    const Spread spread = spread_of_defined(s.worst_rel_rms);
    s.median = spread.median;
    s.worst = spread.worst;
}

const AccuracySummary* CatalogAccuracy::find(std::string_view id) const {
    for (const auto* list : {&models, &luts})
        for (const AccuracySummary& s : *list)
            if (s.id == id) return &s;
    return nullptr;
}

CatalogAccuracy catalog_accuracy(const Environment& env, std::span<const int> lut_entries,
                                 const std::function<void(std::size_t, std::size_t)>& progress) {
    CatalogAccuracy result;
    const std::span<const Model* const> models = all_models();
    for (const Model* m : models) result.models.push_back({std::string(m->id()), {}, 0, 0, 0});
    for (int n : lut_entries) result.luts.push_back({"lut-" + std::to_string(n), {}, 0, 0, 0});
    std::vector<std::vector<double>> fit_seconds(models.size());
    const std::size_t count = env.catalog.entries().size();
    for (std::size_t e = 0; e < count; ++e) {
        const CatalogEntry& entry = env.catalog.entries()[e];
        const Material material = load_material(env.catalog, entry.id);
        const ReferenceCurve curve(material, env.colorimetry, env.converter, env.spectral);
        const SampledReference reference(curve, env.error);
        if (reference.rel_undefined())
            throw InputError(InputLocation(material.provenance.file),
                             "relative error undefined for " + material.id + ": " + *reference.rel_undefined());
        const ClosedFormInput input = closed_form_input(curve, material, env.spectral);
        result.materials.push_back(material.id);
        for (std::size_t m = 0; m < models.size(); ++m) {
            const auto start = std::chrono::steady_clock::now();
            const ModelResult r = fit_model(*models[m], reference, input);
            fit_seconds[m].push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
            result.models[m].worst_rel_rms.push_back(worst_channel(r.fit.value.metrics.rel_rms));
        }
        for (std::size_t l = 0; l < lut_entries.size(); ++l)
            result.luts[l].worst_rel_rms.push_back(
                worst_channel(ReferenceLut(curve, lut_entries[l]).rel_rms(reference)));
        if (progress) progress(e + 1, count);
    }
    for (std::size_t m = 0; m < models.size(); ++m) {
        summarise(result.models[m]);
        result.models[m].fit_seconds_median = median(fit_seconds[m]);
    }
    for (AccuracySummary& s : result.luts) summarise(s);
    return result;
}

}  // namespace metalfit::bench
