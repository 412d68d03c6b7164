#include "libfit/base/enum_names.hpp"

#include "libfit/base/errors.hpp"

namespace metalfit::detail {

std::string known_names_text(const std::string_view* names, std::size_t count, KnownNamesWording wording) {
    std::string text = wording == KnownNamesWording::known      ? "known: "
                       : wording == KnownNamesWording::expected ? "expected "
                                                                : "";
    for (std::size_t i = 0; i < count; ++i) {
        if (i > 0) text += wording != KnownNamesWording::known && i + 1 == count ? " or " : ", ";
        text += names[i];
    }
    return text;
}

void throw_unknown_name(std::string_view what, std::string_view text, const std::string& known) {
    throw UsageError("unknown " + std::string(what) + " '" + std::string(text) + "' (" + known + ")");
}

}  // namespace metalfit::detail
