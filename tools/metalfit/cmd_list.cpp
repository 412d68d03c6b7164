// metalfit list: the built-in materials with their sources and wavelength coverage.
#include <nlohmann/json.hpp>

#include <iomanip>
#include <sstream>

#include "commands.hpp"
#include "libfit/io/catalog.hpp"
#include "libfit/io/finishes.hpp"
#include "list_record.hpp"

namespace metalfit::cli {
namespace {

struct ListOptions {
    bool json = false;
    std::filesystem::path output;
};

std::string table(const nlohmann::json& rows) {
    std::ostringstream out;
    out << std::left << std::setw(16) << "id" << std::setw(18) << "name" << std::setw(22) << "source" << std::setw(18)
        << "range (nm)" << std::setw(8) << "points"
        << "alternates\n";
    for (const auto& row : rows) {
        std::ostringstream range;
        range << std::fixed << std::setprecision(0) << row["range_nm"][0].get<double>() << "–"
              << row["range_nm"][1].get<double>();
        std::string alternates;
        for (const auto& a : row["alternates"]) alternates += (alternates.empty() ? "" : ", ") + a.get<std::string>();
        out << std::setw(16) << row["id"].get<std::string>() << std::setw(18) << row["name"].get<std::string>()
            << std::setw(22) << row["source"].get<std::string>() << std::setw(20) << range.str() << std::setw(8)
            << row["points_360_830"].get<std::size_t>() << alternates << "\n";
    }
    out << "points: samples inside 360–830 nm\n";
    bool heading = false;
    for (const auto& row : rows) {
        const std::string note = row["note"].get<std::string>();
        if (note.empty()) continue;
        if (!heading) out << "\ncaveats (the primary source's catalog note):\n";
        heading = true;
        out << "  " << std::setw(26) << row["id"].get<std::string>() << note << "\n";
    }
    return out.str();
}

}  // namespace

std::function<void()> add_list_command(CLI::App& app, const GlobalOptions& global) {
    auto options = std::make_shared<ListOptions>();
    app.add_flag("--json", options->json, "Print JSON");
    app.add_option("-o,--output", options->output, "Write to this file instead of stdout (- for stdout)");
    return [options, &global] {
        const Catalog catalog = Catalog::load(global.data_dir);
        const nlohmann::json rows = list_record(catalog);
        std::string text;
        if (!options->json) {
            text = table(rows);
            // The named finishes, usable as materials (the JSON stays the list of catalog materials).
            const FinishCatalog finishes = FinishCatalog::load(global.data_dir);
            if (!finishes.entries().empty()) text += "\nnamed finishes (data/finishes.json; docs/colour.md):\n";
            for (const Finish& f : finishes.entries())
                text += "  " + f.id + std::string(f.id.size() < 24 ? 24 - f.id.size() : 1, ' ') + f.metal +
                        (f.coat.empty() ? "" : " --coat " + f.coat) + (f.film.empty() ? "" : " --film " + f.film) +
                        "\n";
        }
        emit(options->json ? rows.dump(2) + "\n" : text, options->output);
    };
}

}  // namespace metalfit::cli
