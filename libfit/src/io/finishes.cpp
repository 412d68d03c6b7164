#include "libfit/io/finishes.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <memory>

#include "libfit/base/errors.hpp"
#include "libfit/base/input_file.hpp"
#include "libfit/base/text.hpp"
#include "libfit/io/layer_stack.hpp"

#include "io/json_fields.hpp"

namespace metalfit {
namespace {

std::vector<std::string> text_list(const nlohmann::json& j, const char* key, const std::filesystem::path& file,
                                   const std::string& where) {
    std::vector<std::string> out;
    const auto it = j.find(key);
    if (it == j.end()) return out;
    if (!it->is_array()) throw InputError({file, 0, where + "." + key}, "expected a list of strings");
    for (const auto& v : *it) {
        if (!v.is_string()) throw InputError({file, 0, where + "." + key}, "expected a list of strings");
        out.push_back(v.get<std::string>());
    }
    return out;
}

}  // namespace

FinishCatalog FinishCatalog::load(const std::filesystem::path& data_dir) {
    FinishCatalog catalog;
    catalog.file_ = data_dir / "finishes.json";
    const auto& file = catalog.file_;
    std::error_code missing;
    if (!std::filesystem::exists(file, missing)) return catalog;  // a database of metals alone
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(read_input_file(file));
    } catch (const nlohmann::json::exception& e) {
        throw InputError({file}, std::string("invalid JSON: ") + e.what());
    }
    const auto finishes = j.find("finishes");
    if (finishes == j.end() || !finishes->is_array()) throw InputError({file, 0, "finishes"}, "expected a list");
    for (std::size_t i = 0; i < finishes->size(); ++i) {
        const auto& f = (*finishes)[i];
        const std::string where = "finishes[" + std::to_string(i) + "]";
        if (!f.is_object()) throw InputError({file, 0, where}, "expected an object");
        Finish finish;
        finish.id = io_detail::string_field(f, "id", file, where, true);
        finish.name = io_detail::string_field(f, "name", file, where, true);
        finish.aliases = text_list(f, "aliases", file, where);
        finish.metal = io_detail::string_field(f, "metal", file, where, true);
        finish.film = io_detail::string_field(f, "film", file, where, false);
        finish.coat = io_detail::string_field(f, "coat", file, where, false);
        finish.note = io_detail::string_field(f, "note", file, where, false);
        finish.sources = text_list(f, "sources", file, where);
        if (finish.film.empty() && finish.coat.empty())
            throw InputError({file, 0, where}, "a finish needs a film or a coat (else it is the bare metal)");
        catalog.entries_.push_back(std::move(finish));
    }
    return catalog;
}

const Finish* FinishCatalog::find(std::string_view name) const {
    for (const Finish& f : entries_) {
        if (equal_ignoring_case(name, f.id) || equal_ignoring_case(name, f.name)) return &f;
        for (const std::string& alias : f.aliases)
            if (equal_ignoring_case(name, alias)) return &f;
    }
    return nullptr;
}

Material load_finish(const Finish& finish, const FinishCatalog& finishes, const Catalog& metals,
                     const FilmCatalog& films, std::string_view source) {
    std::size_t index = 0;
    while (index < finishes.entries().size() && &finishes.entries()[index] != &finish) ++index;
    const std::string where = "finishes[" + std::to_string(index) + "]";
    if (metals.find(finish.metal) == nullptr)
        throw InputError({finishes.file(), 0, where + ".metal"}, "unknown catalog material '" + finish.metal + "'");
    Material m = load_material(metals, finish.metal, source);
    auto stack = std::make_shared<LayerStack>();
    // The layers exactly as --film and --coat would load them; their errors name the finish's field.
    const auto layer = [&](const char* field, const auto& load) {
        try {
            load();
        } catch (const InputError& e) {
            throw InputError({finishes.file(), 0, where + "." + field}, e.what());
        } catch (const UsageError& e) {
            throw InputError({finishes.file(), 0, where + "." + field}, e.what());
        }
    };
    if (!finish.film.empty()) layer("film", [&] { stack->film = load_film(films, finish.film); });
    if (!finish.coat.empty()) layer("coat", [&] { stack->coat = load_coat(films, finish.coat); });
    stack->finish = FinishName{finish.id, finish.name};
    m.id = finish.id;
    m.layers = std::move(stack);
    return m;
}

std::optional<Material> load_finish_named(const Catalog& metals, std::string_view name, std::string_view source) {
    if (looks_like_path(name) || metals.find(std::string(name)) != nullptr) return std::nullopt;
    const FinishCatalog finishes = FinishCatalog::load(metals.data_dir());
    const Finish* finish = finishes.find(name);
    if (!finish) return std::nullopt;
    return load_finish(*finish, finishes, metals, FilmCatalog::load(metals.data_dir()), source);
}

}  // namespace metalfit
