// Internal: a cheap pre-scan of a YAML text before yaml-cpp parses it (docs/data.md, "Limits"). yaml-cpp recurses once
// per nesting level and builds a node per item, so 16 MiB of `[` cost gigabytes and tens of seconds, and aliases to
// aliases expand a small file exponentially in whoever walks the tree (OCIO's config reader). The scan is linear in
// the text and allocates only its stacks.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string_view>

namespace metalfit::detail {

// The deepest nesting accepted: flow collections ([ {) and block levels (indentation, "- ") together. The database's
// files nest 4 deep, OCIO configs about 8.
inline constexpr int kMaxYamlDepth = 64;
// The most nodes (items, keys and collections, counted by their indicators): yaml-cpp spends up to about 1 KB a node (a 500,000-key mapping took 480 MB).
inline constexpr std::size_t kMaxYamlNodes = 200000;
// What aliases may add: each alias counts the bytes of the node its anchor marks (with the aliases inside it), and
// the sum may not exceed this (so no alias chain grows a file beyond twice the input limit when expanded).
inline constexpr std::size_t kMaxYamlAliasBytes = std::size_t{16} << 20;

// What the scan counted (for limits of a format of its own, as OCIO's number of colour spaces).
struct YamlShape {
    std::size_t nodes = 0;
    std::size_t aliases = 0;  // aliases to anchors seen before them
};

// Throws InputError({file, line}, why) when `text` nests deeper than kMaxYamlDepth, holds more than kMaxYamlNodes
// nodes, or its aliases expand beyond kMaxYamlAliasBytes (or refer to an anchor that contains them). Otherwise
// returns what it counted; whether the text is valid YAML is yaml-cpp's to say.
YamlShape check_yaml_structure(std::string_view text, const std::filesystem::path& file);

}  // namespace metalfit::detail
