// An export written material by material (libfit/export/export_stream.hpp): each material's own files staged as its
// fit arrives, the shared ones (record, C++ index, model files) built as they go and written at the end.
#include "libfit/export/export_stream.hpp"

#include <cstdio>
#include <fstream>
#include <map>
#include <optional>
#include <stdexcept>
#include <unordered_set>

#include "export/export_formats.hpp"
#include "export/format_registry.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/base/json_text.hpp"
#include "libfit/base/staged_folder.hpp"

namespace metalfit {
namespace {

using Json = nlohmann::ordered_json;

constexpr int kIndent = 2;                                          // as export_files dumps the record
constexpr std::string_view kRecordPath = "metalfit_export.json";    // the json format's one file
constexpr std::string_view kMaterialsKey = "\n  \"materials\": {";  // the record's top-level member

// Lines kept on disk until the end (an anonymous temporary, gone with the process): what a stream would otherwise
// hold for every material.
class SpillFile {
public:
    SpillFile() : file_(std::tmpfile()) {
        if (!file_) throw std::runtime_error("export: cannot make a temporary file");
    }
    ~SpillFile() { std::fclose(file_); }
    SpillFile(const SpillFile&) = delete;
    SpillFile& operator=(const SpillFile&) = delete;

    void line(std::string_view text) {
        if (std::fwrite(text.data(), 1, text.size(), file_) != text.size() || std::fputc('\n', file_) == EOF)
            throw std::runtime_error("export: cannot write a temporary file");
        ++lines_;
    }
    std::size_t lines() const { return lines_; }
    // Every line in order, without its newline.
    void each(const std::function<void(const std::string&)>& take) {
        std::rewind(file_);
        std::string line;
        for (int c; (c = std::fgetc(file_)) != EOF;)
            if (c == '\n') {
                take(line);
                line.clear();
            } else {
                line += static_cast<char>(c);
            }
        if (std::ferror(file_)) throw std::runtime_error("export: cannot read a temporary file");
    }

private:
    std::FILE* file_;
    std::size_t lines_ = 0;
};

// The shared model files of the shader formats (glsl/metalfit_models.glsl, …): one per format, the same stem.
bool is_models_file(const std::filesystem::path& path) { return path.stem() == "metalfit_models"; }

}  // namespace

struct ExportStream::State {
    std::filesystem::path dir;
    FitRecordContext context;
    ExportRequest request;
    std::string materialx_space;
    StagedFolder folder;
    // The record, written piece by piece into the staging: what comes before the materials, and after them.
    std::ofstream record;
    std::optional<std::string> record_head, record_tail;
    std::unordered_set<std::string> record_ids;
    // Each material's file stem without its model: two materials with one stem would write the same files.
    std::unordered_set<std::string> stems;
    SpillFile cpp_includes, cpp_rows;                      // the C++ index's two lists, one line per entry
    std::map<std::filesystem::path, std::string> shared;   // the model files, merged as they come
    std::vector<std::unique_ptr<SpillFile>> out_of_range;  // stderr's lines, per format of the request
    std::size_t materials = 0;
    bool finished = false;

    State(const std::filesystem::path& d, FitRecordContext c, ExportRequest r, std::string space)
        : dir(d),
          context(std::move(c)),
          request(std::move(r)),
          materialx_space(std::move(space)),
          folder(d, StagedFolder::Existing::keep_other_files,
                 [d](const std::filesystem::path& relative, const std::string& existing, const std::string& mine) {
                     return detail::merge_index(d, relative, existing, mine);
                 }),
          out_of_range(request.formats.size()) {
        for (auto& lines : out_of_range) lines = std::make_unique<SpillFile>();
    }

    void write_record(std::string_view text) {
        if (!record.is_open()) record.open(folder.file(std::string(kRecordPath)), std::ios::binary);
        record.write(text.data(), static_cast<std::streamsize>(text.size()));
        if (!record) throw InputError({dir / kRecordPath}, "cannot write");
    }

    // One material's record: the head written before the first, its entry unless its id was written already.
    void add_record(const std::string& contents) {
        Json j = Json::parse(contents);
        Json& materials = j.at("materials");
        if (materials.size() != 1) throw std::logic_error("export stream: a record of one material expected");
        const std::string id = materials.begin().key();
        const Json entry = materials.begin().value();
        materials = Json::object();
        const std::string whole = j.dump(kIndent) + "\n";
        const std::size_t at = whole.find(std::string(kMaterialsKey) + "}");
        if (at == std::string::npos) throw std::logic_error("export stream: the record has no materials member");
        const std::size_t cut = at + kMaterialsKey.size();
        std::string head = whole.substr(0, cut), tail = whole.substr(cut);
        if (!record_head) {
            write_record(head);
            record_head = std::move(head);
            record_tail = std::move(tail);
        } else if (head != *record_head || tail != *record_tail) {
            throw std::logic_error("export stream: the records of two materials differ outside their materials");
        }
        if (!record_ids.insert(id).second) return;  // the record's "materials" keeps one entry per id
        const std::string margin(2 * kIndent, ' ');
        write_record((record_ids.size() == 1 ? "\n" : ",\n") + margin + Json(id).dump() + ": " +
                     indented_json(entry.dump(kIndent), 2, kIndent));
    }

