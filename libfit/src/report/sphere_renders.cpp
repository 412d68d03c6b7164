// The report's sphere renders: glpreview --sheet --sheet-rows run as a program (posix_spawn), its sheet.json read
// back and its row images left in a temporary folder until the report copies them.
#include "libfit/report/sphere_renders.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>

#include <nlohmann/json.hpp>

#include "base/exclusive_file.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/base/text.hpp"

extern char** environ;

namespace metalfit {
namespace {

namespace fs = std::filesystem;

std::string read_bytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string last_line(const std::string& text) {
    std::istringstream lines(text);
    std::string line, last;
    while (std::getline(lines, line))
        if (!line.empty()) last = line;
    return last;
}

}  // namespace

// glpreview's scratch folder under $TMPDIR, named and locked as the writers' staging folders are
// (".metalfit-renders.metalfit-staging.<pid>.<random>"), so that one a killed report left is removed by the next.
class RenderScratchFolder {
public:
    fs::path path;
    int fd = -1;
    RenderScratchFolder() {
        const fs::path beside = fs::temp_directory_path() / "metalfit-renders";
        int error = 0;
        const std::optional<fs::path> made = detail::make_staging_folder_beside(beside, error);
        if (!made) throw std::runtime_error("cannot make a temporary folder in " + beside.parent_path().string());
        path = *made;
        fd = detail::lock_staging_folder(path);
    }
    ~RenderScratchFolder() {
        std::error_code ec;
        fs::remove_all(path, ec);
        if (fd >= 0) ::close(fd);
    }
    RenderScratchFolder(const RenderScratchFolder&) = delete;
    RenderScratchFolder& operator=(const RenderScratchFolder&) = delete;
};

namespace {

// Reads glpreview's stdout until it ends, passing each "sheet-progress DONE TOTAL" line on; closes `fd`.
void relay_progress(int fd, const std::function<void(std::size_t, std::size_t)>& progress) {
    std::string pending;
    char buffer[512];
    for (;;) {
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        pending.append(buffer, static_cast<std::size_t>(n));
        for (std::size_t end; (end = pending.find('\n')) != std::string::npos; pending.erase(0, end + 1)) {
            std::size_t done = 0, total = 0;
            if (std::sscanf(pending.substr(0, end).c_str(), "sheet-progress %zu %zu", &done, &total) == 2)
                progress(done, total);
        }
    }
    ::close(fd);
}

// The row images, or throws std::runtime_error with the reason.
SphereRowImages run_glpreview(const SphereRenderRequest& r) {
    if (r.glpreview.empty() || !fs::exists(r.glpreview))
        throw std::runtime_error("glpreview was not built beside metalfit");
    if (r.materials.empty()) throw std::runtime_error("no material to render");
    if (r.models.empty()) throw std::runtime_error("no model to render");
    auto scratch = std::make_shared<const RenderScratchFolder>();
    const RenderScratchFolder& folder = *scratch;
    const std::string size = std::to_string(r.cell_size) + "x" + std::to_string(r.cell_size);
    std::vector<std::string> args{r.glpreview.string(), r.scene.string(), "--sheet", join(r.materials, ","),
                                  "--sheet-models", join(r.models, ","), "--size", size,
                                  // a folder inside the scratch folder: glpreview's own staging then lives there too
                                  "-o", (folder.path / "sheet").string(), "--data-dir", r.data_dir.string(),
                                  "--ocio-config", r.ocio.path.string(), "--sheet-rows",
                                  // The pages caption the cells themselves (the error scale from sheet.json): no
                                  // labels, and no OpenImageIO in glpreview (about 110 MiB of its libraries).
                                  "--sheet-labels", "off"};
    if (!r.film.empty()) args.insert(args.end(), {"--sheet-film", r.film});
    if (!r.coat.empty()) args.insert(args.end(), {"--sheet-coat", r.coat});
    if (r.progress) args.emplace_back("--sheet-progress");
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    const std::string log = (folder.path / "glpreview.log").string();
    // Its stdout: a pipe read for the progress lines when progress is asked for, else nowhere.
    int progress_pipe[2] = {-1, -1};
    if (r.progress && pipe2(progress_pipe, O_CLOEXEC) != 0) throw std::runtime_error("glpreview: no pipe for progress");
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    if (r.progress)
        posix_spawn_file_actions_adddup2(&actions, progress_pipe[1], STDOUT_FILENO);
    else
        posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    pid_t pid = 0;
    const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (r.progress) ::close(progress_pipe[1]);
    if (spawned != 0) {
        if (r.progress) ::close(progress_pipe[0]);
        throw std::runtime_error("glpreview could not be started");
    }
    if (r.progress) relay_progress(progress_pipe[0], r.progress);  // until glpreview closes its stdout
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) throw std::runtime_error("glpreview: lost its process");
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        const std::string why = last_line(read_bytes(log));
        throw std::runtime_error(why.empty() ? "glpreview failed" : why);
    }
    SphereRowImages sheet;
    sheet.scratch = scratch;
    for (std::size_t row = 0; row < r.materials.size(); ++row)
        sheet.images.push_back(folder.path / "sheet" / "rows" / (std::to_string(row) + ".png"));
    const auto record = nlohmann::json::parse(read_bytes(folder.path / "sheet" / "sheet.json"));
    // Row r is the r-th material asked for (glpreview names it by its catalog name); its entries go by model, then
    // roughness.
    sheet.materials = r.ids.empty() ? r.materials : r.ids;
    sheet.models = r.models;
    sheet.cells.assign(r.materials.size(), std::vector<std::vector<SphereSheetCells>>(r.models.size()));
    for (const auto& entry : record) {
        const std::size_t row = entry.at("row").get<std::size_t>();
        const auto model = std::find(r.models.begin(), r.models.end(), entry.at("model").get<std::string>());
        if (row >= r.materials.size() || model == r.models.end())
            throw std::runtime_error("glpreview's sheet.json names a cell not asked for");
        const auto& columns = entry.at("columns");
        sheet.cells[row][static_cast<std::size_t>(model - r.models.begin())].push_back(
            {entry.at("roughness").get<double>(), columns.at("reference").get<int>(), columns.at("model").get<int>(),
             columns.at("difference").get<int>(), entry.at("image_rmse_model_vs_reference").get<double>(),
             entry.at("error_view").at("smallest").get<double>(), entry.at("error_view").at("largest").get<double>()});
    }
    bool complete = true;
    for (std::size_t row = 0; row < sheet.cells.size(); ++row) {
        std::error_code ec;
        complete = complete && fs::is_regular_file(sheet.images[row], ec);
        for (const auto& model : sheet.cells[row]) complete = complete && !model.empty();
    }
    if (!complete) throw std::runtime_error("glpreview wrote no complete sheet");
    sheet.cell_width = sheet.cell_height = r.cell_size;
    return sheet;
}

}  // namespace

