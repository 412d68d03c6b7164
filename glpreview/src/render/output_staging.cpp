#include "glpreview/render/output_staging.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <system_error>

#include "libfit/base/errors.hpp"
#include "libfit/base/staged_folder.hpp"

namespace metalfit::glpreview {

OutputStaging::OutputStaging(std::filesystem::path output_dir) : output_dir_(std::move(output_dir)) {
    std::string pattern = (std::filesystem::temp_directory_path() / "glpreview-output.XXXXXX").string();
    if (!::mkdtemp(pattern.data()))
        throw InputError(InputLocation(output_dir_), std::string("cannot make a private folder for the outputs: ") + std::strerror(errno));
    folder_ = pattern;
}

OutputStaging::~OutputStaging() {
    std::error_code ignored;
    std::filesystem::remove_all(folder_, ignored);
}

std::filesystem::path OutputStaging::file(const std::string& name) {
    if (std::find(names_.begin(), names_.end(), name) == names_.end()) names_.push_back(name);
    return folder_ / name;
}

void OutputStaging::commit() {
    std::vector<OutputFile> files;
    for (const std::string& name : names_) {
        std::ifstream in(folder_ / name, std::ios::binary);
        if (!in) throw InputError(InputLocation(output_dir_ / name), "the staged output is missing");
        files.push_back({name, std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>())});
    }
    update_folder_as_unit(output_dir_, files);
}

}  // namespace metalfit::glpreview
