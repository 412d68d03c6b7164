#include "libfit/fit/fit_batch.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

#include "libfit/base/errors.hpp"

namespace metalfit {

std::vector<std::function<Material()>> material_loaders(const Catalog& catalog, bool all,
                                                        const std::vector<std::string>& materials, const std::string& source,
                                                        const UserFileLabels& labels) {
    std::vector<std::function<Material()>> loaders;
    if (all && !labels.empty()) throw UsageError("--name and --reference label one file of your own, not --all");
    if (all) {
        for (const CatalogEntry& entry : catalog.entries())
            loaders.push_back([&catalog, id = entry.id] { return load_material(catalog, id, ""); });
    } else {
        if (!labels.empty() && materials.size() > 1)
            throw UsageError("--name and --reference label one file of your own, not several materials");
        for (const std::string& material : materials) {
            const Material loaded = load_material(catalog, material, source, labels);  // errors before any work
            loaders.push_back([loaded] { return loaded; });
        }
    }
    return loaders;
}

std::vector<MaterialFit> fit_materials(const std::vector<std::function<Material()>>& loaders, const BatchColour& colour,
                                       const MaterialFitRequest& request, int jobs, const BatchProgress& progress) {
    const std::size_t count = loaders.size();
    std::vector<std::optional<MaterialFit>> results(count);
    std::vector<std::exception_ptr> errors(count);
    std::atomic<std::size_t> next{0}, done{0};
    std::mutex progress_mutex;
    const auto worker = [&](const ColorSpaceConverter& converter) {
        for (std::size_t i = next++; i < count; i = next++) {
            try {
                const Material material = loaders[i]();
                results[i] = fit_material(material, colour.colorimetry, converter, request);
            } catch (...) {
                errors[i] = std::current_exception();
            }
            const std::size_t finished = ++done;
            if (progress) {
                std::lock_guard lock(progress_mutex);
                progress(finished, count);
            }
        }
    };
    const int threads = std::max(1, std::min<int>(jobs, static_cast<int>(count)));
    // One OCIO processor per thread: the calling thread uses the caller's; the others' are made here, before any thread
    // starts, so that a failure is an ordinary error and not an exception inside a thread.
    std::vector<ColorSpaceConverter> converters;
    for (int t = 1; t < threads; ++t) converters.push_back(ColorSpaceConverter::create(colour.config, colour.converter.space(), colour.converter.xyz_space()));
    {
        std::vector<std::jthread> pool;
        for (const ColorSpaceConverter& converter : converters) pool.emplace_back(worker, std::cref(converter));
        worker(colour.converter);
    }
    std::vector<MaterialFit> fits;
    for (std::size_t i = 0; i < count; ++i) {
        if (errors[i]) std::rethrow_exception(errors[i]);
        fits.push_back(std::move(*results[i]));
    }
    return fits;
}

}  // namespace metalfit
