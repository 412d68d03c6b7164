// Names are data (libfit/base/names.hpp): the rule every writer applies to text from inputs.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "libfit/base/names.hpp"

namespace test_names {

using metalfit::c_string_literal;
using metalfit::comment_text;
using metalfit::path_component;
using metalfit::python_string_expression;

// An independent reader of the literals c_string_literal writes: the C escapes it may use, nothing else.
std::string read_c_string_literal(const std::string& literal) {
    EXPECT_GE(literal.size(), 2u);
    EXPECT_EQ(literal.front(), '"');
    EXPECT_EQ(literal.back(), '"');
    std::string value;
    for (std::size_t i = 1; i + 1 < literal.size(); ++i) {
        const char c = literal[i];
        EXPECT_NE(c, '"') << "an unescaped quote ends the literal early: " << literal;
        EXPECT_TRUE(c >= 0x20 && c <= 0x7E) << "a byte outside printable ASCII in " << literal;
        if (c != '\\') {
            value += c;
            continue;
        }
        const char next = literal.at(++i);
        if (next == '"' || next == '\\') {
            value += next;
        } else {
            EXPECT_TRUE(next >= '0' && next <= '7') << literal;
            const int code = (next - '0') * 64 + (literal.at(i + 1) - '0') * 8 + (literal.at(i + 2) - '0');
            value += static_cast<char>(code);
            i += 2;
        }
    }
    return value;
}

std::string random_bytes(std::mt19937& random, std::size_t length) {
    std::uniform_int_distribution<int> byte(0, 255);
    std::string s;
    for (std::size_t i = 0; i < length; ++i) s += static_cast<char>(byte(random));
    return s;
}

TEST(Names, CommentTextIsOneVisibleLineThatNoLineCommentCanContinue) {
    const std::string hostile = "a\nb\r\n#define X 1\t*/ \x01 \u202Eevil\u2028 end\\";
    const std::string text = comment_text(hostile);
    EXPECT_EQ(text.find('\n'), std::string::npos);
    EXPECT_EQ(text.find('\r'), std::string::npos);
    EXPECT_EQ(text.find('\x01'), std::string::npos);
    EXPECT_EQ(text.find("\u202E"), std::string::npos);  // direction override shown, not applied
    EXPECT_NE(text.find("<U+202E>"), std::string::npos);
    EXPECT_NE(text.find("<U+2028>"), std::string::npos);
    EXPECT_NE(text.back(), '\\');                            // "// ...\" would swallow the next line of a shader
    EXPECT_NE(text.find("#define X 1"), std::string::npos);  // kept as text, on the comment's line
    // Plain text and UTF-8 letters pass unchanged; a backslash inside the line stays.
    EXPECT_EQ(comment_text("Gold (Au), Johnson & Christy 1972: n, k; Å \\ ok"),
              "Gold (Au), Johnson & Christy 1972: n, k; Å \\ ok");
    EXPECT_EQ(comment_text("ends in \\"), "ends in \\x5C");
}

TEST(Names, CStringLiteralsReadBackAsTheBytesGiven) {
    for (const std::string& s : {std::string(""), std::string("Au"), std::string("a\"b\\c"),
                                 std::string("line\n#error x"), std::string("\u202E right-to-left"),
                                 std::string("octal \1"
                                             "23 then digits 456"),
                                 std::string("nul\0inside", 10)}) {
        const std::string literal = c_string_literal(s);
        EXPECT_EQ(read_c_string_literal(literal), s) << literal;
    }
    std::mt19937 random(7);
    for (int i = 0; i < 500; ++i) {
        const std::string s = random_bytes(random, static_cast<std::size_t>(i % 40));
        EXPECT_EQ(read_c_string_literal(c_string_literal(s)), s);
    }
    EXPECT_EQ(c_string_literal("Cu-Zn"), "\"Cu-Zn\"");  // catalog ids are written as before
}

// An independent reader of python_string_expression: the bytes of its '...' literal (plain), or of its b'...'
// literal followed by .decode('utf-8', 'replace'); only the escapes \\, \' and \xNN, only printable ASCII.
std::string read_python_string_expression(const std::string& expression) {
    const std::string decode = ".decode('utf-8', 'replace')";
    const bool bytes = expression.starts_with("b'");
    std::string body = expression.substr(bytes ? 2 : 1);
    if (bytes) {
        EXPECT_TRUE(body.ends_with("'" + decode)) << expression;
        body.resize(body.size() - decode.size() - 1);
    } else {
        EXPECT_EQ(expression.front(), '\'') << expression;
        EXPECT_EQ(body.back(), '\'') << expression;
        body.pop_back();
    }
    std::string value;
    for (std::size_t i = 0; i < body.size(); ++i) {
        const char c = body[i];
        EXPECT_NE(c, '\'') << "an unescaped quote ends the literal early: " << expression;
        EXPECT_TRUE(c >= 0x20 && c <= 0x7E) << "a byte outside printable ASCII in " << expression;
        if (c != '\\') {
            value += c;
            continue;
        }
        const char next = body.at(++i);
        if (next == '\'' || next == '\\') {
            value += next;
        } else {
            EXPECT_TRUE(bytes && next == 'x') << "only b'' literals escape bytes: " << expression;
            value += static_cast<char>(std::stoi(body.substr(i + 1, 2), nullptr, 16));
            i += 2;
        }
    }
    return value;
}

TEST(Names, PythonStringExpressionsReadBackAsTheBytesGiven) {
    for (const std::string& s :
         {std::string(""), std::string("gold"), std::string("it's \"gold\" \\ and"), std::string("line\nimport os"),
          std::string("\u202E right-to-left"), std::string("\xff not UTF-8"), std::string("nul\0inside", 10)}) {
        const std::string expression = python_string_expression(s);
        EXPECT_EQ(read_python_string_expression(expression), s) << expression;
    }
    std::mt19937 random(13);
    for (int i = 0; i < 500; ++i) {
        const std::string s = random_bytes(random, static_cast<std::size_t>(i % 40));
        EXPECT_EQ(read_python_string_expression(python_string_expression(s)), s);
    }
    // Printable ASCII stays a plain literal; anything else is the bytes form.
    EXPECT_FALSE(python_string_expression("Cu-Zn (metalfit f82-tint)").starts_with("b'"));
    EXPECT_TRUE(python_string_expression("Å").starts_with("b'"));
}

TEST(Names, PathComponentsStayInTheirFolder) {
    for (const std::string s : {"..", ".", "", "../../../x", "/etc/passwd", "a\\b", ".hidden", "a\nb", "x#y?z%20"}) {
        const std::string c = path_component(s);
        EXPECT_FALSE(c.empty()) << s;
        EXPECT_NE(c.front(), '.') << s;
        EXPECT_EQ(c.find_first_of("/\\\n#?% "), std::string::npos) << c;
    }
    std::mt19937 random(11);
    for (int i = 0; i < 500; ++i) {
        const std::string c = path_component(random_bytes(random, static_cast<std::size_t>(i % 12)));
        EXPECT_FALSE(c.empty());
        EXPECT_NE(c.front(), '.');
        for (const char ch : c) EXPECT_TRUE(static_cast<unsigned char>(ch) >= 0x80 || ch > 0x20) << c;
        EXPECT_EQ(c.find('/'), std::string::npos);
    }
    // Names that already are components (every catalog id) keep their page names.
    for (const std::string s : {"Au", "Cu-Zn", "TiN", "my_gold.v2", "Messing-Ä"}) EXPECT_EQ(path_component(s), s);
}

}  // namespace test_names
