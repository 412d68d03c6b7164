#include "libfit/base/record_path.hpp"

#include <optional>
#include <system_error>

namespace metalfit {

namespace {

namespace fs = std::filesystem;

// `file` relative to `folder` when it lies below it (both absolute and normal), else nothing.
std::optional<fs::path> below(const fs::path& file, const fs::path& folder) {
    if (folder.empty()) return std::nullopt;
    const fs::path relative = file.lexically_relative(folder);
    if (relative.empty() || relative == "." || *relative.begin() == "..") return std::nullopt;
    return relative;
}

fs::path absolute_normal(const fs::path& p) {
    std::error_code error;
    const fs::path absolute = fs::absolute(p, error);
    return (error ? p : absolute).lexically_normal();
}

// Below `folder` as written, else below it once symbolic links are resolved (a data folder reached through a link).
std::optional<fs::path> below_either(const fs::path& file, const fs::path& folder) {
    if (folder.empty()) return std::nullopt;
    if (auto relative = below(absolute_normal(file), absolute_normal(folder))) return relative;
    std::error_code error_file, error_folder;
    const fs::path real_file = fs::weakly_canonical(file, error_file);
    const fs::path real_folder = fs::weakly_canonical(folder, error_folder);
    if (error_file || error_folder) return std::nullopt;
    return below(real_file, real_folder);
}

bool starts_with_marker(const std::string& s) {
    return s.starts_with(kDataPathMarker) || s.starts_with(kOutsidePathMarker);
}

}  // namespace

std::string record_path(const fs::path& file, const fs::path& data_dir) {
    if (file.empty()) return {};  // no file (a constant layer's index)
    if (const auto in_data = below_either(file, data_dir))
        return std::string(kDataPathMarker) + in_data->generic_string();
    std::error_code error;
    const fs::path working = fs::current_path(error);
    if (!error)
        if (const auto in_working = below_either(file, working)) {
            std::string relative = in_working->generic_string();
            return starts_with_marker(relative) ? "./" + relative : relative;
        }
    return std::string(kOutsidePathMarker) + file.filename().string();
}

std::vector<std::string> record_messages(const std::vector<std::string>& messages, const fs::path& file,
                                         const fs::path& data_dir) {
    if (file.empty()) return messages;
    const std::string written = record_path(file, data_dir);
    std::vector<std::string> spellings;
    for (const fs::path& p : {absolute_normal(file), file})
        if (p.is_absolute() && p.string() != written) spellings.push_back(p.string());
    std::vector<std::string> out;
    for (std::string message : messages) {
        for (const std::string& spelling : spellings)
            for (std::size_t at = message.find(spelling); at != std::string::npos;
                 at = message.find(spelling, at + written.size()))
                message.replace(at, spelling.size(), written);
        out.push_back(std::move(message));
    }
    return out;
}

}  // namespace metalfit
