// Every writer is one unit (issue 30, goals 2 and 3): the real executables — `metalfit report`, `fit -o`, `table -o`,
// `show -o`, `glpreview` — killed (SIGKILL, SIGTERM, SIGINT, SIGHUP) at random points leave their target either as
// it was or as a finished run leaves it, never a mix; SIGTERM, SIGINT and SIGHUP leave no staging; what a SIGKILL
// leaves is removed by the next run (only names provably a writer's own: a user's file that looks like one stays).
// Plus the regressions of the outside campaign: a symlinked subfolder of -o (F9), a scene named "...json" in
// glpreview --batch (F12), stdout on /dev/full (F17). The export's own kill test is tests/test_export_interrupted.cpp.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <map>
#include <random>

#include "interrupted_runs.hpp"
#include "test_support.hpp"

extern char** environ;

namespace test_writers_interrupted {

namespace fs = std::filesystem;
using metalfit::test::Contains;
using metalfit::test::kGlpreviewExe;
using metalfit::test::kMetalfitExe;
using metalfit::test::read_file;
using metalfit::test::TempDir;

using metalfit::test::names_in;
using metalfit::test::Tree;
using metalfit::test::tree;

// Starts `exe args` with $OCIO unset and stdin, stdout and stderr on /dev/null.
pid_t start(const std::string& exe, const std::vector<std::string>& args) {
    return metalfit::test::spawn_quietly(exe, args);
}

int wait_for(pid_t pid) {
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
    return status;
}

bool exited_ok(int status) { return WIFEXITED(status) && WEXITSTATUS(status) == 0; }

// A writer under test: its command, its target (a file or a folder) and how the old target is put back.
struct Writer {
    std::string exe;
    std::vector<std::string> args;
    fs::path target;  // in its own folder `work`, which holds nothing else but the planted look-alike
    bool folder = false;
    std::function<void()> restore_old;  // puts the old target in place
    std::function<bool(const Tree&)> is_old, is_new;
};

// What the writers' staging names look like beside `target` (libfit/src/base/exclusive_file.hpp).
bool is_staging_name(const std::string& name, const std::string& target) {
    return name.starts_with("." + target + ".metalfit-staging.") || name.starts_with("." + target + ".metalfit-tmp.");
}

Tree target_state(const Writer& w) {
    if (!w.folder) {
        std::error_code ec;
        if (!fs::is_regular_file(w.target, ec)) return {};
        return {{"", read_file(w.target)}};
    }
    return tree(w.target);
}

// Kills the writer at random points of a run (SIGKILL, then SIGTERM, SIGINT or SIGHUP in turn), checking the target
// after each, then runs it to the end and checks that nothing but the target (and the user's look-alike) is left beside it.
void kill_at_random_points(const Writer& w, int trials, std::uint32_t seed) {
    const fs::path work = w.target.parent_path();
    const std::string name = w.target.filename().string();
    // A user's file whose name starts like a staging folder's but is not one of ours: it must survive every run.
    const std::string look_alike = "." + name + (w.folder ? ".metalfit-staging.mine" : ".metalfit-tmp.mine");
    std::ofstream(work / look_alike) << "the user's";

    w.restore_old();
    ASSERT_TRUE(w.is_old(target_state(w)));
    const auto started = std::chrono::steady_clock::now();
    ASSERT_TRUE(exited_ok(wait_for(start(w.exe, w.args))));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    ASSERT_TRUE(w.is_new(target_state(w))) << "a full run";

    std::mt19937 random(seed);
    std::uniform_real_distribution<double> when(0.4, 1.05);  // most kills aim at the end, where the output is written
    int old_seen = 0, new_seen = 0;
    for (int trial = 0; trial < trials; ++trial) {
        constexpr int kDeferred[] = {SIGTERM, SIGINT, SIGHUP};
        const int signal = trial % 2 == 0 ? SIGKILL : kDeferred[(trial / 2) % 3];
        w.restore_old();
        const auto before = names_in(work);
        const double at = when(random) * seconds;
        const int status = metalfit::test::kill_at(start(w.exe, w.args), at, signal);
        const Tree now = target_state(w);
        const bool is_old = w.is_old(now), is_new = w.is_new(now);
        EXPECT_TRUE(is_old || is_new) << name << " trial " << trial << " (signal " << signal << " at " << at << " s of "
                                      << seconds << "): " << now.size()
                                      << " files, neither the old target nor the new one";
        old_seen += is_old;
        new_seen += is_new;
        for (const std::string& left : names_in(work)) {
            if (left == name || left == look_alike) continue;
            if (signal != SIGKILL || WIFEXITED(status))  // deferred: the staging went first
                EXPECT_TRUE(std::find(before.begin(), before.end(), left) != before.end())
                    << name << " trial " << trial << ": signal " << signal << " left " << left;
            else
                EXPECT_TRUE(is_staging_name(left, name)) << name << " trial " << trial << ": " << left;
        }
    }
    // The next run removes what the kills left (not the user's look-alike) and finishes the job.
    ASSERT_TRUE(exited_ok(wait_for(start(w.exe, w.args))));
    EXPECT_TRUE(w.is_new(target_state(w)));
    EXPECT_EQ(names_in(work), (std::vector<std::string>{look_alike, name}))
        << "staging left beside " << name << " after a successful run";
    EXPECT_EQ(read_file(work / look_alike), "the user's");
    std::cout << name << ": kills that left the old target " << old_seen << ", the new one " << new_seen
              << " (a run takes " << seconds << " s)\n";
}

// A folder target: the old one is `old_files` (made by hand); the new one has exactly the names a finished run
// writes (kept_extra: plus the old files it keeps) and none of the old contents.
Writer folder_writer(const std::string& exe, std::vector<std::string> args, const fs::path& target,
                     const Tree& old_files, const Tree& full_run, bool keeps_other_files) {
    Writer w{exe, std::move(args), target, true, {}, {}, {}};
    w.restore_old = [target, old_files] {
        fs::remove_all(target);
        for (const auto& [name, contents] : old_files) {
            fs::create_directories((target / name).parent_path());
            std::ofstream(target / name, std::ios::binary) << contents;
        }
    };
    w.is_old = [old_files](const Tree& t) { return t == old_files; };
    w.is_new = [old_files, full_run, keeps_other_files](const Tree& t) {
        Tree expected_names = full_run;
        if (keeps_other_files)
            for (const auto& [name, contents] : old_files) expected_names.emplace(name, contents);
        if (t.size() != expected_names.size()) return false;
        for (const auto& [name, contents] : t) {
            if (!expected_names.contains(name)) return false;
            if (full_run.contains(name) && old_files.contains(name) && old_files.at(name) == contents) return false;
        }
        return true;
    };
    return w;
}

// A file target: the old one holds "old", the new one what a full run wrote.
Writer file_writer(std::vector<std::string> args, const fs::path& target) {
    Writer w{kMetalfitExe, std::move(args), target, false, {}, {}, {}};
    w.restore_old = [target] { std::ofstream(target, std::ios::binary) << "old"; };
    w.is_old = [](const Tree& t) { return t.size() == 1 && t.begin()->second == "old"; };
    auto expected = std::make_shared<std::string>();
    w.is_new = [expected](const Tree& t) {
        if (t.size() != 1 || t.begin()->second == "old" || t.begin()->second.empty()) return false;
        if (expected->empty()) *expected = t.begin()->second;  // the first full run's output
        return t.begin()->second == *expected;
    };
    return w;
}

// metalfit report needs the chart libraries compiled in (node_modules/ at configure time, scripts/install-deps.sh).
bool report_is_built(const fs::path& scratch) {
    const auto r = metalfit::test::run_command(
        kMetalfitExe, "report Au --model schlick --renders off -o '" + (scratch / "probe-report").string() + "'",
        scratch);
    fs::remove_all(scratch / "probe-report");
    return !Contains(r.err, "built without the chart libraries");
}

TEST(WritersInterrupted, ReportIsTheOldFolderOrTheNewOne) {
    TempDir tmp;
    if (!report_is_built(tmp.path())) GTEST_SKIP() << "metalfit was built without the report's chart libraries";
    const fs::path work = tmp.path() / "work", dir = work / "report";
    fs::create_directories(work);
    const std::vector<std::string> args{"report",    "Au,Cu", "--model", "schlick,f82-tint",
                                        "--renders", "off",   "-o",      dir.string()};
    ASSERT_TRUE(exited_ok(wait_for(start(kMetalfitExe, args))));
    const Tree full_run = tree(dir);
    ASSERT_GT(full_run.size(), 3u);
    const Tree old_files{{"index.html", "old"}, {"only-in-the-old.txt", "old"}};  // replaced: the old files go
    kill_at_random_points(folder_writer(kMetalfitExe, args, dir, old_files, full_run, false), 6, 3001u);
}

TEST(WritersInterrupted, FitToAFileIsTheOldFileOrTheNewOne) {
    TempDir tmp;
    const fs::path work = tmp.path() / "work";
    fs::create_directories(work);
    const fs::path out = work / "fit.json";
    kill_at_random_points(
        file_writer({"fit", "--all", "--model", "schlick,f82-tint", "--json", "-o", out.string()}, out), 6, 3002u);
}

TEST(WritersInterrupted, TableAndShowToAFileAreTheOldFileOrTheNewOne) {
    TempDir tmp;
    const fs::path work = tmp.path() / "work";
    fs::create_directories(work);
    const fs::path table = work / "table.md";
    kill_at_random_points(file_writer({"table", "-o", table.string()}, table), 4, 3003u);
    fs::remove_all(work);
    fs::create_directories(work);
    const fs::path show = work / "show.json";
    kill_at_random_points(file_writer({"show", "gold", "--json", "-o", show.string()}, show), 4, 3004u);
}

const char* kSmallScene = R"({"image": {"width": 48, "height": 32},
    "camera": {"position": [0, 1.2, 2.5], "look_at": [0, 1, 0]},
    "spheres": [{"center": [0, 1, 0], "radius": 0.5, "material": "Cu", "fresnel": "schlick"}]})";

