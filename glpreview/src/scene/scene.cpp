#include "glpreview/scene/scene.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string_view>
#include <fstream>
#include <initializer_list>
#include <sstream>

#include "libfit/base/errors.hpp"
#include "libfit/io/catalog.hpp"

namespace metalfit::glpreview {
namespace {

using nlohmann::json;

// Scene text quoted in a message: at most `max` characters, control and non-ASCII bytes written as \xNN, so that a
// message stays one short line whatever the file holds.
std::string excerpt(std::string_view text, std::size_t max = 40) {
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (out.size() >= max) return out + "...";
        const auto c = static_cast<unsigned char>(text[i]);
        if (c >= 0x20 && c < 0x7f) {
            out += static_cast<char>(c);
        } else {
            char hex[8];
            std::snprintf(hex, sizeof hex, "\\x%02X", c);
            out += hex;
        }
    }
    return out;
}

constexpr std::uintmax_t kMaxSceneBytes = 16u << 20;  // 16 MiB

// Reads one JSON object strictly: every key must be known, every value of the expected type. Errors name the file
// and the dotted field path.
class Reader {
public:
    Reader(const json& value, std::string path, const std::filesystem::path& file,
           std::initializer_list<const char*> keys)
        : value_(value), path_(std::move(path)), file_(file) {
        if (!value_.is_object()) fail(path_, "expected an object");
        for (const auto& item : value_.items()) {
            const std::string& key = item.key();  // not a structured binding: clang 14 cannot capture one (P1091)
            const bool known = std::any_of(keys.begin(), keys.end(), [&](const char* k) { return key == k; });
            if (!known) {
                std::string list;
                for (const char* k : keys) list += (list.empty() ? "" : ", ") + std::string(k);
                fail(field(excerpt(key)), "unknown key (known: " + list + ")");
            }
        }
    }

