#include "glpreview/scene/scene.hpp"
#include "glpreview/scene/scene_reader.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <string_view>

#include "glpreview/scene/scene_keys.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/base/text.hpp"
#include "libfit/io/catalog.hpp"
#include "libfit/io/layer_materials.hpp"

namespace metalfit::glpreview {
namespace {

using nlohmann::json;
using Reader = SceneReader;

constexpr std::uintmax_t kMaxSceneBytes = 16u << 20;  // 16 MiB

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
            if (l.array)
                path += "[" + std::to_string(l.index) + "]";
            else if (!l.key.empty())
                path += (path.empty() ? "" : ".") + scene_excerpt(l.key);
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

}  // namespace

void check_image_size(const std::filesystem::path& file, const std::string& what, int width, int height) {
    if (width < 1 || height < 1 || width > kMaxImageEdge || height > kMaxImageEdge)
        throw InputError(InputLocation(file, 0, what),
                         "width and height must be in [1, " + std::to_string(kMaxImageEdge) + "]");
    if (static_cast<long long>(width) * height > kMaxImagePixels)
        throw InputError(InputLocation(file, 0, what), std::to_string(width) + " x " + std::to_string(height) +
                                                           " is more than " + std::to_string(kMaxImagePixels) +
                                                           " pixels");
}

std::vector<std::string> placement_warnings(const Scene& scene) {
    std::vector<std::string> warnings;
    if (scene.environment.type == EnvironmentType::equirect) {
        // The image painted on a box proxy: a camera outside it looks at the painted box from behind.
        const auto* box =
            scene.environment.equirect.proxy ? std::get_if<BoxProxy>(&*scene.environment.equirect.proxy) : nullptr;
        const Vec3 c = scene.camera.position;
        bool inside = true;
        for (int i = 0; box && i < 3; ++i) inside = inside && c[i] > box->min[i] && c[i] < box->max[i];
        if (box && !inside && scene.camera_position_given)
            warnings.push_back(
                scene.file.string() +
                ": camera.position: outside the proxy box (environment.proxy.box: the view shows the painted box from behind)");
        return warnings;
    }
    if (scene.environment.type != EnvironmentType::room) return warnings;
    const Room& room = scene.environment.room;
    const std::string file = scene.file.string() + ": ";
    const Vec3 c = scene.camera.position;
    bool camera_inside = true;
    for (int i = 0; i < 3; ++i) camera_inside = camera_inside && c[i] > room.min[i] && c[i] < room.max[i];
    if (!camera_inside && scene.camera_position_given)
        warnings.push_back(file + "camera.position: outside the room (the view shows the walls from behind)");
    for (std::size_t s = 0; s < scene.spheres.size(); ++s) {
        const Sphere& sphere = scene.spheres[s];
        bool through = false;
        for (int i = 0; i < 3; ++i)
            through = through || sphere.center[i] - sphere.radius < room.min[i] ||
                      sphere.center[i] + sphere.radius > room.max[i];
        if (through)
            warnings.push_back(
                file + "spheres[" + std::to_string(s) +
                "]: not inside the room (it reaches through or lies beyond a wall; its reflection there is meaningless)");
    }
    return warnings;
}

bool policy_allows(const PathPolicy& policy, const std::filesystem::path& scene_file,
                   const std::filesystem::path& resolved) {
    namespace fs = std::filesystem;
    if (policy.allow_outside) return true;
    std::error_code error;
    const fs::path folder = fs::weakly_canonical(fs::absolute(scene_file).parent_path(), error);
    const fs::path data =
        policy.data_dir.empty() ? fs::path() : fs::weakly_canonical(fs::absolute(policy.data_dir), error);
    return inside(resolved, folder) || inside(resolved, data);
}

void confine_scene_paths(const Scene& scene, const PathPolicy& policy) {
    if (policy.allow_outside) return;
    namespace fs = std::filesystem;
    std::error_code error;
    auto check = [&](const fs::path& path, const std::string& field) {
        const fs::path resolved = fs::weakly_canonical(fs::absolute(path), error);
        if (!policy_allows(policy, scene.file, resolved))
            throw InputError(
                InputLocation(scene.file, 0, field),
                "a path outside the scene's folder and the database (glpreview --allow-paths-outside to allow it)");
    };
    const auto check_written = [&](const std::string& text, const std::string& field) {
        if (const fs::path written = text; looks_like_path(text))
            check(written.is_absolute() ? written : scene.file.parent_path() / written, field);
    };
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
        const Sphere& s = scene.spheres[i];
        const std::string field = "spheres[" + std::to_string(i) + "]";
        check_written(s.material, field + ".material");
        // A film's or coat's file (the key's text before its thickness).
        for (const auto& [key, text] : {std::pair{".film", &s.film}, std::pair{".coat", &s.coat}})
            if (!text->empty())
                check_written(std::string(trim(parse_layer_argument("--" + std::string(key + 1), *text).material)),
                              field + key);
    }
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
        const int line =
            1 + static_cast<int>(std::count(json_text.begin(), json_text.begin() + static_cast<long>(offset), '\n'));
        throw InputError(InputLocation(file, line, tracker.error_field), "number beyond the range of a double");
    } catch (const json::parse_error& e) {
        // nlohmann reports the byte offset; turn it into a line number.
        const auto offset = std::min<std::size_t>(e.byte, json_text.size());
        const int line =
            1 + static_cast<int>(std::count(json_text.begin(), json_text.begin() + static_cast<long>(offset), '\n'));
        std::string what = e.what();
        const auto colon = what.rfind(": ");
        throw InputError(InputLocation(file, line),
                         "invalid JSON: " +
                             scene_excerpt(colon == std::string::npos ? what : what.substr(colon + 2), 120));
    }
    Scene scene;
    scene.file = file;
    std::vector<const char*> top_keys{"image", "space", "camera", "spheres", "outputs"};
    for (const SceneKeys* effect : scene_key_readers())
        for (const char* key : effect->scene_keys()) top_keys.push_back(key);
    Reader top(root, "", file, top_keys);
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
    // The keys the registered effects read (the environment, ...), before the spheres.
    for (const SceneKeys* effect : scene_key_readers()) effect->read_scene(top, scene);
    if (!top.has("spheres")) top.fail("spheres", "missing (at least one sphere)");
    top.each("spheres", [&](const json& v, const std::string& path) {
        std::vector<const char*> keys{"center", "radius"};
        for (const SceneKeys* effect : scene_key_readers())
            for (const char* key : effect->sphere_keys()) keys.push_back(key);
        Reader r(v, path, file, keys);
        Sphere s;
        if (!r.has("center")) r.fail(r.field("center"), "missing");
        r.read("center", s.center);
        r.read("radius", s.radius, 1e-4, kSceneBig);
        for (const SceneKeys* effect : scene_key_readers()) effect->read_sphere(r, s, scene);
        if (scene.spheres.size() >= kMaxSpheres)
            top.fail("spheres", "at most " + std::to_string(kMaxSpheres) + " spheres");
        scene.spheres.push_back(s);
    });
    if (scene.spheres.empty()) top.fail("spheres", "at least one sphere");
    if (top.has("outputs")) {
        Reader r(top.at("outputs"), "outputs", file,
                 {"beauty", "reference", "difference", "metrics", "exr", "png", "localization", "labels", "rim",
                  "timing_frames", "reference_samples"});
        Outputs& o = scene.outputs;
        r.read("beauty", o.beauty);
        r.read("reference", o.reference);
        r.read("difference", o.difference);
        r.read("metrics", o.metrics);
        r.read("exr", o.exr);
        r.read("png", o.png);
        r.read("localization", o.localization);
        r.read("labels", o.labels);
        r.read("rim", o.rim);
        r.read("timing_frames", o.timing_frames, 5, 1000);
        r.read("reference_samples", o.reference_samples, 1, 65536);
        if (!o.exr && !o.png && (o.beauty || o.reference || o.difference))
            r.fail("outputs.exr", "images asked for but neither exr nor png");
        if (o.rim && !o.png) r.fail("outputs.rim", "rim.png is a PNG: needs outputs.png");
    }
    for (const SceneKeys* effect : scene_key_readers()) effect->check_scene(top, scene);
    for (std::string& w : placement_warnings(scene)) scene.warnings.push_back(std::move(w));
    return scene;
}

Scene load_scene(const std::filesystem::path& file) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(file, error))  // a FIFO or a device would hang or never end
        throw InputError(InputLocation(file),
                         std::filesystem::exists(file, error) ? "not a regular file" : "cannot read the scene file");
    if (std::filesystem::file_size(file, error) > kMaxSceneBytes)
        throw InputError(InputLocation(file), "larger than 16 MiB: not a scene");
    std::ifstream in(file, std::ios::binary);
    if (!in) throw InputError(InputLocation(file), "cannot read the scene file");
    std::stringstream text;
    text << in.rdbuf();
    return parse_scene(text.str(), file);
}

}  // namespace metalfit::glpreview