    void add(const std::vector<MaterialFit>& fits) {
        const std::vector<std::vector<ExportFile>> by_format =
            detail::export_files_by_format(fits, context, request, materialx_space);
        const std::string cpp_index_path = detail::cpp_index_path(request.id_prefix);
        bool stem_checked = fits.empty();
        for (std::size_t k = 0; k < by_format.size(); ++k)
            for (const ExportFile& f : by_format[k]) {
                for (const std::string& line : out_of_range_lines({f})) out_of_range[k]->line(line);
                if (f.path == kRecordPath) {
                    if (fits.empty())
                        folder.write(f.path, f.contents);
                    else
                        add_record(f.contents);
                } else if (f.path == cpp_index_path) {
                    // One material's entries: never one already listed (its files would be another's, refused).
                    for (const detail::CppIndexEntry& e : detail::parse_cpp_materials_index(f.contents)) {
                        cpp_includes.line(e.include);
                        cpp_rows.line(e.row);
                    }
                } else if (is_models_file(f.path)) {
                    const auto there = shared.find(f.path);
                    if (there == shared.end()) {
                        shared.emplace(f.path, f.contents);
                    } else if (there->second != f.contents) {
                        const auto merge = detail::format_entry(request.formats[k]).merge_index;
                        std::optional<std::string> merged;
                        if (merge) merged = merge(f.path.generic_string(), there->second, f.contents);
                        there->second = merged ? *std::move(merged) : f.contents;
                    }
                } else {
                    // The first file of the material that is its own: its stem is new, or another material's
                    // files are these (export_files names the same first file).
                    if (!stem_checked &&
                        !stems.insert(detail::file_stem(request.id_prefix, fits.front().material.id, "")).second)
                        throw UsageError("export: two materials would write the same file " + f.path.string() +
                                         " (their ids differ only in punctuation or case)");
                    stem_checked = true;
                    folder.write(f.path, f.contents);
                }
            }
    }
};

ExportStream::ExportStream(const std::filesystem::path& dir, FitRecordContext context, ExportRequest request,
                           std::string materialx_space)
    : state_(std::make_unique<State>(dir, std::move(context), std::move(request), std::move(materialx_space))) {
    require_export_space(state_->request, state_->context.space, state_->materialx_space);
}

ExportStream::~ExportStream() = default;

void ExportStream::add(const MaterialFit& fit) {
    if (state_->finished) throw std::logic_error("ExportStream: material added after finish");
    state_->add({fit});
    ++state_->materials;
}

void ExportStream::finish(const std::function<void(const std::string&)>& out_of_range_line) {
    State& s = *state_;
    if (s.finished) throw std::logic_error("ExportStream: finished twice");
    s.finished = true;
    if (s.materials == 0) s.add({});  // the files of an export of nothing, as export_files writes them
    if (s.record_tail) {
        s.write_record("\n" + std::string(kIndent, ' ') + *s.record_tail);
        s.record.close();
        if (!s.record) throw InputError({s.dir / kRecordPath}, "cannot write");
    }
    if (s.cpp_rows.lines() > 0) {  // cpp_materials_index's text, its lists copied from the spill files
        const std::string relative = detail::cpp_index_path(s.request.id_prefix);
        std::ofstream index(s.folder.file(relative), std::ios::binary);
        const auto put = [&](const std::string& text) {
            index << text;
            if (!index) throw InputError({s.dir / relative}, "cannot write");
        };
        put(detail::cpp_materials_index_head());
        s.cpp_includes.each([&](const std::string& line) { put(line + "\n"); });
        put(detail::cpp_materials_index_middle(s.request.id_prefix, s.cpp_rows.lines()));
        s.cpp_rows.each([&](const std::string& line) { put(line + "\n"); });
        put(detail::cpp_materials_index_tail(s.request.id_prefix));
        index.close();
        if (!index) throw InputError({s.dir / relative}, "cannot write");
    }
    for (const auto& [path, contents] : s.shared) s.folder.write(path, contents);
    s.folder.commit();
    for (auto& lines : s.out_of_range) lines->each(out_of_range_line);
}

void fit_materials_for_export(const std::vector<std::function<Material()>>& loaders, const BatchColour& colour,
                              const MaterialFitRequest& request, const ExportRequest& export_request, int jobs,
                              const BatchSink& sink, const BatchProgress& progress) {
    const bool bare_metal = needs_bare_metal_fits(export_request);
    fit_materials_in_order(
        loaders, colour,
        [&](const Material& material, const ColorSpaceConverter& converter) {
            MaterialFit fit = fit_material(material, colour.colorimetry, converter, request);
            if (bare_metal && material.layers && !material.layers->empty()) {
                Material bare = fit.material;  // as attach_bare_metal_fits: the fitted material, layers removed
                bare.layers = nullptr;
                fit.bare_metal =
                    std::make_shared<const MaterialFit>(fit_material(bare, colour.colorimetry, converter, request));
            }
            return fit;
        },
        jobs, sink, progress);
}

}  // namespace metalfit
