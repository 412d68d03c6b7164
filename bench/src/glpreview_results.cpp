#include "metalfit_bench/glpreview_results.hpp"

#include <unistd.h>

#include <stdexcept>

#include "metalfit_bench/subprocess.hpp"

namespace metalfit::bench {
namespace {

using nlohmann::json;

const json& field(const json& j, const std::string& path, const char* key) {
    if (!j.is_object()) throw std::runtime_error(path + ": expected an object");
    const auto it = j.find(key);
    if (it == j.end()) throw std::runtime_error((path.empty() ? "" : path + ".") + key + ": missing");
    return *it;
}

std::string join(const std::string& path, const char* key) { return (path.empty() ? "" : path + ".") + key; }

std::string string_field(const json& j, const std::string& path, const char* key) {
    const json& v = field(j, path, key);
    if (!v.is_string()) throw std::runtime_error(join(path, key) + ": expected a string");
    return v.get<std::string>();
}

double number_field(const json& j, const std::string& path, const char* key) {
    const json& v = field(j, path, key);
    if (!v.is_number()) throw std::runtime_error(join(path, key) + ": expected a number");
    return v.get<double>();
}

int int_field(const json& j, const std::string& path, const char* key) {
    const json& v = field(j, path, key);
    if (!v.is_number_integer()) throw std::runtime_error(join(path, key) + ": expected an integer");
    return v.get<int>();
}

const json& array_field(const json& j, const std::string& path, const char* key) {
    const json& v = field(j, path, key);
    if (!v.is_array()) throw std::runtime_error(join(path, key) + ": expected an array");
    return v;
}

void size_field(const json& j, int& width, int& height) {
    const json& s = array_field(j, "", "size");
    if (s.size() != 2 || !s[0].is_number_integer() || !s[1].is_number_integer())
        throw std::runtime_error("size: expected [width, height]");
    width = s[0].get<int>();
    height = s[1].get<int>();
}

template <class T, class Parse>
GpuSection<T> run(const std::filesystem::path& glpreview, const char* mode, bool quick, Parse parse) {
    GpuSection<T> section;
    if (glpreview.empty() || access(glpreview.c_str(), X_OK) != 0) {
        section.skipped =
            "no glpreview executable at " + (glpreview.empty() ? std::string("(none)") : glpreview.string());
        return section;
    }
    std::vector<std::string> args{mode};
    if (quick) args.emplace_back("--quick");
    args.emplace_back("--json");
    const ProcessResult r = run_process(glpreview, args);
    if (r.exit_code != 0) {
        const std::string why = last_line(r.err);
        section.skipped = "glpreview " + std::string(mode) + " failed (exit " + std::to_string(r.exit_code) + ")" +
                          (why.empty() ? "" : ": " + why);
        return section;
    }
    try {
        section.value = parse(json::parse(r.out));
    } catch (const std::exception& e) {
        section.skipped = "glpreview " + std::string(mode) + " printed unusable JSON: " + last_line(e.what());
    }
    return section;
}

}  // namespace

const ShaderTiming* ShaderBench::find(std::string_view model) const {
    for (const ShaderTiming& t : models)
        if (t.model == model) return &t;
    return nullptr;
}

ShaderBench parse_shader_bench(const json& j) {
    ShaderBench b;
    b.renderer = string_field(j, "", "renderer");
    size_field(j, b.width, b.height);
    b.frames = int_field(j, "", "frames");
    if (j.contains("evaluations_per_pixel")) b.evaluations_per_pixel = int_field(j, "", "evaluations_per_pixel");
    if (j.contains("clock")) b.clock = string_field(j, "", "clock");
    const json& models = array_field(j, "", "models");
    for (std::size_t i = 0; i < models.size(); ++i) {
        const std::string path = "models[" + std::to_string(i) + "]";
        ShaderTiming t{string_field(models[i], path, "model"), number_field(models[i], path, "ms_per_frame"),
                       number_field(models[i], path, "ratio_to_conductor_rgb"), std::nullopt, std::nullopt};
        if (models[i].contains("ratio_noise")) t.ratio_noise = number_field(models[i], path, "ratio_noise");
        if (models[i].contains("ratio_quartiles")) {
            const json& q = models[i]["ratio_quartiles"];
            if (!q.is_array() || q.size() != 2 || !q[0].is_number() || !q[1].is_number())
                throw std::runtime_error(path + ".ratio_quartiles: expected [first, third]");
            t.ratio_quartiles = std::array<double, 2>{q[0].get<double>(), q[1].get<double>()};
        }
        b.models.push_back(std::move(t));
    }
    return b;
}

LocalizationBench parse_localization_bench(const json& j) {
    LocalizationBench b;
    b.renderer = string_field(j, "", "renderer");
    size_field(j, b.width, b.height);
    const json& rooms = array_field(j, "", "rooms");
    for (std::size_t r = 0; r < rooms.size(); ++r) {
        const std::string room_path = "rooms[" + std::to_string(r) + "]";
        LocalizationRoom room{string_field(rooms[r], room_path, "room"), {}};
        const json& rows = array_field(rooms[r], room_path, "rows");
        for (std::size_t i = 0; i < rows.size(); ++i) {
            const std::string path = room_path + ".rows[" + std::to_string(i) + "]";
            LocalizationRow row;
            row.mode = string_field(rows[i], path, "mode");
            const json& strategy = field(rows[i], path, "strategy");
            if (strategy.is_string())
                row.strategy = strategy.get<std::string>();
            else if (!strategy.is_null())
                throw std::runtime_error(path + ".strategy: expected a string or null");
            row.iterations = int_field(rows[i], path, "iterations");
            row.search_steps = int_field(rows[i], path, "search_steps");
            const json& tolerance = field(rows[i], path, "tolerance");
            if (tolerance.is_number())
                row.tolerance = tolerance.get<double>();
            else if (!tolerance.is_null())
                throw std::runtime_error(path + ".tolerance: expected a number or null");
            row.mean_iterations = number_field(rows[i], path, "mean_iterations");
            row.ms_per_frame = number_field(rows[i], path, "ms_per_frame");
            row.ratio_to_classic = number_field(rows[i], path, "ratio_to_classic");
            row.ratio_noise = number_field(rows[i], path, "ratio_noise");
            row.rmse = number_field(rows[i], path, "rmse");
            row.mean_abs = number_field(rows[i], path, "mean_abs");
            room.rows.push_back(std::move(row));
        }
        b.rooms.push_back(std::move(room));
    }
    return b;
}

json to_json(const ShaderBench& b) {
    json models = json::array();
    for (const ShaderTiming& t : b.models) {
        json m = {
            {"model", t.model}, {"ms_per_frame", t.ms_per_frame}, {"ratio_to_conductor_rgb", t.ratio_to_conductor_rgb}};
        if (t.ratio_noise) m["ratio_noise"] = *t.ratio_noise;
        if (t.ratio_quartiles) m["ratio_quartiles"] = *t.ratio_quartiles;
        models.push_back(std::move(m));
    }
    json j = {{"renderer", b.renderer},
              {"size", {b.width, b.height}},
              {"frames", b.frames},
              {"evaluations_per_pixel", b.evaluations_per_pixel},
              {"models", models}};
    if (!b.clock.empty()) j["clock"] = b.clock;
    return j;
}

json to_json(const LocalizationBench& b) {
    json rooms = json::array();
    for (const LocalizationRoom& room : b.rooms) {
        json rows = json::array();
        for (const LocalizationRow& r : room.rows)
            rows.push_back({{"mode", r.mode},
                            {"strategy", r.strategy ? json(*r.strategy) : json(nullptr)},
                            {"iterations", r.iterations},
                            {"search_steps", r.search_steps},
                            {"tolerance", r.tolerance ? json(*r.tolerance) : json(nullptr)},
                            {"mean_iterations", r.mean_iterations},
                            {"ms_per_frame", r.ms_per_frame},
                            {"ratio_to_classic", r.ratio_to_classic},
                            {"ratio_noise", r.ratio_noise},
                            {"rmse", r.rmse},
                            {"mean_abs", r.mean_abs}});
        rooms.push_back({{"room", room.room}, {"rows", rows}});
    }
    return {{"renderer", b.renderer}, {"size", {b.width, b.height}}, {"rooms", rooms}};
}

GpuSection<ShaderBench> run_shader_bench(const std::filesystem::path& glpreview, bool quick) {
    return run<ShaderBench>(glpreview, "--bench-shaders", quick, parse_shader_bench);
}

GpuSection<LocalizationBench> run_localization_bench(const std::filesystem::path& glpreview, bool quick) {
    return run<LocalizationBench>(glpreview, "--bench-localization", quick, parse_localization_bench);
}

}  // namespace metalfit::bench
