// The names of an enum's values: one table per enum, used both to print a value and to parse one, so that what a
// record writes is what an option reads back. Each table is a constant beside its enum (`kBudgetMetricNames`, ...).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace metalfit {

template <typename Enum>
struct EnumName {
    Enum value;
    std::string_view name;
};

// How the message about an unknown name lists the known ones: "(known: a, b, c)", "(a, b or c)" or
// "(expected a, b or c)" — the wording each option has always used.
enum class KnownNamesWording { known, alternatives, expected };

namespace detail {
// "a, b, c" / "a, b or c" / "expected a, b or c" of `names`.
std::string known_names_text(const std::string_view* names, std::size_t count, KnownNamesWording wording);
// UsageError "unknown <what> '<text>' (<known>)".
[[noreturn]] void throw_unknown_name(std::string_view what, std::string_view text, const std::string& known);
}  // namespace detail

template <typename Enum, std::size_t N>
struct EnumNames {
    std::string_view what;  // "budget metric": what the message about an unknown name calls a value
    KnownNamesWording wording;
    std::array<EnumName<Enum>, N> names;  // in the order messages and help list them

    // The name of `value` ("?" for a value outside the table, which a complete table never meets).
    constexpr std::string_view name(Enum value) const {
        for (const EnumName<Enum>& n : names)
            if (n.value == value) return n.name;
        return "?";
    }
    // The value named `text` (exactly, case-sensitive); nothing when no value has that name.
    constexpr std::optional<Enum> find(std::string_view text) const {
        for (const EnumName<Enum>& n : names)
            if (n.name == text) return n.value;
        return std::nullopt;
    }
    // The value named `text`; else a UsageError "unknown <what> '<text>' (<the known names>)".
    Enum parse(std::string_view text) const {
        if (const std::optional<Enum> value = find(text)) return *value;
        detail::throw_unknown_name(what, text, known());
    }
    // The known names, worded as in the message about an unknown one.
    std::string known() const {
        std::array<std::string_view, N> list;
        for (std::size_t i = 0; i < N; ++i) list[i] = names[i].name;
        return detail::known_names_text(list.data(), N, wording);
    }
};

template <typename Enum, std::size_t N>
EnumNames(std::string_view, KnownNamesWording, std::array<EnumName<Enum>, N>) -> EnumNames<Enum, N>;

}  // namespace metalfit
