// The report folder is written as one unit: complete, or not at all (an existing one then stays as it was).
#include <gtest/gtest.h>

#include <thread>

#include "libfit/base/errors.hpp"
#include "libfit/report/report.hpp"
#include "test_support.hpp"

namespace test_report_folder {

namespace fs = std::filesystem;
using metalfit::ReportFile;
using metalfit::test::read_file;

std::size_t entries(const fs::path& dir) {
    return std::distance(fs::directory_iterator(dir), fs::directory_iterator());
}

TEST(ReportFolder, WritesEveryFileAndReplacesAnOldFolderWhole) {
    const metalfit::test::TempDir tmp;
    const fs::path dir = tmp.path() / "report";
    metalfit::write_report_folder(dir, {{"index.html", "one"}, {"materials/Au.html", "gold"}, {"old-only.txt", "x"}});
    EXPECT_EQ(read_file(dir / "materials/Au.html"), "gold");
    metalfit::write_report_folder(dir, std::vector<ReportFile>{{"index.html", "two"}});
    EXPECT_EQ(read_file(dir / "index.html"), "two");
    EXPECT_FALSE(fs::exists(dir / "old-only.txt")) << "the old folder is replaced, not merged";
    EXPECT_EQ(entries(tmp.path()), 1u) << "no temporary or old folder is left beside it";
}

TEST(ReportFolder, AFailureLeavesNothingNewAndTheOldFolderAsItWas) {
    const metalfit::test::TempDir tmp;
    const fs::path dir = tmp.path() / "report";
    // "a" is a file, so "a/b" cannot be written: the second file fails after the first was written.
    const std::vector<ReportFile> failing{{"a", "file"}, {"a/b", "under a file"}};
    EXPECT_THROW(metalfit::write_report_folder(dir, failing), metalfit::InputError);
    EXPECT_EQ(entries(tmp.path()), 0u);

    metalfit::write_report_folder(dir, std::vector<ReportFile>{{"index.html", "kept"}});
    EXPECT_THROW(metalfit::write_report_folder(dir, failing), metalfit::InputError);
    EXPECT_EQ(read_file(dir / "index.html"), "kept");
    EXPECT_EQ(entries(tmp.path()), 1u);
}

// F3: two reports at once into one folder both succeed, one after the other; the folder is one of them whole and
// nothing is left beside it.
TEST(ReportFolder, ParallelWritersOfOneFolderAllSucceed) {
    const metalfit::test::TempDir tmp;
    const fs::path dir = tmp.path() / "report";
    metalfit::write_report_folder(dir, std::vector<ReportFile>{{"index.html", "old"}});
    std::vector<std::thread> writers;
    std::vector<std::string> errors(6);
    for (int i = 0; i < 6; ++i)
        writers.emplace_back([&, i] {
            try {
                const std::string n = std::to_string(i);
                metalfit::write_report_folder(
                    dir, std::vector<ReportFile>{{"index.html", n}, {"materials/" + n + ".html", n}});
            } catch (const std::exception& e) {
                errors[static_cast<std::size_t>(i)] = e.what();
            }
        });
    for (auto& w : writers) w.join();
    for (const std::string& e : errors) EXPECT_EQ(e, "");
    const std::string n = read_file(dir / "index.html");
    EXPECT_EQ(read_file(dir / "materials" / (n + ".html")), n);
    EXPECT_EQ(entries(dir / "materials"), 1u);
    EXPECT_EQ(entries(tmp.path()), 1u);
}

TEST(ReportFolder, ATargetThatIsAFileOrUnderNoFolderIsAnInputError) {
    const metalfit::test::TempDir tmp;
    std::ofstream(tmp.path() / "file") << "x";
    EXPECT_THROW(metalfit::write_report_folder(tmp.path() / "file", {}), metalfit::InputError);
    EXPECT_THROW(metalfit::write_report_folder(tmp.path() / "file" / "report", {}), metalfit::InputError);
    EXPECT_THROW(metalfit::write_report_folder(tmp.path() / "missing" / "report", {}), metalfit::InputError);
    EXPECT_EQ(read_file(tmp.path() / "file"), "x");
    EXPECT_EQ(entries(tmp.path()), 1u);
}

}  // namespace test_report_folder
