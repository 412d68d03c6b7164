// UTF-8 validation: the one check every importer and both command lines use. metalfit's records, exports and
// messages are UTF-8 (JSON requires it), so text that reaches them (names, units, column names, file names,
// command-line values, OCIO names) is checked where it enters, and refused there with a message naming where. Bytes
// and code points that a message or a literal cannot show as they are are written as escapes (`byte_escape`,
// `code_point_name`), the same everywhere.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "libfit/base/number_text.hpp"

namespace metalfit {

// The length of the well-formed UTF-8 sequence at text[i] (1 to 4), 0 when there is none: a stray continuation
// byte, a bad lead byte (0xC0, 0xC1, 0xF5–0xFF), a truncated sequence, an overlong encoding, a UTF-16 surrogate
// (U+D800–U+DFFF) or a code point above U+10FFFF (RFC 3629). `code` receives the code point when there is one.
std::size_t utf8_sequence(std::string_view text, std::size_t i, char32_t& code);

// A byte as C's and Python's escape "\xNN", two hex digits: upper case in messages ("\xE9"), lower case where
// Python literals are written ("\xe9").
std::string byte_escape(unsigned char byte, HexLetters letters = HexLetters::upper);
// A code point as Unicode names it: "U+" and at least four upper-case hex digits ("U+00E9", "U+1F600").
std::string code_point_name(char32_t code);

// Where text is not UTF-8: the byte offset, the 1-based line (counting '\n' before it) and why, in words
// ("byte 0xFF is not UTF-8", "overlong encoding C0 AF of U+002F", "UTF-16 surrogate U+D800 in UTF-8",
// "code point U+110000 (F4 90 80 80) above U+10FFFF"; a stray, bad or unfinished sequence names its first byte).
struct Utf8Problem {
    std::size_t offset = 0;
    int line = 1;
    std::string reason;
};

// The first place where `text` is not UTF-8; nullopt when all of it is.
std::optional<Utf8Problem> find_invalid_utf8(std::string_view text);

// Whether `text` is UTF-8 throughout.
inline bool is_utf8(std::string_view text) { return !find_invalid_utf8(text).has_value(); }

// Throws UsageError "<what> is not UTF-8 (<reason>): <the value, sanitised>" when `value` is not UTF-8; for the values
// of a command line (`what`: "--name", "argument 3").
void require_utf8_argument(std::string_view value, std::string_view what);

// Every argument of a command line (argv[1] on) must be UTF-8: values become names, labels and paths in records and
// messages. Throws UsageError naming the first that is not ("argument 3 (after --name)").
void require_utf8_arguments(int argc, const char* const* argv);

}  // namespace metalfit
