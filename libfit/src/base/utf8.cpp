#include "libfit/base/utf8.hpp"

#include "libfit/base/errors.hpp"

namespace metalfit {
namespace {

// The sequence a lead byte at text[i] announces, decoded as far as its continuation bytes go: `length` 0 for a byte
// that starts none (a stray continuation byte, 0xF8–0xFF), `complete` false when the text ends or a byte that is no
// continuation byte comes before `length` bytes; `code` the code point of a complete sequence.
struct Decoded {
    std::size_t length = 0;
    bool complete = false;
    char32_t code = 0;
};

Decoded decode(std::string_view text, std::size_t i) {
    const auto c = static_cast<unsigned char>(text[i]);
    Decoded d;
    d.length = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
    if (d.length == 0) return d;
    d.code = d.length == 1 ? c : d.length == 2 ? (c & 0x1F) : d.length == 3 ? (c & 0x0F) : (c & 0x07);
    for (std::size_t j = 1; j < d.length; ++j) {
        if (i + j >= text.size() || (static_cast<unsigned char>(text[i + j]) >> 6) != 0x2) return d;
        d.code = (d.code << 6) | (static_cast<unsigned char>(text[i + j]) & 0x3F);
    }
    d.complete = true;
    return d;
}

bool overlong(const Decoded& d) {
    return (d.length == 2 && d.code < 0x80) || (d.length == 3 && d.code < 0x800) || (d.length == 4 && d.code < 0x10000);
}

bool surrogate(char32_t code) { return code >= 0xD800 && code <= 0xDFFF; }

// "C0 AF": each byte as two upper-case hex digits.
std::string hex_bytes(std::string_view bytes) {
    std::string out;
    for (const char b : bytes)
        out += (out.empty() ? "" : " ") + hex_text(static_cast<unsigned char>(b), 2, HexLetters::upper);
    return out;
}

// Why text[i] starts no UTF-8 sequence (utf8_sequence returned 0 there).
std::string why_not(std::string_view text, std::size_t i) {
    const Decoded d = decode(text, i);
    if (!d.complete)  // no lead byte, or a truncated sequence
        return "byte 0x" + hex_text(static_cast<unsigned char>(text[i]), 2, HexLetters::upper) + " is not UTF-8";
    const std::string bytes = hex_bytes(text.substr(i, d.length));
    if (overlong(d)) return "overlong encoding " + bytes + " of " + code_point_name(d.code);
    if (surrogate(d.code)) return "UTF-16 surrogate " + code_point_name(d.code) + " (" + bytes + ") in UTF-8";
    return "code point " + code_point_name(d.code) + " (" + bytes + ") above U+10FFFF";
}

}  // namespace

std::string byte_escape(unsigned char byte, HexLetters letters) { return "\\x" + hex_text(byte, 2, letters); }

std::string code_point_name(char32_t code) { return "U+" + hex_text(code, 4, HexLetters::upper); }

std::size_t utf8_sequence(std::string_view text, std::size_t i, char32_t& code) {
    const Decoded d = decode(text, i);
    if (!d.complete || overlong(d) || d.code > 0x10FFFF || surrogate(d.code)) return 0;
    code = d.code;
    return d.length;
}

std::optional<Utf8Problem> find_invalid_utf8(std::string_view text) {
    int line = 1;
    for (std::size_t i = 0; i < text.size();) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c < 0x80) {  // the common case, one byte at a time
            line += c == '\n';
            ++i;
            continue;
        }
        char32_t code = 0;
        const std::size_t length = utf8_sequence(text, i, code);
        if (length == 0) return Utf8Problem{i, line, why_not(text, i)};
        i += length;
    }
    return std::nullopt;
}

void require_utf8_argument(std::string_view value, std::string_view what) {
    if (const auto problem = find_invalid_utf8(value))
        throw UsageError(std::string(what) + " is not UTF-8 (" + problem->reason + "): " + std::string(value));
}

void require_utf8_arguments(int argc, const char* const* argv) {
    for (int i = 1; i < argc; ++i) {
        const std::string_view previous = i > 1 ? std::string_view(argv[i - 1]) : std::string_view();
        std::string what = "argument " + std::to_string(i);
        if (previous.starts_with("-") && is_utf8(previous)) what += " (after " + std::string(previous) + ")";
        require_utf8_argument(argv[i], what);
    }
}

}  // namespace metalfit
