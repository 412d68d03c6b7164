// UTF-8 validation (libfit/base/utf8.hpp), the one check of every importer and both command lines: RFC 3629's
// well-formed sequences only, and the place and reason of the first byte that is not one.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "libfit/base/errors.hpp"
#include "libfit/base/utf8.hpp"

namespace metalfit {
namespace test_utf8 {

TEST(Utf8, WellFormedTextPasses) {
    for (const char* text :
         {"", "plain ASCII", "\xc2\xb5m \xce\xb5\xe2\x82\x81 \xc3\x85 \xe2\x84\xab", "\xef\xbb\xbfwith BOM",
          "\xf0\x9f\x98\x80 U+1F600", "\xf4\x8f\xbf\xbf U+10FFFF", "\xed\x9f\xbf U+D7FF", "\xee\x80\x80 U+E000"})
        EXPECT_TRUE(is_utf8(text)) << text;
}

TEST(Utf8, EveryIllFormedClassIsFoundWithItsPlaceAndReason) {
    struct Case {
        std::string text;
        std::size_t offset;
        int line;
        std::string reason;
    };
    const Case cases[] = {
        {"ab\xff", 2, 1, "byte 0xFF is not UTF-8"},
        {"a\nb\n\x80", 4, 3, "byte 0x80 is not UTF-8"},  // stray continuation byte
        {"caf\xe9 x", 3, 1, "byte 0xE9 is not UTF-8"},   // Latin-1
        {"x\xe2\x82", 1, 1, "byte 0xE2 is not UTF-8"},   // truncated at the end
        {"\xc0\xaf", 0, 1, "overlong encoding C0 AF of U+002F"},
        {"\xe0\x80\xaf", 0, 1, "overlong encoding E0 80 AF of U+002F"},
        {"\xf0\x80\x80\xaf", 0, 1, "overlong encoding F0 80 80 AF of U+002F"},
        {"\xed\xa0\x80", 0, 1, "UTF-16 surrogate U+D800 (ED A0 80) in UTF-8"},
        {"\xed\xbf\xbf", 0, 1, "UTF-16 surrogate U+DFFF (ED BF BF) in UTF-8"},
        {"\xf4\x90\x80\x80", 0, 1, "code point U+110000 (F4 90 80 80) above U+10FFFF"},
        {"\xf7\xbf\xbf\xbf", 0, 1, "code point U+1FFFFF (F7 BF BF BF) above U+10FFFF"},
        {"\xf8\x88\x80\x80\x80", 0, 1, "byte 0xF8 is not UTF-8"},  // 5-byte forms are gone
    };
    for (const Case& c : cases) {
        const auto problem = find_invalid_utf8(c.text);
        ASSERT_TRUE(problem.has_value()) << c.reason;
        EXPECT_EQ(problem->offset, c.offset) << c.reason;
        EXPECT_EQ(problem->line, c.line) << c.reason;
        EXPECT_EQ(problem->reason, c.reason);
    }
}

TEST(Utf8, SanitisedMessagesUseTheSameRule) {
    // What utf8.hpp refuses, sanitised_message escapes byte by byte (the same decoder): no raw ill-formed byte is printed.
    EXPECT_EQ(sanitised_message("a\xed\xa0\x80z"), "a\\xED\\xA0\\x80z");
    EXPECT_EQ(sanitised_message("\xf4\x90\x80\x80"), "\\xF4\\x90\\x80\\x80");
    EXPECT_EQ(sanitised_message("\xc3\x85"), "\xc3\x85");
}

TEST(Utf8, CommandLineValuesAreUsageErrorsNamingTheArgument) {
    const char* argv[] = {"metalfit", "show", "--name", "caf\xe9", "gold"};
    try {
        require_utf8_arguments(5, argv);
        FAIL() << "no error";
    } catch (const UsageError& e) {
        EXPECT_EQ(sanitised_message(e.what()),
                  "argument 3 (after --name) is not UTF-8 (byte 0xE9 is not UTF-8): caf\\xE9");
    }
    const char* fine[] = {"metalfit", "show", "--name", "caf\xc3\xa9"};
    EXPECT_NO_THROW(require_utf8_arguments(4, fine));
}

// The escapes messages and literals write: byte_escape is printf's "\\x%02X" (messages) or "\\x%02x" (Python
// literals) for every byte, code_point_name printf's "U+%04X" for every code point and beyond (a decoded sequence
// above U+10FFFF is named too).
TEST(Utf8, EscapesAreWhatPrintfWrites) {
    char text[32];
    for (unsigned byte = 0; byte < 256; ++byte) {
        std::snprintf(text, sizeof text, "\\x%02X", byte);
        ASSERT_EQ(byte_escape(static_cast<unsigned char>(byte)), text);
        std::snprintf(text, sizeof text, "\\x%02x", byte);
        ASSERT_EQ(byte_escape(static_cast<unsigned char>(byte), HexLetters::lower), text);
    }
    for (char32_t code = 0; code <= 0x1FFFFF; code += code < 0x1000 ? 1 : 97) {
        std::snprintf(text, sizeof text, "U+%04X", static_cast<unsigned>(code));
        ASSERT_EQ(code_point_name(code), text);
    }
    EXPECT_EQ(byte_escape(0xE9), "\\xE9");
    EXPECT_EQ(code_point_name(0x200B), "U+200B");
    EXPECT_EQ(code_point_name(0x1F600), "U+1F600");
    // What sanitised_message writes with them: a stray byte, a control character, an invisible code point.
    EXPECT_EQ(sanitised_message("a\xff\x01\xe2\x80\x8b"), "a\\xFF\\x01<U+200B>");
}

}  // namespace test_utf8
}  // namespace metalfit
