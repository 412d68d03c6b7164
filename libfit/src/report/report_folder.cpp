// Writing the report folder as one unit: a temporary folder beside the target, filled, then renamed into place.
#include <fstream>
#include <random>
#include <system_error>

#include "libfit/base/errors.hpp"
#include "libfit/report/report.hpp"

namespace metalfit {
namespace {

namespace fs = std::filesystem;

fs::path sibling(const fs::path& dir, const std::string& tag) {
    std::random_device random;
    return dir.parent_path() / (dir.filename().string() + "." + tag + "-" + std::to_string(random() % 1000000000u));
}

}  // namespace

fs::path check_report_folder(const fs::path& target) {
    // "out/report/" names the folder "report": drop the trailing separator.
    const fs::path dir = target.has_filename() ? target : target.parent_path();
    if (dir.empty()) throw InputError(InputLocation(target), "no report folder named");
    std::error_code ec;
    if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
        throw InputError(InputLocation(dir), "exists and is not a folder");
    const fs::path parent = dir.parent_path().empty() ? fs::path(".") : dir.parent_path();
    if (!fs::is_directory(parent, ec)) throw InputError(InputLocation(parent), "no such folder (create it first)");
    return dir;
}

void write_report_folder(const fs::path& target, const std::vector<ReportFile>& files) {
    const fs::path dir = check_report_folder(target);
    std::error_code ec;

    const fs::path temporary = sibling(dir, "tmp");
    const auto fail = [&](const fs::path& where, const std::string& what) {
        std::error_code ignored;
        fs::remove_all(temporary, ignored);
        throw InputError(InputLocation(where), what);
    };
    if (!fs::create_directory(temporary, ec)) fail(dir, "cannot create a folder beside it: " + ec.message());
    for (const ReportFile& file : files) {
        const fs::path path = temporary / file.path;
        fs::create_directories(path.parent_path(), ec);
        std::ofstream out(path, std::ios::binary);
        out.write(file.contents.data(), static_cast<std::streamsize>(file.contents.size()));
        out.close();
        if (!out) fail(dir / file.path, "cannot be written");
    }
    // Replace: the old folder moves aside, the new one takes its name, the old one goes.
    const bool replacing = fs::exists(dir, ec);
    const fs::path old = sibling(dir, "old");
    if (replacing) {
        fs::rename(dir, old, ec);
        if (ec) fail(dir, "cannot be replaced: " + ec.message());
    }
    fs::rename(temporary, dir, ec);
    if (ec) {
        std::error_code ignored;
        if (replacing) fs::rename(old, dir, ignored);
        fail(dir, "cannot be written: " + ec.message());
    }
    if (replacing) fs::remove_all(old, ec);
}

}  // namespace metalfit
