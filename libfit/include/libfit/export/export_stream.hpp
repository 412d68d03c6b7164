// An export written material by material (`metalfit export --all`): each material's files go into the staging
// folder as its fit arrives and the fit is let go; the files every material shares (the record
// metalfit_export.json, the C++ index, the model files) are built as they go and written at the end. The folder is
// byte for byte what export_files + write_export write for the same fits, and is switched in as one unit the same
// way (StagedFolder, merged with an earlier export there); memory does not grow with the number of materials
// beyond its id and file stem per material (docs/decisions.md, "Streamed export and report").
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "libfit/export/export.hpp"

namespace metalfit {

class ExportStream {
public:
    // Nothing is written before finish(); a stream destroyed unfinished leaves `dir` as it was. The staging folder
    // is made here (InputError naming `dir` when it cannot be).
    ExportStream(const std::filesystem::path& dir, FitRecordContext context, ExportRequest request,
                 std::string materialx_space);
    ~ExportStream();
    ExportStream(const ExportStream&) = delete;
    ExportStream& operator=(const ExportStream&) = delete;

    // The next material, in the order of the export (a layered material with its bare_metal attached where
    // needs_bare_metal_fits). UsageError as export_files when it would write a file another material writes.
    void add(const MaterialFit& fit);
    // Writes the shared files and switches the folder in; then hands on out_of_range_lines of every file, in the
    // order export_files lists them (kept on disk meanwhile: a line per colour outside [0, 1] of every file).
    void finish(const std::function<void(const std::string&)>& out_of_range_line);

private:
    struct State;
    std::unique_ptr<State> state_;
};

// fit_materials_in_order for an export: where the request needs the bare metal of layered materials
// (needs_bare_metal_fits), each material is fitted twice on the threads, as it is and without its layers, and the
// sink gets it with `bare_metal` attached (attach_bare_metal_fits's result, without holding every fit).
void fit_materials_for_export(const std::vector<std::function<Material()>>& loaders, const BatchColour& colour,
                              const MaterialFitRequest& request, const ExportRequest& export_request, int jobs,
                              const BatchSink& sink, const BatchProgress& progress = {});

}  // namespace metalfit