bool glpreview_is_built() { return *kGlpreviewExe != '\0'; }

TEST(WritersInterrupted, GlpreviewIsTheOldFolderOrTheNewOne) {
    if (!glpreview_is_built()) GTEST_SKIP() << "glpreview is not built";
    TempDir tmp;
    const fs::path scene = tmp.write("s.json", kSmallScene);
    const fs::path work = tmp.path() / "work", dir = work / "out";
    fs::create_directories(work);
    const std::vector<std::string> args{scene.string(), "-o", dir.string()};
    ASSERT_TRUE(exited_ok(wait_for(start(kGlpreviewExe, args))));
    const Tree full_run = tree(dir);
    ASSERT_GE(full_run.size(), 3u);
    Tree old_files{{"kept.txt", "old"}};  // glpreview keeps the other files of its folder
    for (const auto& [name, contents] : full_run) old_files[name] = "old";
    kill_at_random_points(folder_writer(kGlpreviewExe, args, dir, old_files, full_run, true), 6, 3005u);
}

// F12: a scene named "...json" has the stem "..": --batch must not write (and replace) the parent of -o.
TEST(WritersInterrupted, BatchSceneNamesCannotNameTheParentOfTheOutput) {
    if (!glpreview_is_built()) GTEST_SKIP() << "glpreview is not built";
    TempDir tmp;
    const fs::path parent = tmp.path() / "parent";
    fs::create_directories(parent / "out");
    std::ofstream(parent / "precious.txt") << "mine";
    for (const char* name : {"...json", "..json"}) {  // stems ".." and "."
        const fs::path scene = tmp.write(name, kSmallScene);
        const auto r = metalfit::test::run_command(
            kGlpreviewExe, "--batch '" + scene.string() + "' -o '" + (parent / "out").string() + "'", tmp.path());
        EXPECT_EQ(r.exit_code, 2) << name << ": " << r.err;
        EXPECT_TRUE(Contains(r.err, "cannot name its output folder")) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_EQ(names_in(parent), (std::vector<std::string>{"out", "precious.txt"})) << name;
        EXPECT_TRUE(fs::is_empty(parent / "out")) << name;
    }
}

