// Writing the report folder as one unit: libfit's StagedFolder (staged beside the target, exchanged into place).
#include <system_error>

#include "libfit/base/errors.hpp"
#include "libfit/base/staged_folder.hpp"
#include "libfit/report/report.hpp"

namespace metalfit {

namespace fs = std::filesystem;

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
    replace_folder_as_unit(check_report_folder(target), files);
}

}  // namespace metalfit
