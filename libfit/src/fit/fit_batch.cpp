#include "libfit/fit/fit_batch.hpp"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

#include "libfit/base/errors.hpp"
#include "libfit/io/finishes.hpp"

namespace metalfit {

std::vector<std::function<Material()>> material_loaders(const Catalog& catalog, bool all,
                                                        const std::vector<std::string>& materials,
                                                        const std::string& source, const UserFileLabels& labels) {
    std::vector<std::function<Material()>> loaders;
    if (all && !labels.empty()) throw UsageError("--name and --reference label one file of your own, not --all");
    if (all) {
        for (const CatalogEntry& entry : catalog.entries())
            loaders.push_back([&catalog, id = entry.id] { return load_material(catalog, id, ""); });
    } else {
        if (!labels.empty() && materials.size() > 1)
            throw UsageError("--name and --reference label one file of your own, not several materials");
        for (const std::string& material : materials) {
            if (std::optional<Material> finish = load_finish_named(catalog, material, source)) {
                if (!labels.empty()) throw UsageError("--name and --reference label a file of your own, not a finish");
                loaders.push_back([loaded = std::move(*finish)] { return loaded; });
                continue;
            }
            const Material loaded = load_material(catalog, material, source, labels);  // errors before any work
            loaders.push_back([loaded] { return loaded; });
        }
    }
    return loaders;
}

void fit_materials_in_order(const std::vector<std::function<Material()>>& loaders, const BatchColour& colour,
                            const MaterialFitRequest& request, int jobs, const BatchSink& sink,
                            const BatchProgress& progress, std::size_t window, BatchStatistics* statistics) {
    fit_materials_in_order(
        loaders, colour,
        [&](const Material& material, const ColorSpaceConverter& converter) {
            return fit_material(material, colour.colorimetry, converter, request);
        },
        jobs, sink, progress, window, statistics);
}

void fit_materials_in_order(const std::vector<std::function<Material()>>& loaders, const BatchColour& colour,
                            const BatchFit& fit, int jobs, const BatchSink& sink, const BatchProgress& progress,
                            std::size_t window, BatchStatistics* statistics) {
    const std::size_t count = loaders.size();
    const int threads = std::max(1, std::min<int>(jobs, static_cast<int>(count)));
    if (window == 0) window = kBatchWindowPerThread * static_cast<std::size_t>(threads);
    // The reorder window: material i lives in slot i % window from its start until the sink has it. A material is
    // started only while i < next_to_hand + window, so its slot is free.
    struct Slot {
        std::optional<MaterialFit> fit;
        std::exception_ptr error;
        bool ready = false;
    };
    std::vector<Slot> slots(window);
    std::mutex mutex;                  // guards everything below and the slots
    std::condition_variable advanced;  // next_to_hand moved on, or the batch stopped
    std::size_t next_to_start = 0, next_to_hand = 0, finished = 0;
    bool handing = false;  // a thread is calling the sink; the others leave their results in the window
    bool stopped = false;
    std::exception_ptr failure;
    std::mutex progress_mutex;

    const auto worker = [&](const ColorSpaceConverter& converter) {
        std::unique_lock lock(mutex);
        for (;;) {
            const auto may_start = [&] {
                return stopped || next_to_start >= count || next_to_start < next_to_hand + window;
            };
            if (!may_start()) {
                const auto waiting_since = std::chrono::steady_clock::now();
                advanced.wait(lock, may_start);
                if (statistics) {
                    ++statistics->window_waits;
                    statistics->window_wait_s +=
                        std::chrono::duration<double>(std::chrono::steady_clock::now() - waiting_since).count();
                }
            }
            if (stopped || next_to_start >= count) return;
            const std::size_t i = next_to_start++;
            lock.unlock();
            Slot result;
            try {
                const Material material = loaders[i]();
                result.fit = fit(material, converter);
            } catch (...) {
                result.error = std::current_exception();
            }
            if (progress) {
                std::lock_guard progress_lock(progress_mutex);
                progress(++finished, count);
            }
            lock.lock();
            result.ready = true;
            slots[i % window] = std::move(result);
            if (handing) continue;  // the thread handing results on takes this one when its turn comes
            // This thread hands on every result that is next in order, the sink called without the lock.
            handing = true;
            while (!stopped && slots[next_to_hand % window].ready) {
                Slot next = std::move(slots[next_to_hand % window]);
                slots[next_to_hand % window] = Slot{};
                if (next.error) {
                    failure = next.error;
                    stopped = true;
                    break;
                }
                lock.unlock();
                std::exception_ptr sink_error;
                try {
                    sink(next_to_hand, std::move(*next.fit));
                } catch (...) {
                    sink_error = std::current_exception();
                }
                next.fit.reset();
                lock.lock();
                if (sink_error) {
                    failure = sink_error;
                    stopped = true;
                    break;
                }
                ++next_to_hand;
                advanced.notify_all();
            }
            handing = false;
            if (stopped) advanced.notify_all();
        }
    };
    // One converter per thread: the calling thread uses the caller's; the others' are made here, before any thread
    // starts, so that a failure is an ordinary error and not an exception inside a thread. They share the process's
    // Config and OCIO's cached processors (libfit/color/ocio_config_loads.hpp; OCIO's CPU processors are thread-safe).
    std::vector<ColorSpaceConverter> converters;
    for (int t = 1; t < threads; ++t)
        converters.push_back(
            ColorSpaceConverter::create(colour.config, colour.converter.space(), colour.converter.xyz_space()));
    {
        std::vector<std::jthread> pool;
        for (const ColorSpaceConverter& converter : converters) pool.emplace_back(worker, std::cref(converter));
        worker(colour.converter);
    }
    if (failure) std::rethrow_exception(failure);
}

std::vector<MaterialFit> fit_materials(const std::vector<std::function<Material()>>& loaders, const BatchColour& colour,
                                       const MaterialFitRequest& request, int jobs, const BatchProgress& progress) {
    std::vector<MaterialFit> fits;
    fits.reserve(loaders.size());
    fit_materials_in_order(
        loaders, colour, request, jobs, [&](std::size_t, MaterialFit&& fit) { fits.push_back(std::move(fit)); },
        progress);
    return fits;
}

}  // namespace metalfit
