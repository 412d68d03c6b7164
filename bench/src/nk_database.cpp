#include "metalfit_bench/nk_database.hpp"

#include <time.h>

#include <algorithm>
#include <exception>
#include <system_error>

#include "libfit/base/errors.hpp"
#include "libfit/io/csv.hpp"
#include "libfit/spectral/spectrum.hpp"

namespace metalfit::bench {
namespace {

double thread_cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

bool is_nk_file(const std::filesystem::path& file) {
    const std::string extension = file.extension().string();
    if (extension != ".yml" && extension != ".yaml") return false;
    for (const auto& part : file.parent_path())
        if (part == "n2") return false;  // the database's nonlinear indices (n2), not n and k
    return true;
}

}  // namespace

bool is_metal(const Material& material) {
    std::vector<double> k;
    for (int nm = static_cast<int>(kVisibleRange.min_nm); nm <= static_cast<int>(kVisibleRange.max_nm); nm += 10)
        k.push_back(material.index.k(nm, Interpolation::linear, OutOfRange::error));
    std::nth_element(k.begin(), k.begin() + static_cast<std::ptrdiff_t>(k.size() / 2), k.end());
    return k[k.size() / 2] >= kMetalMedianK;  // 48 values: the upper median
}

NkDatabaseScan scan_nk_database(const std::filesystem::path& folder) {
    namespace fs = std::filesystem;
    std::error_code error;
    if (!fs::is_directory(folder, error))
        throw InputError({folder}, "not a folder (a refractiveindex.info database folder, such as data/nk)");
    const double cpu0 = thread_cpu_seconds();
    NkDatabaseScan scan;
    scan.folder = folder;
    std::vector<fs::path> files;
    for (fs::recursive_directory_iterator it(folder, fs::directory_options::skip_permission_denied, error), end;
         !error && it != end; it.increment(error))
        if (it->is_regular_file(error)) files.push_back(it->path());
    if (error) throw InputError({folder}, "cannot be read: " + error.message());
    std::sort(files.begin(), files.end());
    scan.files = files.size();
    for (const fs::path& file : files) {
        if (!is_nk_file(file)) {
            ++scan.not_nk;
            continue;
        }
        try {
            const Material m = load_nk_file(file);
            if (!m.index.range().covers(kVisibleRange))
                ++scan.outside_visible;
            else if (!is_metal(m))
                ++scan.not_metal;
            else
                scan.metal_files.push_back(file);
        } catch (const std::exception&) {
            ++scan.unreadable;
        }
    }
    scan.cpu_s = thread_cpu_seconds() - cpu0;
    return scan;
}

}  // namespace metalfit::bench
