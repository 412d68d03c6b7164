// The rule for --id-prefix: a prefix every exported identifier can carry in C++, GLSL and HLSL.
#include <algorithm>
#include <set>

#include "libfit/export/export.hpp"

namespace metalfit {

std::string id_prefix_problem(std::string_view text) {
    // Keywords and reserved words of C++20, GLSL 4.60 / ES 3.00 and HLSL (Shader Model 6) that match the pattern.
    static const std::set<std::string_view> reserved{
        "alignas", "alignof", "and", "and_eq", "asm", "auto", "bitand", "bitor", "bool", "break", "case", "catch",
        "char", "char8_t", "char16_t", "char32_t", "class", "compl", "concept", "const", "consteval", "constexpr",
        "constinit", "const_cast", "continue", "co_await", "co_return", "co_yield", "decltype", "default", "delete",
        "do", "double", "dynamic_cast", "else", "enum", "explicit", "export", "extern", "false", "float", "for",
        "friend", "goto", "if", "inline", "int", "long", "mutable", "namespace", "new", "noexcept", "not", "not_eq",
        "nullptr", "operator", "or", "or_eq", "private", "protected", "public", "register", "reinterpret_cast",
        "requires", "return", "short", "signed", "sizeof", "static", "static_assert", "static_cast", "struct", "switch",
        "template", "this", "thread_local", "throw", "true", "try", "typedef", "typeid", "typename", "union",
        "unsigned", "using", "virtual", "void", "volatile", "wchar_t", "while", "xor", "xor_eq",
        // GLSL
        "attribute", "uniform", "varying", "buffer", "shared", "coherent", "restrict", "readonly", "writeonly",
        "layout", "centroid", "flat", "smooth", "noperspective", "patch", "sample", "subroutine", "in", "out", "inout",
        "invariant", "precise", "discard", "uint", "lowp", "mediump", "highp", "precision", "vec2", "vec3", "vec4",
        "ivec2", "ivec3", "ivec4", "uvec2", "uvec3", "uvec4", "bvec2", "bvec3", "bvec4", "dvec2", "dvec3", "dvec4",
        "mat2", "mat3", "mat4", "common", "partition", "active", "filter", "input", "output", "superp", "fixed", "half",
        "hvec2", "hvec3", "hvec4", "fvec2", "fvec3", "fvec4", "cast", "interface", "noinline", "external", "resource",
        // HLSL
        "bool2", "bool3", "bool4", "cbuffer", "tbuffer", "column_major", "row_major", "compile", "dword", "float2",
        "float3", "float4", "groupshared", "half2", "half3", "half4", "int2", "int3", "int4", "line", "lineadj",
        "linear", "matrix", "nointerpolation", "packoffset", "pass", "pixelfragment", "point", "sampler",
        "sampler_state", "snorm", "stateblock", "technique", "texture", "triangle", "triangleadj", "unorm", "vector",
        "vertexfragment", "min16float", "min10float", "min16int", "min12int", "min16uint", "uint2", "uint3", "uint4"};
    if (text.empty() || text.size() > 31 || !(text[0] >= 'a' && text[0] <= 'z') ||
        !std::all_of(text.begin(), text.end(),
                     [](char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_'; }))
        return "expected [a-z][a-z0-9_]{0,30} (a lower-case letter, then up to 30 letters, digits or '_')";
    if (text.find("__") != std::string::npos || text.back() == '_')
        return "the identifiers would hold \"__\", which C++ and GLSL reserve";
    if (text == "gl") return "GLSL reserves identifiers starting with gl_";
    if (reserved.contains(text)) return "a C++, GLSL or HLSL keyword";
    return {};
}

}  // namespace metalfit