RenderMode parse_render_mode(const std::string& text) { return kRenderModeNames.parse(text); }

std::optional<std::size_t> SphereRowImages::row_of(const std::string& material) const {
    const auto it = std::find(materials.begin(), materials.end(), material);
    if (it == materials.end()) return std::nullopt;
    return static_cast<std::size_t>(it - materials.begin());
}

std::string SphereRowImages::image_bytes(std::size_t row) const {
    const fs::path& file = images.at(row);
    std::string bytes = read_bytes(file);
    if (bytes.empty()) throw InputError(InputLocation(file), "glpreview's render cannot be read or is empty");
    return bytes;
}

fs::path glpreview_beside_this_program() {
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (ec) return {};
    const fs::path glpreview = self.parent_path() / "glpreview";
    return fs::exists(glpreview, ec) ? glpreview : fs::path{};
}

SphereRenders render_spheres(const SphereRenderRequest& request, RenderMode mode) {
    if (mode == RenderMode::off) return {std::nullopt, "--renders off"};
    try {
        return {run_glpreview(request), {}};
    } catch (const std::exception& e) {
        if (mode == RenderMode::on)
            throw InputError(InputLocation(request.glpreview.empty() ? "glpreview" : request.glpreview),
                             std::string("--renders on: ") + e.what());
        std::string reason = e.what();
        if (reason.rfind("glpreview: ", 0) == 0) reason = reason.substr(11);
        return {std::nullopt, reason};
    }
}

}  // namespace metalfit
