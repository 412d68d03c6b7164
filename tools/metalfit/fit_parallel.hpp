// Fitting many materials on several threads, for the subcommands that fit (fit, export).
#pragma once

#include <functional>
#include <vector>

#include "colour_options.hpp"
#include "libfit/io/catalog.hpp"
#include "libfit/fit/fit.hpp"

namespace metalfit::cli {

// One loader per material: every catalog entry (`all`), or the one material or file named (loaded here, so that an
// unknown name or a bad file fails before any work). The loaders refer to `catalog`, which must outlive them.
std::vector<std::function<Material()>> material_loaders(const Catalog& catalog, bool all, const std::string& material,
                                                        const std::string& source);

// Runs fit_material for every material on `jobs` threads; results in input order (the output does not depend on
// the threads). A progress line goes to stderr when it is a terminal. The first error, in input order, is rethrown.
std::vector<MaterialFit> fit_in_parallel(const std::vector<std::function<Material()>>& loaders, const ColourSetup& setup,
                                         const MaterialFitRequest& request, int jobs);

}  // namespace metalfit::cli
