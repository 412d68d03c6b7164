#include "libfit/export/roughness.hpp"

#include <charconv>
#include <system_error>

namespace metalfit {

std::optional<double> roughness_from_text(std::string_view text) {
    double value = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc{} || end != text.data() + text.size() || !(value >= 0.0 && value <= 1.0))
        return std::nullopt;
    return value;
}

}  // namespace metalfit
