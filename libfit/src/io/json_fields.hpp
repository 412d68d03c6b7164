// The data files' JSON fields as the catalog and the finishes read them: one place that says what a missing or
// mistyped field is (InputError naming the file and the field's path).
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

#include "libfit/base/errors.hpp"

namespace metalfit::io_detail {

// j[key] as a string; absent or null: "" unless `required` (InputError "missing"); not a string: InputError.
inline std::string string_field(const nlohmann::json& j, const char* key, const std::filesystem::path& file,
                                const std::string& where, bool required = true) {
    const auto it = j.find(key);
    if (it == j.end() || it->is_null()) {
        if (required) throw InputError({file, 0, where + "." + key}, "missing");
        return {};
    }
    if (!it->is_string()) throw InputError({file, 0, where + "." + key}, "expected a string");
    return it->get<std::string>();
}

}  // namespace metalfit::io_detail
