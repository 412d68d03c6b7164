// Small text helpers shared by the libraries' messages and explanations.
#pragma once

#include <string>
#include <vector>

namespace metalfit {

// "a, b, c" (or with another separator); empty for no items.
inline std::string join(const std::vector<std::string>& items, const char* separator = ", ") {
    std::string text;
    for (const auto& item : items) text += (text.empty() ? "" : separator) + item;
    return text;
}

}  // namespace metalfit