// F17: a stdout that fails (/dev/full) is exit 3 with one line, and nothing is written.
TEST(WritersInterrupted, AFullStdoutWritesNothing) {
    TempDir tmp;
    if (!report_is_built(tmp.path())) GTEST_SKIP() << "metalfit was built without the report's chart libraries";
    const auto full = [&](const std::string& exe, const std::string& args) {
        const fs::path err = tmp.path() / "err.txt";
        const std::string command =
            "env OCIO= '" + exe + "' " + args + " >/dev/full 2>'" + err.string() + "' </dev/null";
        const int status = std::system(command.c_str());
        const std::string text = read_file(err);
        fs::remove(err);
        EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 3) << args << ": " << text;
        // one line says it (glpreview also names its renderer on stderr)
        EXPECT_TRUE(Contains(text, "standard output: cannot write")) << text;
        EXPECT_EQ(text.find("standard output"), text.rfind("standard output")) << text;
    };
    full(kMetalfitExe, "report Au --model schlick --renders off -o '" + (tmp.path() / "report").string() + "'");
    EXPECT_EQ(names_in(tmp.path()), std::vector<std::string>{});
    if (!glpreview_is_built()) return;
    const fs::path scene = tmp.write("s.json", kSmallScene);
    full(kGlpreviewExe, "'" + scene.string() + "' -o '" + (tmp.path() / "out").string() + "'");
    full(kGlpreviewExe, "--batch '" + scene.string() + "' -o '" + (tmp.path() / "batch").string() + "'");
    full(kGlpreviewExe, "'" + (metalfit::test::kData / "scenes" / "sheet.json").string() +
                            "' --sheet Au --sheet-models schlick --size 24x24 -o '" + (tmp.path() / "sheet").string() +
                            "'");
    EXPECT_EQ(names_in(tmp.path()), std::vector<std::string>{"s.json"});
}

// F9: a subfolder of -o that is a link is never descended into: exit 3, one line naming it, nothing written there
// or in the folder.
TEST(WritersInterrupted, ASymlinkedSubfolderOfTheOutputIsRefused) {
    TempDir tmp;
    const fs::path outside = tmp.path() / "outside", dir = tmp.path() / "out";
    fs::create_directories(outside);
    fs::create_directories(dir);
    std::ofstream(dir / "mine.txt") << "mine";
    fs::create_directory_symlink(outside, dir / "glsl");
    const auto r = metalfit::test::run_command(
        kMetalfitExe, "export gold --model schlick --format json,glsl -o '" + dir.string() + "'", tmp.path());
    EXPECT_EQ(r.exit_code, 3) << r.err;
    EXPECT_TRUE(Contains(r.err, (dir / "glsl").string() + ": is a link")) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(fs::is_empty(outside));
    EXPECT_EQ(names_in(dir), (std::vector<std::string>{"glsl", "mine.txt"}));
    EXPECT_TRUE(fs::is_symlink(dir / "glsl"));
    EXPECT_EQ(names_in(tmp.path()), (std::vector<std::string>{"out", "outside"}));
}

}  // namespace test_writers_interrupted
