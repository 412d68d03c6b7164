// An export is one unit (issue 13, item 3): a child `metalfit export --all` killed at random points, by SIGKILL or
// SIGINT, leaves the folder it writes either as it was or as a finished run leaves it; a SIGKILL may leave a staging
// folder beside it, which the next export removes; a SIGINT adds none.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <random>

#include "interrupted_runs.hpp"
#include "test_support.hpp"

extern char** environ;

namespace test_export_interrupted {

namespace fs = std::filesystem;
using metalfit::test::read_file;
using metalfit::test::TempDir;

using metalfit::test::names_in;
using metalfit::test::tree;

pid_t start_export(const std::vector<std::string>& args) {
    return metalfit::test::spawn_quietly(metalfit::test::kMetalfitExe, args);
}

int wait_for(pid_t pid) {
    int status = 0;
    ::waitpid(pid, &status, 0);
    return status;
}

void copy_tree(const fs::path& from, const fs::path& to) {
    fs::remove_all(to);
    fs::copy(from, to, fs::copy_options::recursive);
}

TEST(ExportInterrupted, AKilledExportLeavesTheOldFolderOrTheNewOne) {
    TempDir tmp;
    const fs::path old_dir = tmp.path() / "old", work = tmp.path() / "work", dir = work / "out";
    const std::vector<std::string> old_args{"export",   "--all",     "--model", "f82-tint",
                                            "--format", "json,glsl", "-o",      old_dir.string()};
    ASSERT_EQ(wait_for(start_export(old_args)), 0);
    const auto old_tree = tree(old_dir);
    // The closed forms: the writing of ~1200 files, which the kills aim at, dominates the run (no Ceres solves, which
    // take minutes under the sanitizers).
    const std::vector<std::string> new_args{
        "export",   "--all",     "--model",  "schlick,lazanyi,f82-tint,conductor-rgb,gulbrandsen",
        "--params", "closed",    "--format", "all",
        "-o",       dir.string()};
    fs::create_directories(work);
    copy_tree(old_dir, dir);
    const auto started = std::chrono::steady_clock::now();
    ASSERT_EQ(wait_for(start_export(new_args)), 0);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    const auto new_tree = tree(dir);
    ASSERT_GT(new_tree.size(), old_tree.size() + 500);  // the new set is the old one plus ~1100 files

    std::mt19937 random(20261201u);
    std::uniform_real_distribution<double> late(0.5, 1.1);  // most kills aim at the writing, which dominates
    int old_seen = 0, new_seen = 0;
    for (int trial = 0; trial < 6; ++trial) {
        const int signal = trial % 3 == 2 ? SIGINT : SIGKILL;
        copy_tree(old_dir, dir);
        const auto before = names_in(work);  // "out", and a staging folder an earlier SIGKILL may have left
        const double at = trial == 0 ? 0.3 * seconds : late(random) * seconds;
        const int status = metalfit::test::kill_at(start_export(new_args), at, signal);
        const auto now = tree(dir);
        const bool is_old = now == old_tree, is_new = now == new_tree;
        EXPECT_TRUE(is_old || is_new) << "trial " << trial << " at " << at << " s: " << now.size() << " files, old "
                                      << old_tree.size() << ", new " << new_tree.size();
        old_seen += is_old;
        new_seen += is_new;
        const auto left = names_in(work);
        if (signal == SIGINT || WIFEXITED(status)) {
            // SIGINT: this run's staging is removed first; one an earlier SIGKILL left is removed only if the signal
            // came after this run took the lock, so it may still be there.
            EXPECT_TRUE(std::find(left.begin(), left.end(), "out") != left.end()) << "trial " << trial;
            for (const std::string& name : left)
                EXPECT_TRUE(name == "out" || std::find(before.begin(), before.end(), name) != before.end())
                    << "trial " << trial << ": " << name << " was left by this run";
        } else {
            EXPECT_LE(left.size(), 2u) << "trial " << trial;
            for (const std::string& name : left)
                EXPECT_TRUE(name == "out" || name.starts_with(".out.metalfit-staging.")) << name;
        }
    }
    // The next export removes a staging folder a kill left and finishes the job.
    fs::create_directory(work / metalfit::test::stale_staging_name("out"));
    ASSERT_EQ(wait_for(start_export(new_args)), 0);
    EXPECT_EQ(tree(dir), new_tree);
    EXPECT_EQ(names_in(work), std::vector<std::string>{"out"});
    std::cout << "kills that left the old folder: " << old_seen << ", the new one: " << new_seen << "\n";
}

}  // namespace test_export_interrupted
