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

// One loader per material: every catalog entry (`all`), or each material or file named (loaded here, so that an
// unknown name or a bad file fails before any work). The loaders refer to `catalog`, which must outlive them.
// `labels` name and cite a user file (UsageError with `all`, several materials or a catalog material).
std::vector<std::function<Material()>> material_loaders(const Catalog& catalog, bool all,
                                                        const std::vector<std::string>& materials, const std::string& source,
                                                        const UserFileLabels& labels = {});

// The colour pipeline a batch fits under: the OCIO config (each thread builds its own processor from it), the
// colorimetry, and the converter of the calling thread.
struct BatchColour {
    const OcioConfigChoice& config;
    const Colorimetry& colorimetry;
    const ColorSpaceConverter& converter;
};

// Called after each material with (finished, total), from the worker threads one at a time.
using BatchProgress = std::function<void(std::size_t finished, std::size_t total)>;

// Runs fit_material for every material on `jobs` threads; results in input order (the output does not depend on
// the threads). The first error, in input order, is rethrown.
std::vector<MaterialFit> fit_materials(const std::vector<std::function<Material()>>& loaders, const BatchColour& colour,
                                       const MaterialFitRequest& request, int jobs, const BatchProgress& progress = {});

}  // namespace metalfit
