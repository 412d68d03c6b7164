// An export written as one unit: every file below the folder, staged beside it and switched in with one rename
// (StagedFolder), the files an earlier export there shares merged with it (index_merge.cpp).
#include "export/format_registry.hpp"
#include "libfit/base/staged_folder.hpp"
#include "libfit/export/export.hpp"

namespace metalfit {

void write_export(const std::filesystem::path& dir, const std::vector<ExportFile>& files) {
    std::vector<OutputFile> outputs;
    outputs.reserve(files.size());
    for (const ExportFile& f : files) outputs.push_back({f.path, f.contents});
    update_folder_as_unit(dir, outputs,
                          [&](const std::filesystem::path& relative, const std::string& existing,
                              const std::string& mine) { return detail::merge_index(dir, relative, existing, mine); });
}

}  // namespace metalfit
