// Fitting many materials on several threads (what `metalfit fit --all` and `metalfit export --all` do).
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "libfit/color/color_space.hpp"
#include "libfit/color/colorimetry.hpp"
#include "libfit/fit/fit.hpp"
#include "libfit/io/catalog.hpp"

namespace metalfit {

// One loader per material: every catalog entry (`all`), or each material, named finish (data/finishes.json:
// io/finishes.hpp) or file named (loaded here, so that an unknown name or a bad file fails before any work). The loaders refer to `catalog`, which must outlive them.
// `labels` name and cite a user file (UsageError with `all`, several materials or a catalog material).
std::vector<std::function<Material()>> material_loaders(const Catalog& catalog, bool all,
                                                        const std::vector<std::string>& materials,
                                                        const std::string& source, const UserFileLabels& labels = {});

// The colour pipeline a batch fits under: the OCIO config (each thread builds its own processor from it), the
// colorimetry, and the converter of the calling thread.
struct BatchColour {
    const OcioConfigChoice& config;
    const Colorimetry& colorimetry;
    const ColorSpaceConverter& converter;
};

// Called after each material with (finished, total), from the worker threads one at a time.
using BatchProgress = std::function<void(std::size_t finished, std::size_t total)>;

// Receives each material's fit, in input order (index: its position in the loaders), one call at a time, from
// whichever worker thread is free; it keeps what it needs and lets the fit go. An exception it throws stops the batch
// and is rethrown by fit_materials_in_order.
using BatchSink = std::function<void(std::size_t index, MaterialFit&& fit)>;

// How many materials may be loaded or fitted ahead of the one the sink is waiting for, per worker thread: the
// reorder window that holds the results of fast materials while a slow one ahead of them finishes.
inline constexpr std::size_t kBatchWindowPerThread = 8;

// Runs fit_material for every material on `jobs` threads and hands each fit to `sink` in input order (the order
// does not depend on the threads). Memory stays flat: at most `window` materials (0: kBatchWindowPerThread per
// thread) are loaded and not yet handed to the sink at any time; a thread that would run further ahead waits. The
// first error in input order stops the batch (the sink has received every material before it) and is rethrown.
// How often and how long (wall clock, summed over the threads) threads waited at the reorder window for a slow
// material ahead of them: what `metalfit bench --scaling` reports, never part of an output.
struct BatchStatistics {
    std::size_t window_waits = 0;
    double window_wait_s = 0;
};

void fit_materials_in_order(const std::vector<std::function<Material()>>& loaders, const BatchColour& colour,
                            const MaterialFitRequest& request, int jobs, const BatchSink& sink,
                            const BatchProgress& progress = {}, std::size_t window = 0,
                            BatchStatistics* statistics = nullptr);

// The work done for each material on a worker thread, with that thread's OCIO processor: fit_material by default.
using BatchFit = std::function<MaterialFit(const Material& material, const ColorSpaceConverter& converter)>;

// The same with another fit per material (export's, which fits a layered material's bare metal too).
void fit_materials_in_order(const std::vector<std::function<Material()>>& loaders, const BatchColour& colour,
                            const BatchFit& fit, int jobs, const BatchSink& sink, const BatchProgress& progress = {},
                            std::size_t window = 0, BatchStatistics* statistics = nullptr);

// fit_materials_in_order into a vector: every material's fit, in input order, for callers that need them all.
std::vector<MaterialFit> fit_materials(const std::vector<std::function<Material()>>& loaders, const BatchColour& colour,
                                       const MaterialFitRequest& request, int jobs, const BatchProgress& progress = {});

}  // namespace metalfit