    bool has(const char* key) const { return value_.contains(key); }
    const std::filesystem::path& file() const { return file_; }
    const json& at(const char* key) const { return value_.at(key); }
    std::string field(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

    [[noreturn]] void fail(const std::string& field, const std::string& message) const {
        throw InputError(InputLocation(file_, 0, field), message);
    }

    void read(const char* key, double& out, double min, double max) const {
        if (!has(key)) return;
        const json& v = at(key);
        if (!v.is_number()) fail(field(key), "expected a number");
        out = v.get<double>();
        if (!(out >= min && out <= max)) fail(field(key), "must be in [" + num(min) + ", " + num(max) + "]");
    }
    void read(const char* key, int& out, int min, int max) const {
        if (!has(key)) return;
        const json& v = at(key);
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
        const json& v = at(key);
        if (!v.is_array() || v.size() != 3 || !std::all_of(v.begin(), v.end(), [](const json& e) { return e.is_number(); }))
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
    template <typename Enum>
    void read_enum(const char* key, Enum& out, std::initializer_list<std::pair<const char*, Enum>> names) const {
        std::string text;
        read(key, text);
        if (text.empty()) return;
        std::string list;
        for (const auto& [name, value] : names) {
            if (text == name) {
                out = value;
                return;
            }
            list += (list.empty() ? "" : ", ") + std::string(name);
        }
        fail(field(key), "unknown value '" + excerpt(text) + "' (known: " + list + ")");
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
    const json& value_;
    std::string path_;
    const std::filesystem::path& file_;
};

constexpr double kBig = 1e6;

// A SAX pass that only follows where it is (the dotted field path, as the Reader names fields), to name the field of
// an error nlohmann reports without one (a number overflow).
struct FieldTracker : nlohmann::json_sax<json> {
    struct Level {
        bool array = false;
        std::size_t index = 0;
        std::string key;
    };
    std::vector<Level> levels;
    std::string error_field;
    std::size_t error_byte = 0;

    std::string here() const {
        std::string path;
        for (const Level& l : levels) {
            if (l.array) path += "[" + std::to_string(l.index) + "]";
            else if (!l.key.empty()) path += (path.empty() ? "" : ".") + excerpt(l.key);
        }
        return path;
    }
    bool value() {
        if (!levels.empty() && levels.back().array) ++levels.back().index;
        return true;
    }
    bool null() override { return value(); }
    bool boolean(bool) override { return value(); }
    bool number_integer(number_integer_t) override { return value(); }
    bool number_unsigned(number_unsigned_t) override { return value(); }
    bool number_float(number_float_t, const string_t&) override { return value(); }
    bool string(string_t&) override { return value(); }
    bool binary(binary_t&) override { return value(); }
    bool start_object(std::size_t) override {
        levels.push_back({false, 0, ""});
        return true;
    }
    bool key(string_t& k) override {
        levels.back().key = k;
        return true;
    }
    bool end_object() override {
        levels.pop_back();
        return value();
    }
    bool start_array(std::size_t) override {
        levels.push_back({true, 0, ""});
        return true;
    }
    bool end_array() override {
        levels.pop_back();
        return value();
    }
    bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception&) override {
        error_field = here();
        error_byte = position;
        return false;
    }
};

bool inside(const std::filesystem::path& p, const std::filesystem::path& folder) {
    if (folder.empty()) return false;
    auto f = folder.begin(), q = p.begin();
    for (; f != folder.end(); ++f, ++q) {
        if (f->empty()) continue;  // a trailing separator
        if (q == p.end() || *f != *q) return false;
    }
    return true;
}

void check_box(const Reader& r, const char* what, const Vec3& min, const Vec3& max) {
    if (!(min.x < max.x && min.y < max.y && min.z < max.z)) r.fail(r.field(what), "min must be below max on every axis");
}

Room read_room(const Reader& r) {
    Room room;
    r.read("min", room.min);
    r.read("max", room.max);
    check_box(r, "max", room.min, room.max);
    r.read_color("wall_x_min", room.wall_x_min);
    r.read_color("wall_x_max", room.wall_x_max);
    r.read_color("wall_z_min", room.wall_z_min);
    r.read_color("wall_z_max", room.wall_z_max);
    r.read_color("floor_light", room.floor_light);
    r.read_color("floor_dark", room.floor_dark);
    r.read_color("ceiling", room.ceiling);
    r.read("checker", room.checker, 1e-3, kBig);
    bool panels_given = false;
    r.each("panels", [&](const json& v, const std::string& path) {
        panels_given = true;
        Reader p(v, path, r.file(), {"min", "max", "radiance"});
        CeilingPanel panel;
        auto read2 = [&](const char* key, double& a, double& b) {
            if (!p.has(key)) p.fail(p.field(key), "missing ([x, z])");
            const json& e = p.at(key);
            if (!e.is_array() || e.size() != 2 || !e[0].is_number() || !e[1].is_number())
                p.fail(p.field(key), "expected [x, z]");
            a = e[0].get<double>();
            b = e[1].get<double>();
        };
        read2("min", panel.min_x, panel.min_z);
        read2("max", panel.max_x, panel.max_z);
        if (!(panel.min_x < panel.max_x && panel.min_z < panel.max_z)) p.fail(p.field("max"), "min must be below max");
        p.read_color("radiance", panel.radiance);
        if (room.panels.size() >= kMaxPanels) r.fail(r.field("panels"), "at most " + std::to_string(kMaxPanels) + " panels");
        room.panels.push_back(panel);
    });
    if (!panels_given) {  // default: a 2 × 2 grid of panels over the room's middle
        const double cx = 0.5 * (room.min.x + room.max.x), cz = 0.5 * (room.min.z + room.max.z);
        const double sx = 0.15 * (room.max.x - room.min.x), sz = 0.15 * (room.max.z - room.min.z);
        for (int i : {-1, 1})
            for (int j : {-1, 1})
                room.panels.push_back({cx + i * sx - 0.4 * sx, cz + j * sz - 0.4 * sz, cx + i * sx + 0.4 * sx,
                                       cz + j * sz + 0.4 * sz, {6, 6, 6}});
    }
    r.each("boxes", [&](const json& v, const std::string& path) {
        Reader b(v, path, r.file(), {"min", "max", "color"});
        RoomBox box;
        if (!b.has("min") || !b.has("max")) b.fail(path, "a box needs min and max");
        b.read("min", box.min);
        b.read("max", box.max);
        check_box(b, "max", box.min, box.max);
        b.read_color("color", box.color);
        if (room.boxes.size() >= kMaxRoomBoxes) b.fail(path, "at most " + std::to_string(kMaxRoomBoxes) + " boxes and columns together");
        room.boxes.push_back(box);
    });
    r.each("columns", [&](const json& v, const std::string& path) {
        Reader c(v, path, r.file(), {"center", "half_width", "color"});
        if (!c.has("center")) c.fail(c.field("center"), "missing ([x, z])");
        const json& e = c.at("center");
        if (!e.is_array() || e.size() != 2 || !e[0].is_number() || !e[1].is_number())
            c.fail(c.field("center"), "expected [x, z]");
        double half = 0.2;
        c.read("half_width", half, 1e-3, kBig);
        RoomBox box;
        box.min = {e[0].get<double>() - half, room.min.y, e[1].get<double>() - half};
        box.max = {e[0].get<double>() + half, room.max.y, e[1].get<double>() + half};
        c.read_color("color", box.color);
        if (room.boxes.size() >= kMaxRoomBoxes) c.fail(path, "at most " + std::to_string(kMaxRoomBoxes) + " boxes and columns together");
        room.boxes.push_back(box);
    });
    return room;
}

// "proxy": {"box": {"min": [..], "max": [..]}} or {"sphere": radius} (docs/scene.md, "Environments").
EnvironmentProxy read_proxy(const Reader& environment) {
    const Reader r(environment.at("proxy"), "environment.proxy", environment.file(), {"box", "sphere"});
    if (r.has("box") == r.has("sphere")) r.fail("environment.proxy", "expected exactly one of 'box' or 'sphere'");
    if (r.has("sphere")) {
        SphereProxy sphere;
        r.read("sphere", sphere.radius, 1e-3, kBig);
        return sphere;
    }
    const Reader b(r.at("box"), "environment.proxy.box", environment.file(), {"min", "max"});
    BoxProxy box;
    for (const char* key : {"min", "max"})
        if (!b.has(key)) b.fail(b.field(key), "missing");
    b.read("min", box.min);
    b.read("max", box.max);
    for (int i = 0; i < 3; ++i) {
        if (std::abs(box.min[i]) > kBig) b.fail(b.field("min"), "coordinates must be in [-1e+06, 1e+06]");
        if (std::abs(box.max[i]) > kBig) b.fail(b.field("max"), "coordinates must be in [-1e+06, 1e+06]");
        if (!(box.max[i] - box.min[i] >= 1e-3)) b.fail(b.field("max"), "must exceed min by at least 1e-3 on every axis");
    }
    return box;
}

}  // namespace

void check_image_size(const std::filesystem::path& file, const std::string& what, int width, int height) {
    if (width < 1 || height < 1 || width > kMaxImageEdge || height > kMaxImageEdge)
        throw InputError(InputLocation(file, 0, what), "width and height must be in [1, " + std::to_string(kMaxImageEdge) + "]");
    if (static_cast<long long>(width) * height > kMaxImagePixels)
        throw InputError(InputLocation(file, 0, what), std::to_string(width) + " x " + std::to_string(height) + " is more than " +
                                                         std::to_string(kMaxImagePixels) + " pixels");
}

std::vector<std::string> placement_warnings(const Scene& scene) {
    std::vector<std::string> warnings;
    if (scene.environment.type == EnvironmentType::equirect) {
        // The image painted on a box proxy: a camera outside it looks at the painted box from behind.
        const auto* box = scene.environment.equirect.proxy ? std::get_if<BoxProxy>(&*scene.environment.equirect.proxy) : nullptr;
        const Vec3 c = scene.camera.position;
        bool inside = true;
        for (int i = 0; box && i < 3; ++i) inside = inside && c[i] > box->min[i] && c[i] < box->max[i];
        if (box && !inside && scene.camera_position_given)
            warnings.push_back(scene.file.string() + ": camera.position: outside the proxy box (environment.proxy.box: the view shows the painted box from behind)");
        return warnings;
    }
    if (scene.environment.type != EnvironmentType::room) return warnings;
    const Room& room = scene.environment.room;
    const std::string file = scene.file.string() + ": ";
    const Vec3 c = scene.camera.position;
    bool camera_inside = true;
    for (int i = 0; i < 3; ++i) camera_inside = camera_inside && c[i] > room.min[i] && c[i] < room.max[i];
    if (!camera_inside && scene.camera_position_given) warnings.push_back(file + "camera.position: outside the room (the view shows the walls from behind)");
    for (std::size_t s = 0; s < scene.spheres.size(); ++s) {
        const Sphere& sphere = scene.spheres[s];
        bool through = false;
        for (int i = 0; i < 3; ++i)
            through = through || sphere.center[i] - sphere.radius < room.min[i] || sphere.center[i] + sphere.radius > room.max[i];
        if (through)
            warnings.push_back(file + "spheres[" + std::to_string(s) + "]: not inside the room (it reaches through or lies beyond a wall; its reflection there is meaningless)");
    }
    return warnings;
}

bool policy_allows(const PathPolicy& policy, const std::filesystem::path& scene_file, const std::filesystem::path& resolved) {
    namespace fs = std::filesystem;
    if (policy.allow_outside) return true;
    std::error_code error;
    const fs::path folder = fs::weakly_canonical(fs::absolute(scene_file).parent_path(), error);
    const fs::path data = policy.data_dir.empty() ? fs::path() : fs::weakly_canonical(fs::absolute(policy.data_dir), error);
    return inside(resolved, folder) || inside(resolved, data);
}

void confine_scene_paths(const Scene& scene, const PathPolicy& policy) {
    if (policy.allow_outside) return;
    namespace fs = std::filesystem;
    std::error_code error;
    auto check = [&](const fs::path& path, const std::string& field) {
        const fs::path resolved = fs::weakly_canonical(fs::absolute(path), error);
        if (!policy_allows(policy, scene.file, resolved))
            throw InputError(InputLocation(scene.file, 0, field),
                             "a path outside the scene's folder and the database (glpreview --allow-paths-outside to allow it)");
    };
    for (std::size_t i = 0; i < scene.spheres.size(); ++i)
        if (const fs::path written = scene.spheres[i].material; looks_like_path(scene.spheres[i].material))
            check(written.is_absolute() ? written : scene.file.parent_path() / written, "spheres[" + std::to_string(i) + "].material");
    if (scene.environment.type == EnvironmentType::equirect) check(scene.environment.equirect.file, "environment.file");
}

Vec3 Environment::reference() const {
    if (reference_point) return *reference_point;
    if (type == EnvironmentType::room) return 0.5 * (room.min + room.max);
    return {0, 0, 0};
}

std::optional<BoxProxy> Environment::parallax_box() const {
    if (type == EnvironmentType::room) return BoxProxy{room.min, room.max};
    if (type == EnvironmentType::equirect && equirect.proxy)
        if (const auto* box = std::get_if<BoxProxy>(&*equirect.proxy)) return *box;
    return std::nullopt;
}

const char* to_string(ReflectionMode mode) {
    switch (mode) {
        case ReflectionMode::classic: return "classic";
        case ReflectionMode::distance_impostor: return "distance-impostor";
        case ReflectionMode::box_parallax: return "box-parallax";
    }
    return "?";
}

const char* to_string(Strategy strategy) {
    switch (strategy) {
        case Strategy::secant: return "secant";
        case Strategy::false_position: return "false-position";
        case Strategy::mixed: return "mixed";
        case Strategy::illinois: return "illinois";
        case Strategy::safe_secant: return "safe-secant";
    }
    return "?";
}

const char* to_string(EnvironmentType type) {
    switch (type) {
        case EnvironmentType::room: return "room";
        case EnvironmentType::sphere_room: return "sphere-room";
        case EnvironmentType::equirect: return "equirect";
    }
    return "?";
}

const char* to_string(GlossyMethod method) { return method == GlossyMethod::localized ? "localized" : "prefiltered"; }

std::string fresnel_name(const FresnelChoice& fresnel) {
    if (const auto* model = std::get_if<ModelFresnel>(&fresnel)) return model->model;
    return "reference";
}

Scene parse_scene(const std::string& json_text, const std::filesystem::path& file) {
    json root;
    try {
        root = json::parse(json_text);
    } catch (const json::out_of_range& e) {  // a number beyond double range (1e309): name where it is
        FieldTracker tracker;
        json::sax_parse(json_text, &tracker);
        const auto offset = std::min<std::size_t>(tracker.error_byte, json_text.size());
        const int line = 1 + static_cast<int>(std::count(json_text.begin(), json_text.begin() + static_cast<long>(offset), '\n'));
        throw InputError(InputLocation(file, line, tracker.error_field), "number beyond the range of a double");
    } catch (const json::parse_error& e) {
        // nlohmann reports the byte offset; turn it into a line number.
        const auto offset = std::min<std::size_t>(e.byte, json_text.size());
        const int line = 1 + static_cast<int>(std::count(json_text.begin(), json_text.begin() + static_cast<long>(offset), '\n'));
        std::string what = e.what();
        const auto colon = what.rfind(": ");
        throw InputError(InputLocation(file, line), "invalid JSON: " + excerpt(colon == std::string::npos ? what : what.substr(colon + 2), 120));
    }
    Scene scene;
    scene.file = file;
    Reader top(root, "", file, {"image", "space", "camera", "environment", "spheres", "outputs"});
    if (top.has("space")) top.read("space", scene.space);

    if (top.has("image")) {
        Reader r(top.at("image"), "image", file, {"width", "height"});
        r.read("width", scene.width, 1, kMaxImageEdge);
        r.read("height", scene.height, 1, kMaxImageEdge);
        check_image_size(file, "image", scene.width, scene.height);
    }
    if (top.has("camera")) {
        Reader r(top.at("camera"), "camera", file, {"position", "look_at", "up", "fov_y_deg"});
        r.read("position", scene.camera.position);
        scene.camera_position_given = r.has("position");
        r.read("look_at", scene.camera.look_at);
        r.read("up", scene.camera.up);
        r.read("fov_y_deg", scene.camera.fov_y_deg, 1, 170);
        if (length(scene.camera.look_at - scene.camera.position) == 0) r.fail("camera.look_at", "equals the position");
        if (length(cross(scene.camera.look_at - scene.camera.position, scene.camera.up)) < 1e-9)
            r.fail("camera.up", "is parallel to the viewing direction");
    }
    {
        static const json no_environment = json::object();  // the default room, with its default panels
        const json& env = top.has("environment") ? top.at("environment") : no_environment;
        Environment& e = scene.environment;
        std::string type = "room";
        if (env.is_object() && env.contains("type")) {
            if (!env["type"].is_string()) top.fail("environment.type", "expected a string");
            type = env["type"].get<std::string>();
        }
        if (type == "room") {
            Reader r(env, "environment", file,
                     {"type", "reference_point", "cube_size", "min", "max", "wall_x_min", "wall_x_max", "wall_z_min",
                      "wall_z_max", "floor_light", "floor_dark", "ceiling", "checker", "panels", "boxes", "columns"});
            e.type = EnvironmentType::room;
            e.room = read_room(r);
            r.read("cube_size", e.cube_size, 8, 4096);
            if (r.has("reference_point")) {
                Vec3 p;
                r.read("reference_point", p);
                e.reference_point = p;
                for (int i = 0; i < 3; ++i)
                    if (!(p[i] > e.room.min[i] && p[i] < e.room.max[i])) r.fail("environment.reference_point", "must be inside the room");
            }
        } else if (type == "sphere-room") {
            Reader r(env, "environment", file, {"type", "reference_point", "cube_size", "radius", "checker_deg", "light", "dark"});
            e.type = EnvironmentType::sphere_room;
            r.read("radius", e.sphere_room.radius, 1e-3, kBig);
            r.read("checker_deg", e.sphere_room.checker_deg, 0.1, 180);
            r.read_color("light", e.sphere_room.light);
            r.read_color("dark", e.sphere_room.dark);
            r.read("cube_size", e.cube_size, 8, 4096);
            if (r.has("reference_point")) {
                Vec3 p;
                r.read("reference_point", p);
                e.reference_point = p;
            }
        } else if (type == "equirect") {
            Reader r(env, "environment", file, {"type", "file", "intensity", "colorspace", "proxy", "reference_point", "cube_size"});
            e.type = EnvironmentType::equirect;
            std::string path;
            r.read("file", path);
            if (path.empty()) r.fail("environment.file", "missing (an equirectangular EXR or HDR image)");
            e.equirect.file = std::filesystem::path(path).is_absolute() ? std::filesystem::path(path)
                                                                        : file.parent_path() / path;
            r.read("intensity", e.equirect.intensity, 0, kBig);
            if (r.has("colorspace")) r.read("colorspace", e.equirect.colorspace);
            if (r.has("proxy")) e.equirect.proxy = read_proxy(r);
            r.read("cube_size", e.cube_size, 8, 4096);
            if (r.has("reference_point")) {
                Vec3 p;
                r.read("reference_point", p);
                e.reference_point = p;
            }
            if (const auto* box = e.equirect.proxy ? std::get_if<BoxProxy>(&*e.equirect.proxy) : nullptr) {
                const Vec3 o = e.reference();
                for (int i = 0; i < 3; ++i)
                    if (!(o[i] > box->min[i] && o[i] < box->max[i]))
                        r.fail(r.has("reference_point") ? "environment.reference_point" : "environment.proxy.box",
                               "the capture point (environment.reference_point, default the origin) must lie inside the proxy box");
            }
            if (!e.equirect.proxy)
                for (const char* key : {"reference_point", "cube_size"})
                    if (r.has(key))
                        scene.warnings.push_back(file.string() + ": environment." + key +
                                                 ": ignored: an equirect without a proxy is at infinity (nothing is captured)");
        } else {
            top.fail("environment.type", "unknown value '" + excerpt(type) + "' (known: room, sphere-room, equirect)");
        }
    }
    if (!top.has("spheres")) top.fail("spheres", "missing (at least one sphere)");
    top.each("spheres", [&](const json& v, const std::string& path) {
        Reader r(v, path, file, {"center", "radius", "material", "source", "fresnel", "params", "reflection", "strategy", "iterations",
                                  "tolerance", "roughness", "glossy", "localized_size"});
        Sphere s;
        if (!r.has("center")) r.fail(r.field("center"), "missing");
        r.read("center", s.center);
        r.read("radius", s.radius, 1e-4, kBig);
        r.read("material", s.material);
        r.read("source", s.source);
        std::string fresnel = "reference", params = "fit";
        r.read("fresnel", fresnel);
        r.read("params", params);
        if (params != "fit" && params != "closed") r.fail(r.field("params"), "unknown value '" + excerpt(params) + "' (known: fit, closed)");
        if (fresnel != "reference")  // "params" is checked on a reference sphere too, and means nothing there
            s.fresnel = ModelFresnel{fresnel, params == "closed" ? ParameterSource::closed : ParameterSource::fit};
        r.read_enum("reflection", s.reflection,
                    {{"classic", ReflectionMode::classic},
                     {"distance-impostor", ReflectionMode::distance_impostor},
                     {"box-parallax", ReflectionMode::box_parallax}});
        r.read_enum("strategy", s.strategy,
                    {{"secant", Strategy::secant},
                     {"false-position", Strategy::false_position},
                     {"mixed", Strategy::mixed},
                     {"illinois", Strategy::illinois},
                     {"safe-secant", Strategy::safe_secant}});
        r.read("iterations", s.iterations, 0, 64);
        r.read("tolerance", s.tolerance, 0, 1);
        r.read("roughness", s.roughness, 0, 1);
        r.read_enum("glossy", s.glossy, {{"prefiltered", GlossyMethod::prefiltered}, {"localized", GlossyMethod::localized}});
        r.read("localized_size", s.localized_size, 2, 16);
        if (r.has("reflection") && s.rough() && s.glossy == GlossyMethod::localized)
            scene.warnings.push_back(file.string() + ": " + r.field("reflection") +
                                     ": ignored: glossy 'localized' localizes by the area lights' positions");
        if (r.has("localized_size") && !(s.rough() && s.glossy == GlossyMethod::localized))
            scene.warnings.push_back(file.string() + ": " + r.field("localized_size") + ": ignored: only a rough sphere with glossy 'localized' uses it");
        if (s.rough() && !scene.environment.captured())
            r.fail(r.field("roughness"), "rough spheres need a captured environment (room, sphere-room or an equirect with a proxy): an equirect at infinity is not prefiltered");
        if (r.has("glossy") && !s.rough())
            scene.warnings.push_back(file.string() + ": " + r.field("glossy") + ": ignored: the sphere is a mirror (roughness 0)");
        if (s.reflection != ReflectionMode::distance_impostor)
            for (const char* key : {"strategy", "iterations", "tolerance"})
                if (r.has(key))
                    scene.warnings.push_back(file.string() + ": " + r.field(key) + ": ignored: only the distance impostor refines (reflection '" +
                                             to_string(s.reflection) + "')");
        if (s.reflection != ReflectionMode::classic && !scene.environment.captured())
            r.fail(r.field("reflection"), "an equirect environment is at infinity without a proxy: only 'classic' reflections");
        if (s.reflection == ReflectionMode::box_parallax && !scene.environment.parallax_box())
            r.fail(r.field("reflection"), "box-parallax needs a room environment or an equirect with a box proxy");
        if (scene.spheres.size() >= kMaxSpheres) top.fail("spheres", "at most " + std::to_string(kMaxSpheres) + " spheres");
        scene.spheres.push_back(s);
    });
    if (scene.spheres.empty()) top.fail("spheres", "at least one sphere");
    if (top.has("outputs")) {
        Reader r(top.at("outputs"), "outputs", file, {"beauty", "reference", "difference", "metrics", "exr", "png", "localization",
                                                             "timing_frames", "reference_samples"});
        Outputs& o = scene.outputs;
        r.read("beauty", o.beauty);
        r.read("reference", o.reference);
        r.read("difference", o.difference);
        r.read("metrics", o.metrics);
        r.read("exr", o.exr);
        r.read("png", o.png);
        r.read("localization", o.localization);
        r.read("timing_frames", o.timing_frames, 5, 1000);
        r.read("reference_samples", o.reference_samples, 1, 65536);
        if (!o.exr && !o.png && (o.beauty || o.reference || o.difference)) r.fail("outputs.exr", "images asked for but neither exr nor png");
    }
    for (std::string& w : placement_warnings(scene)) scene.warnings.push_back(std::move(w));
    return scene;
}

Scene load_scene(const std::filesystem::path& file) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(file, error))  // a FIFO or a device would hang or never end
        throw InputError(InputLocation(file), std::filesystem::exists(file, error) ? "not a regular file" : "cannot read the scene file");
    if (std::filesystem::file_size(file, error) > kMaxSceneBytes)
        throw InputError(InputLocation(file), "larger than 16 MiB: not a scene");
    std::ifstream in(file, std::ios::binary);
    if (!in) throw InputError(InputLocation(file), "cannot read the scene file");
    std::stringstream text;
    text << in.rdbuf();
    return parse_scene(text.str(), file);
}

}  // namespace metalfit::glpreview
