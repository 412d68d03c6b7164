// Names are data: the one rule by which text that came from an input (a material's name or id, a file's name, a
// --reference, a YAML's REFERENCES or COMMENTS) is written into a file that a consumer parses as code, markup or a
// path. Every writer goes through these; none writes such text as it came (docs/export.md, "Names are data").
#pragma once

#include <string>
#include <string_view>

namespace metalfit {

// The text as one line of visible characters, safe inside a line comment of C, C++, GLSL and HLSL, an XML comment or
// attribute (after the XML writer's own escaping) and an HTML text node (after HTML escaping): line breaks and tabs
// become spaces, other control characters and bytes that are not UTF-8 are written as \xNN, invisible and
// direction-changing characters (U+202E and the other bidirectional controls, zero-width spaces, U+2028/U+2029, the
// byte-order mark) as <U+XXXX> — sanitised_message's rule, without its length cut. A backslash at the end of the line
// is written as \x5C, so that no line comment continues onto the next line.
std::string comment_text(std::string_view text);

// A C or C++ string literal (quotes included) whose value is `text`'s bytes: the quote and the backslash escaped,
// control characters and bytes above 0x7E as three-digit octal escapes (which, unlike \x, end by themselves), so the
// literal holds only printable ASCII and no character a compiler warns about (-Wbidi-chars).
std::string c_string_literal(std::string_view text);

// A Python 3 expression whose value is the str of `text`'s bytes read as UTF-8 (what Blender and every Python tool
// name things with): a plain literal '...' when every byte is printable ASCII (the quote and the backslash escaped),
// else b'...'.decode('utf-8', 'replace') with every other byte as \xNN, so the source holds only printable ASCII
// whatever the text (a newline, a quote, U+202E, bytes that are not UTF-8, which become U+FFFD as Python reads them).
std::string python_string_expression(std::string_view text);

// `name` as one path component inside an output folder, also usable as it is in a relative URL: every ASCII byte but
// letters, digits, '-', '_' and '.' becomes '_' (separators, control characters, spaces, '#', '?', '%', ':'), UTF-8
// beyond ASCII is kept; never empty, "." or "..", never starting with a dot (a leading dot becomes '_'). A name that is
// already such a component comes back unchanged (catalog ids keep their page names).
std::string path_component(std::string_view name);

}  // namespace metalfit
