// Reading a scene's JSON strictly, for the core parser and the effects that read their own keys
// (Effect::scene_keys, Effect::sphere_keys): every key must be known, every value of the expected type; errors name
// the file and the dotted field path ("scene.json: spheres[1].iterations: expected an integer").
#pragma once

#include <algorithm>
#include <filesystem>
#include <initializer_list>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "libfit/base/enum_names.hpp"

#include "glpreview/scene/vec3.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/base/utf8.hpp"
#include "libfit/color/color.hpp"

namespace metalfit::glpreview {

// The largest value of a length, radius or intensity a scene may give.
inline constexpr double kSceneBig = 1e6;

// Scene text quoted in a message: at most `max` characters, control and non-ASCII bytes written as \xNN, so that a
// message stays one short line whatever the file holds.
inline std::string scene_excerpt(std::string_view text, std::size_t max = 40) {
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (out.size() >= max) return out + "...";
        const auto c = static_cast<unsigned char>(text[i]);
        if (c >= 0x20 && c < 0x7f) {
            out += static_cast<char>(c);
        } else {
            out += byte_escape(c);
        }
    }
    return out;
}

// Reads one JSON object strictly: every key must be known, every value of the expected type. Errors name the file
// and the dotted field path.
class SceneReader {
public:
    SceneReader(const nlohmann::json& value, std::string path, const std::filesystem::path& file,
                std::initializer_list<const char*> keys)
        : SceneReader(value, std::move(path), file, std::vector<const char*>(keys)) {}
    // `keys` the known keys: those of the core and those the registered effects read (Effect::scene_keys).
    SceneReader(const nlohmann::json& value, std::string path, const std::filesystem::path& file,
                const std::vector<const char*>& keys)
        : value_(value), path_(std::move(path)), file_(file) {
        if (!value_.is_object()) fail(path_, "expected an object");
        for (const auto& item : value_.items()) {
            const std::string& key = item.key();  // not a structured binding: clang 14 cannot capture one (P1091)
            const bool known = std::any_of(keys.begin(), keys.end(), [&](const char* k) { return key == k; });
            if (!known) {
                std::string list;
                for (const char* k : keys) list += (list.empty() ? "" : ", ") + std::string(k);
                fail(field(scene_excerpt(key)), "unknown key (known: " + list + ")");
            }
        }
    }
    const std::string& path() const { return path_; }

    bool has(const char* key) const { return value_.contains(key); }
    const std::filesystem::path& file() const { return file_; }
    const nlohmann::json& at(const char* key) const { return value_.at(key); }
    std::string field(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

    [[noreturn]] void fail(const std::string& field, const std::string& message) const {
        throw InputError(InputLocation(file_, 0, field), message);
    }

    void read(const char* key, double& out, double min, double max) const {
        if (!has(key)) return;
        const nlohmann::json& v = at(key);
        if (!v.is_number()) fail(field(key), "expected a number");
        out = v.get<double>();
        if (!(out >= min && out <= max)) fail(field(key), "must be in [" + num(min) + ", " + num(max) + "]");
    }
    void read(const char* key, int& out, int min, int max) const {
        if (!has(key)) return;
        const nlohmann::json& v = at(key);
        if (!v.is_number_integer()) fail(field(key), "expected an integer");
        const auto i = v.get<long long>();
        if (i < min || i > max) fail(field(key), "must be in [" + num(min) + ", " + num(max) + "]");
        out = static_cast<int>(i);
    }
    void read(const char* key, bool& out) const {
        if (!has(key)) return;
        if (!at(key).is_boolean()) fail(field(key), "expected true or false");
        out = at(key).get<bool>();
    }
    void read(const char* key, std::string& out) const {
        if (!has(key)) return;
        if (!at(key).is_string()) fail(field(key), "expected a string");
        out = at(key).get<std::string>();
        if (out.empty()) fail(field(key), "must not be empty");
    }
    void read(const char* key, Vec3& out) const {
        if (!has(key)) return;
        const nlohmann::json& v = at(key);
        if (!v.is_array() || v.size() != 3 ||
            !std::all_of(v.begin(), v.end(), [](const nlohmann::json& e) { return e.is_number(); }))
            fail(field(key), "expected an array of 3 numbers");
        out = {v[0].get<double>(), v[1].get<double>(), v[2].get<double>()};
    }
    void read_color(const char* key, RGB& out) const {
        if (!has(key)) return;
        Vec3 triple;
        read(key, triple);
        if (triple.x < 0 || triple.y < 0 || triple.z < 0) fail(field(key), "radiance must not be negative");
        out = {triple.x, triple.y, triple.z};
    }
    // A string key naming a value of `names` (a table of libfit's EnumNames); "unknown value 'x' (known: …)".
    template <typename Enum, std::size_t N>
    void read_enum(const char* key, Enum& out, const EnumNames<Enum, N>& names) const {
        std::string text;
        read(key, text);
        if (text.empty()) return;
        if (const std::optional<Enum> value = names.find(text)) {
            out = *value;
            return;
        }
        fail(field(key), "unknown value '" + scene_excerpt(text) + "' (" + names.known() + ")");
    }
    // Calls f(element, "key[i]") for each element of an array-valued key.
    template <typename F>
    void each(const char* key, F f) const {
        if (!has(key)) return;
        if (!at(key).is_array()) fail(field(key), "expected an array");
        for (std::size_t i = 0; i < at(key).size(); ++i) f(at(key)[i], field(key) + "[" + std::to_string(i) + "]");
    }

private:
    static std::string num(double v) {
        std::ostringstream s;
        s << v;
        return s.str();
    }
    const nlohmann::json& value_;
    std::string path_;
    const std::filesystem::path& file_;
};

}  // namespace metalfit::glpreview
