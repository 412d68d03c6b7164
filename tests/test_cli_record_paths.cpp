// Records are portable (issue 29, item 7): the real metalfit, run from a working folder of its own on a catalog
// material, a file in that folder and a file outside it, writes no absolute path in any record (fit --json,
// metalfit_export.json and an export's JSON, show --json, the oxide chart, report.json), and the database files it
// names as data:<path> are the files it read (docs/fit-record.md, "Paths in records"; libfit/base/record_path.hpp).
#include <gtest/gtest.h>

#include "test_support.hpp"
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace test_cli_record_paths {

namespace fs = std::filesystem;
using metalfit::test::kData;
using metalfit::test::kFixturesDir;
using metalfit::test::kMetalfitExe;
using metalfit::test::read_file;
using metalfit::test::TempDir;

using Result = metalfit::test::CommandResult;

// metalfit `args` (already shell-quoted) run with `working` as its working folder.
Result run_in(const fs::path& working, const std::string& args) {
    const fs::path out = working / ".stdout", err = working / ".stderr";
    const std::string command = "cd '" + working.string() + "' && env OCIO= '" + std::string(kMetalfitExe) + "' " +
                                args + " >'" + out.string() + "' 2>'" + err.string() + "' </dev/null";
    const int status = std::system(command.c_str());
    Result r{WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_file(out), read_file(err)};
    fs::remove(out);
    fs::remove(err);
    return r;
}

// Every string value of `j` with its JSON pointer.
void strings_of(const nlohmann::json& j, const std::string& at, std::vector<std::pair<std::string, std::string>>& out) {
    if (j.is_string())
        out.emplace_back(at, j.get<std::string>());
    else if (j.is_array())
        for (std::size_t i = 0; i < j.size(); ++i) strings_of(j[i], at + "/" + std::to_string(i), out);
    else if (j.is_object())
        for (const auto& [k, v] : j.items()) strings_of(v, at + "/" + k, out);
}

class RecordPaths : public ::testing::Test {
protected:
    void SetUp() override {
        fs::create_directories(work_);
        fs::create_directories(elsewhere_);
        fs::copy_file(kData / "nk" / "Au" / "Johnson.yml", work_ / "mine.yml");
        fs::copy_file(kData / "nk" / "Cu" / "Johnson.yml", elsewhere_ / "far.yml");
        data_ = fs::weakly_canonical(kData).string();
    }

    // No string of `record` is an absolute path (but shader text) or holds the database's, the working folder's or the other folder's
    // absolute path; returns the strings for further checks.
    std::vector<std::pair<std::string, std::string>> expect_portable(const nlohmann::json& record,
                                                                     const std::string& what) const {
        std::vector<std::pair<std::string, std::string>> strings;
        strings_of(record, "", strings);
        for (const auto& [at, s] : strings) {
            // The report's model GLSL (models/<i>/glsl/source) opens with a // comment, not a path.
            EXPECT_FALSE(s.starts_with("/") && !at.ends_with("/glsl/source")) << what << " " << at << ": " << s;
            for (const std::string& absolute :
                 {data_, std::string(metalfit::test::kDataDir), temp_.path().string(), fs::current_path().string()})
                EXPECT_EQ(s.find(absolute), std::string::npos) << what << " " << at << ": " << s;
        }
        return strings;
    }

    // `value` is data:<path> of an existing database file, and that path is `expected` when given.
    static void expect_data_file(const nlohmann::json& value, const std::string& expected = {}) {
        ASSERT_TRUE(value.is_string()) << value;
        const std::string s = value.get<std::string>();
        ASSERT_TRUE(s.starts_with("data:")) << s;
        const std::string relative = s.substr(5);
        EXPECT_TRUE(fs::is_regular_file(kData / relative)) << s << " does not resolve in " << kData;
        if (!expected.empty()) {
            EXPECT_EQ(relative, expected);
        }
    }

    nlohmann::json json_of(const std::string& args) const {
        const Result r = run_in(work_, args);
        EXPECT_EQ(r.exit_code, 0) << args << ": " << r.err;
        return nlohmann::json::parse(r.out.empty() ? "null" : r.out);
    }

    TempDir temp_;
    fs::path work_ = temp_.path() / "work";
    fs::path elsewhere_ = temp_.path() / "elsewhere";
    std::string data_;
};

TEST_F(RecordPaths, FitRecordNamesDatabaseWorkingAndOutsideFilesPortably) {
    const std::string far = (elsewhere_ / "far.yml").string();
    const auto j = json_of("fit Au mine.yml '" + far + "' --film TiO2:50nm --model schlick --json");
    expect_portable(j, "fit --json");
    expect_data_file(j["provenance"]["ocio_config"]["file"], "ocio/config.ocio");
    expect_data_file(j["materials"]["Au"]["data"]["file"], "nk/Au/Johnson.yml");
    expect_data_file(j["materials"]["Au"]["data"]["stack"]["film"]["file"]);
    EXPECT_EQ(j["materials"]["mine"]["data"]["file"], "mine.yml");
    EXPECT_EQ(j["materials"]["far"]["data"]["file"], "outside:far.yml");
}

TEST_F(RecordPaths, ExportRecordsAndHeadersArePortable) {
    const Result r = run_in(work_, "export Au mine.yml --model schlick --format json,glsl,openpbr -o out");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(read_file(work_ / "out" / "metalfit_export.json"));
    expect_portable(j, "metalfit_export.json");
    expect_data_file(j["provenance"]["ocio_config"]["file"], "ocio/config.ocio");
    expect_data_file(j["materials"]["Au"]["data"]["file"], "nk/Au/Johnson.yml");
    EXPECT_EQ(j["materials"]["mine"]["data"]["file"], "mine.yml");
    int files = 0;
    for (const auto& entry : fs::recursive_directory_iterator(work_ / "out")) {
        if (!entry.is_regular_file()) continue;
        ++files;
        const std::string text = read_file(entry.path());
        for (const std::string& absolute : {data_, std::string(metalfit::test::kDataDir), temp_.path().string()})
            EXPECT_EQ(text.find(absolute), std::string::npos) << entry.path() << " holds " << absolute;
        if (entry.path().extension() == ".json") expect_portable(nlohmann::json::parse(text), entry.path().string());
    }
    EXPECT_GE(files, 4);
    // The headers name the data as the record does.
    EXPECT_TRUE(metalfit::test::Contains(read_file(work_ / "out" / "openpbr" / "metalfit_au_schlick.json"),
                                         "data:nk/Au/Johnson.yml"));
}

TEST_F(RecordPaths, ShowAndTableRecordsArePortable) {
    const auto show = json_of("show Au --json");
    expect_portable(show, "show --json");
    expect_data_file(show["provenance"]["file"], "nk/Au/Johnson.yml");
    expect_data_file(show["provenance"]["ocio_config"], "ocio/config.ocio");
    const auto mine = json_of("show mine.yml --json");
    expect_portable(mine, "show mine.yml --json");
    EXPECT_EQ(mine["provenance"]["file"], "mine.yml");
    const auto chart = json_of("table Ti --film TiO2 --thickness 0:100:50nm --format json");
    expect_portable(chart, "table --thickness --format json");
    expect_data_file(chart["stack"]["metal"]["file"], "nk/Ti/Johnson.yml");
    expect_data_file(chart["stack"]["film"]["file"]);
    expect_portable(json_of("table Ti mine.yml --film TiO2:80nm --format json"), "table --format json");
    expect_portable(json_of("spaces --json"), "spaces --json");
}

TEST_F(RecordPaths, ReportRecordIsPortable) {
    const Result r = run_in(work_, "report Au mine.yml --model schlick --renders off -o report");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(read_file(work_ / "report" / "report.json"));
    expect_portable(j, "report.json");
    expect_data_file(j["provenance"]["ocio_config"]["file"], "ocio/config.ocio");
}

// A file whose far-infrared rows are dropped with a warning (the importer names the file as given): given by an
// absolute path, outside and inside the working folder, its warning in fit, show and report records names it as the
// records name files, never by the machine's path.
TEST_F(RecordPaths, ImporterWarningsNameTheFileAsRecordsDo) {
    fs::copy_file(fs::path(kFixturesDir) / "drop-ir-negative-n.yml", elsewhere_ / "ir.yml");
    fs::copy_file(fs::path(kFixturesDir) / "drop-ir-negative-n.yml", work_ / "ir-here.yml");
    const std::string far = (elsewhere_ / "ir.yml").string(), here = (work_ / "ir-here.yml").string();
    const auto fit = json_of("fit '" + far + "' '" + here + "' --model schlick --json");
    expect_portable(fit, "fit --json");
    for (const auto& [id, expected] :
         {std::pair<std::string, std::string>{"ir", "outside:ir.yml:"}, {"ir-here", "ir-here.yml:"}}) {
        const auto& warnings = fit["materials"][id]["warnings"];
        ASSERT_FALSE(warnings.empty()) << id << ": the fixture's dropped rows give no warning";
        EXPECT_TRUE(warnings[0].get<std::string>().starts_with(expected)) << warnings[0];
    }
    expect_portable(json_of("show '" + far + "' --json"), "show --json");
    const Result r = run_in(work_, "report '" + far + "' --model schlick --renders off -o report");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find(far), std::string::npos) << "stderr names the file as given: " << r.err;
    expect_portable(nlohmann::json::parse(read_file(work_ / "report" / "report.json")), "report.json");
}

