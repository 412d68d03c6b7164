// metalfit models: the Fresnel models, their parameters and bounds, and their GLSL (the single definitions).
#include <nlohmann/json.hpp>

#include <cstdio>
#include <sstream>

#include "commands.hpp"
#include "libfit/base/number_text.hpp"
#include "libfit/base/version.hpp"
#include "libfit/models/model.hpp"

namespace metalfit::cli {
namespace {

struct ModelsOptions {
    std::string models = "all";
    bool json = false;
    bool glsl = false;
    std::filesystem::path output;
};

std::string number(double v) { return significant_text(v, 6); }

std::string signature(const Model& m) {
    std::string s = "vec3 " + std::string(m.glsl_function()) + "(";
    for (const Parameter& p : m.parameters()) s += "vec3 " + std::string(p.name) + ", ";
    return s + "float mu)";
}

void run_models(const ModelsOptions& o) {
    const std::vector<const Model*> models = parse_model_list(o.models);
    if (o.glsl) {
        emit("// metalfit " METALFIT_VERSION
             " Fresnel models (libfit/models): F(mu), mu = cos(theta), per RGB channel.\n" +
                 glsl_library(models),
             o.output);
        return;
    }
    if (o.json) {
        nlohmann::ordered_json j = nlohmann::ordered_json::array();
        for (const Model* m : models) {
            nlohmann::ordered_json params = nlohmann::ordered_json::array();
            for (const Parameter& p : m->parameters())
                params.push_back({{"name", p.name}, {"lower", p.lower}, {"upper", p.upper}, {"meaning", p.meaning}});
            j.push_back({{"id", m->id()}, {"title", m->title()}, {"parameters", params}, {"glsl", signature(*m)}});
        }
        emit(j.dump(2) + "\n", o.output);
        return;
    }
    std::ostringstream s;
    for (const Model* m : models) {
        s << m->id() << ": " << m->title() << "\n  " << signature(*m) << "\n";
        for (const Parameter& p : m->parameters())
            s << "  " << p.name << " in [" << number(p.lower) << ", " << number(p.upper) << "]: " << p.meaning << "\n";
    }
    emit(s.str(), o.output);
}

}  // namespace

std::function<void()> add_models_command(CLI::App& app, const GlobalOptions&) {
    auto o = std::make_shared<ModelsOptions>();
    app.add_option("--model", o->models, "Models, comma-separated, or all: " + model_ids());
    CLI::Option* json = app.add_flag("--json", o->json, "Print a JSON array");
    app.add_flag("--glsl", o->glsl, "Print the GLSL functions of the models (each shared function once)")
        ->excludes(json);
    app.add_option("-o,--output", o->output, "Write to this file instead of stdout (- for stdout)");
    return [o] { run_models(*o); };
}

}  // namespace metalfit::cli
