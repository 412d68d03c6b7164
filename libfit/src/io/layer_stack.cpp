#include "libfit/io/layer_stack.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "libfit/base/record_path.hpp"

namespace metalfit {
namespace {

std::string number(double v) {
    std::ostringstream s;
    s.precision(6);
    s << v;
    return s.str();
}

// "TiO2 (Siefke)", "n = 1.5", "my-oxide".
std::string layer_material_name(const LayerMaterial& m) {
    if (m.source == "constant") return m.name;
    return m.id + (m.source.empty() || m.source == m.id ? "" : " (" + m.source + ")");
}

}  // namespace

std::string describe(const ThinFilm& film) {
    return layer_material_name(film.material) + " film of " + number(film.thickness_nm) + " nm";
}

std::string describe(const ClearCoat& coat) {
    std::string text = "coat " + layer_material_name(coat.material);
    if (coat.thickness_nm) text += " " + number(*coat.thickness_nm) + " nm thick";
    return text;
}

std::string describe_stack(const Material& metal) {
    if (!metal.layers || metal.layers->empty()) return metal.name;
    const LayerStack& s = *metal.layers;
    std::string text = (s.finish ? s.finish->name + ": " : std::string()) + metal.name;
    if (s.coat) text += " under a " + describe(*s.coat);
    if (s.film) text += std::string(s.coat ? " over" : " under") + " a " + describe(*s.film);
    return text;
}

std::string short_stack_name(const Material& metal) {
    if (!metal.layers || metal.layers->empty()) return metal.name;
    const LayerStack& s = *metal.layers;
    if (s.finish) return s.finish->name;
    const auto short_name = [](const LayerMaterial& m) { return m.source == "constant" ? m.name : m.id; };
    std::string text = metal.name;
    if (s.film) text += " + " + short_name(s.film->material) + " " + number(s.film->thickness_nm) + " nm";
    if (s.coat) text += " + coat " + short_name(s.coat->material);
    return text;
}

LayerIndexSummary layer_index_summary(const LayerMaterial& material) {
    const auto n = [&](double nm) { return material.index.n(nm, Interpolation::linear, OutOfRange::clamp); };
    const auto k = [&](double nm) { return material.index.k(nm, Interpolation::linear, OutOfRange::clamp); };
    LayerIndexSummary s;
    s.n = n(kLayerIndexWavelengthNm);
    s.k = k(kLayerIndexWavelengthNm);
    s.n_min = s.n_max = s.n;
    s.k_max = s.k;
    for (int nm = kLayerVisibleFirstNm; nm <= kLayerVisibleLastNm; ++nm) {
        const double nv = n(nm), kv = k(nm);
        s.n_min = std::min(s.n_min, nv);
        s.n_max = std::max(s.n_max, nv);
        s.k_max = std::max(s.k_max, kv);
    }
    return s;
}

std::string describe_layer_index(const LayerIndexSummary& s) {
    std::string text = "n(550 nm) = " + number(s.n) + ", k(550 nm) = " + number(s.k) + "; over 380-780 nm n " +
                       number(s.n_min) + "-" + number(s.n_max) + ", k up to " + number(s.k_max);
    return text;
}

namespace {

nlohmann::ordered_json layer_material_record(const LayerMaterial& m, const std::filesystem::path& data_dir) {
    const LayerIndexSummary index = layer_index_summary(m);
    return {{"material", m.id},
            {"name", m.name},
            {"source", m.source},
            {"file", record_path(m.provenance.file, data_dir)},
            {"sha256", m.provenance.sha256},
            {"reference", m.provenance.references},
            {"data_type", m.provenance.data_type},
            {"index_at_nm", kLayerIndexWavelengthNm},
            {"n", index.n},
            {"k", index.k},
            {"n_visible", {index.n_min, index.n_max}},
            {"k_visible_max", index.k_max}};
}

}  // namespace

nlohmann::ordered_json stack_record(const Material& metal, const std::filesystem::path& data_dir) {
    if (!metal.layers || metal.layers->empty()) return nullptr;
    const LayerStack& s = *metal.layers;
    nlohmann::ordered_json j = {{"description", describe_stack(metal)}};
    if (s.coat) {
        nlohmann::ordered_json coat = layer_material_record(s.coat->material, data_dir);
        coat["thickness_nm"] =
            s.coat->thickness_nm ? nlohmann::ordered_json(*s.coat->thickness_nm) : nlohmann::ordered_json(nullptr);
        j["coat"] = std::move(coat);
    }
    if (s.film) {
        nlohmann::ordered_json film = layer_material_record(s.film->material, data_dir);
        film["thickness_nm"] = s.film->thickness_nm;
        j["film"] = std::move(film);
    }
    if (s.finish) j["finish"] = {{"id", s.finish->id}, {"name", s.finish->name}};
    return j;
}

std::string film_thickness_problem(double d) {
    if (!std::isfinite(d)) return "thickness " + number(d) + " is not a finite number";
    if (d < 0) return "thickness " + number(d) + " nm is negative";
    if (d > kMaxFilmThicknessNm)
        return "thickness " + number(d) +
               " nm is beyond 2 µm, where a film is no longer coherent (its interference "
               "colours average out); give a thick layer as a coat (--coat)";
    return {};
}

std::string coat_thickness_problem(double d) {
    if (!std::isfinite(d)) return "thickness " + number(d) + " is not a finite number";
    if (d < 0) return "thickness " + number(d) + " nm is negative";
    return {};
}

}  // namespace metalfit