// The database, the OCIO config and a film file all given by absolute paths outside the working folder (a copy of
// the database: the default one lies in the source tree), the output folder too: no record or exported file of fit,
// export or report holds any of those paths, nor the machine's temporary folder.
TEST_F(RecordPaths, AbsoluteDataFolderConfigAndOutputsLeaveNoAbsolutePath) {
    const fs::path db = elsewhere_ / "db";
    fs::copy(kData, db, fs::copy_options::recursive);
    fs::copy_file(kData / "films" / "TiO2" / "Siefke.yml", elsewhere_ / "film.yml");
    const std::string abs_db = fs::weakly_canonical(db).string();
    const std::string flags = "--data-dir '" + abs_db + "' --ocio-config '" + abs_db + "/ocio/config.ocio'";
    const std::string film = "--film '" + (elsewhere_ / "film.yml").string() + ":40nm'";
    const auto absolute_free = [&](const std::string& text, const std::string& what) {
        for (const std::string& absolute : {abs_db, elsewhere_.string(), work_.string(), temp_.path().string(), data_})
            EXPECT_EQ(text.find(absolute), std::string::npos) << what << " holds " << absolute;
    };
    const Result fit = run_in(work_, flags + " fit Au mine.yml '" + (elsewhere_ / "far.yml").string() + "' " + film +
                                         " --model schlick --json");
    ASSERT_EQ(fit.exit_code, 0) << fit.err;
    absolute_free(fit.out, "fit --json");
    const auto record = nlohmann::json::parse(fit.out);
    expect_portable(record, "fit --json");
    EXPECT_EQ(record["provenance"]["ocio_config"]["file"], "data:ocio/config.ocio");
    const fs::path out = temp_.path() / "export-out";
    const Result exported = run_in(work_, flags + " export Au mine.yml " + film +
                                              " --model schlick,rational --format all -o '" + out.string() + "'");
    ASSERT_EQ(exported.exit_code, 0) << exported.err;
    int files = 0;
    for (const auto& entry : fs::recursive_directory_iterator(out)) {
        if (!entry.is_regular_file()) continue;
        ++files;
        const std::string text = read_file(entry.path());
        absolute_free(text, entry.path().string());
        if (entry.path().extension() == ".json") expect_portable(nlohmann::json::parse(text), entry.path().string());
    }
    EXPECT_GE(files, 10);
}

}  // namespace test_cli_record_paths
