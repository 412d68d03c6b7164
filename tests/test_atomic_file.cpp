// Atomic output files and file digests.
#include <gtest/gtest.h>

#include "test_support.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include <signal.h>

#include "libfit/base/atomic_file.hpp"
#include "libfit/base/deferred_signals.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/base/file_digest.hpp"
#include "libfit/base/staged_folder.hpp"

namespace metalfit {
namespace test_atomic_file {

using namespace metalfit::test;

namespace fs = std::filesystem;

std::vector<std::string> list(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

std::string join(const std::vector<std::string>& v) {
    std::string s;
    for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
    return s;
}

TEST(AtomicFile, WritesContentsAndLeavesNoTemporary) {
    TempDir dir;
    const fs::path target = dir.path() / "out.json";
    const std::string contents = "{\"a\": 1}\nsecond line\n";
    write_file_atomically(target, contents);
    EXPECT_EQ(read_file(target), contents);
    const auto names = list(dir.path());
    EXPECT_EQ(names, std::vector<std::string>{"out.json"}) << join(names);
}

TEST(AtomicFile, WritesBinaryAndEmptyContents) {
    TempDir dir;
    const std::string binary("a\0b\r\n\xff", 6);
    write_file_atomically(dir.path() / "bin", binary);
    EXPECT_EQ(read_file(dir.path() / "bin"), binary);
    write_file_atomically(dir.path() / "empty", "");
    EXPECT_TRUE(fs::exists(dir.path() / "empty"));
    EXPECT_EQ(fs::file_size(dir.path() / "empty"), 0u);
    EXPECT_EQ(list(dir.path()), (std::vector<std::string>{"bin", "empty"}));
}

TEST(AtomicFile, OverwritingKeepsOnlyTheNewContent) {
    TempDir dir;
    const fs::path target = dir.path() / "report.html";
    write_file_atomically(target, std::string(10000, 'x'));
    write_file_atomically(target, "short");
    EXPECT_EQ(read_file(target), "short");
    EXPECT_EQ(fs::file_size(target), 5u);
    const auto names = list(dir.path());
    EXPECT_EQ(names, std::vector<std::string>{"report.html"}) << join(names);
}

TEST(AtomicFile, ANonRegularTargetIsWrittenInPlaceNotReplaced) {
    // -o /dev/null or a pipe: renaming a file over it would replace the device itself. A FIFO stands in for it.
    TempDir dir;
    const fs::path fifo = dir.path() / "pipe";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    std::string received;
    std::thread reader([&] {
        std::ifstream in(fifo, std::ios::binary);
        received.assign(std::istreambuf_iterator<char>(in), {});
    });
    write_file_atomically(fifo, "through the pipe");
    reader.join();
    EXPECT_EQ(received, "through the pipe");
    EXPECT_TRUE(fs::is_fifo(fifo));
    EXPECT_EQ(list(dir.path()), std::vector<std::string>{"pipe"});
    EXPECT_THROW(write_file_atomically(dir.path(), "x"), metalfit::InputError);  // a directory is refused
}

TEST(StreamedOutputFile, PiecesAppearTogetherAtCommitAndNothingBefore) {
    TempDir dir;
    const fs::path target = dir.path() / "record.json";
    write_file_atomically(target, "old");
    {
        StreamedOutputFile out(target);
        out.write("{\n");
        out.write(std::string(100000, 'x'));
        out.write("\n}\n");
        EXPECT_EQ(read_file(target), "old");  // the pieces are in the temporary beside it
        EXPECT_EQ(list(dir.path()).size(), 2u) << join(list(dir.path()));
        out.commit();
    }
    EXPECT_EQ(read_file(target), "{\n" + std::string(100000, 'x') + "\n}\n");
    EXPECT_EQ(list(dir.path()), std::vector<std::string>{"record.json"});
}

TEST(StreamedOutputFile, WithoutCommitTheTargetStaysAsItWasAndNoTemporaryIsLeft) {
    TempDir dir;
    const fs::path target = dir.path() / "record.json";
    write_file_atomically(target, "old");
    try {
        StreamedOutputFile out(target);
        out.write("half a record");
        throw std::runtime_error("a fit failed");
    } catch (const std::runtime_error&) {}
    EXPECT_EQ(read_file(target), "old");
    EXPECT_EQ(list(dir.path()), std::vector<std::string>{"record.json"});
    { StreamedOutputFile never(dir.path() / "new.json"); }
    EXPECT_EQ(list(dir.path()), std::vector<std::string>{"record.json"});
}

TEST(StreamedOutputFile, ABadTargetIsRefusedBeforeAnythingIsWritten) {
    TempDir dir;
    EXPECT_THROW(StreamedOutputFile(dir.path() / "no-such-dir" / "out.json"), InputError);
    EXPECT_THROW(StreamedOutputFile(dir.path()), InputError);  // a directory
    EXPECT_TRUE(list(dir.path()).empty()) << join(list(dir.path()));
}

TEST(StreamedOutputFile, ADeviceGetsTheWholeOutputAtCommit) {
    TempDir dir;
    const fs::path fifo = dir.path() / "pipe";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    StreamedOutputFile out(fifo);  // spooled: nothing opens the pipe before commit
    out.write("through ");
    out.write("the pipe");
    std::string received;
    std::thread reader([&] {
        std::ifstream in(fifo, std::ios::binary);
        received.assign(std::istreambuf_iterator<char>(in), {});
    });
    out.commit();
    reader.join();
    EXPECT_EQ(received, "through the pipe");
    EXPECT_EQ(list(dir.path()), std::vector<std::string>{"pipe"});
}

TEST(AtomicFile, MissingDirectoryThrowsAndCreatesNothing) {
    TempDir dir;
    const fs::path target = dir.path() / "no-such-dir" / "out.txt";
    try {
        write_file_atomically(target, "data");
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_TRUE(Contains(e.what(), target.string()));
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
    }
    EXPECT_FALSE(fs::exists(dir.path() / "no-such-dir"));
    EXPECT_TRUE(list(dir.path()).empty()) << join(list(dir.path()));
}

TEST(AtomicFile, ReadOnlyDirectoryThrowsAndLeavesNothing) {
    TempDir dir;
    const fs::path target = dir.path() / "existing.txt";
    write_file_atomically(target, "old");
    fs::permissions(dir.path(),
                    fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read | fs::perms::group_exec |
                        fs::perms::others_read | fs::perms::others_exec,
                    fs::perm_options::replace);
    {
        // Running as root (or with CAP_DAC_OVERRIDE) makes a 0555 directory writable anyway.
        const fs::path probe = dir.path() / "probe";
        bool writable = false;
        {
            std::ofstream out(probe);
            writable = static_cast<bool>(out);
        }
        if (writable) {
            std::error_code ec;
            fs::remove(probe, ec);
            GTEST_SKIP() << "the read-only directory is writable (running as root?)";
        }
    }
    for (const char* name : {"new.txt", "existing.txt"}) {
        const fs::path t = dir.path() / name;
        try {
            write_file_atomically(t, "new contents");
            ADD_FAILURE() << "expected InputError for " << t;
        } catch (const InputError& e) {
            EXPECT_TRUE(Contains(e.what(), t.string()));
        }
    }
    EXPECT_EQ(read_file(target), "old");  // the old file is untouched
    const auto names = list(dir.path());
    EXPECT_EQ(names, std::vector<std::string>{"existing.txt"}) << join(names);
}

// ---- Planted links (issue 13, item 1) ------------------------------------------------------------------------------

// Links planted at every name the writer could use for its temporary (the old ".NAME.tmp.<pid>" scheme) must not
// redirect the output into the file they point to.
TEST(AtomicFile, LinksPlantedAtPredictableTemporaryNamesAreNotFollowed) {
    TempDir dir;
    const fs::path victim = dir.write("victim", "precious");
    const fs::path target = dir.path() / "out.json";
    fs::create_symlink(victim, dir.path() / (".out.json.tmp." + std::to_string(::getpid())));
    write_file_atomically(target, "output");
    EXPECT_EQ(read_file(victim), "precious");
    EXPECT_EQ(read_file(target), "output");
    write_files_atomically(std::vector<OutputFile>{{target, "second"}});
    EXPECT_EQ(read_file(victim), "precious");
    EXPECT_EQ(read_file(target), "second");
}

TEST(AtomicFile, ALinkAtTheTargetIsReplacedNotWrittenThrough) {
    TempDir dir;
    const fs::path victim = dir.write("victim", "precious");
    const fs::path target = dir.path() / "out.json";
    fs::create_symlink(victim, target);
    write_file_atomically(target, "output");
    EXPECT_EQ(read_file(victim), "precious");
    EXPECT_FALSE(fs::is_symlink(target));
    EXPECT_EQ(read_file(target), "output");
}

// ---- Signals: deferred while writing, raised afterwards ---------------------------------------------------------------

TEST(DeferredSignalsDeathTest, ASignalWhileWritingEndsTheProcessAfterCleanup) {
    TempDir dir;
    const fs::path target = dir.path() / "out";
    EXPECT_EXIT(
        {
            const DeferredSignals deferred;
            ::raise(SIGTERM);
            if (!DeferredSignals::pending()) std::exit(10);
            try {
                write_files_atomically(std::vector<OutputFile>{{target, "x"}});
            } catch (const Interrupted&) {
                if (!fs::is_empty(dir.path())) std::exit(11);
                throw;
            }
            std::exit(12);
        },
        ::testing::KilledBySignal(SIGTERM), "");
    EXPECT_TRUE(fs::is_empty(dir.path()));
}

// ---- Folders as one unit (issue 13, items 3 and 6) ---------------------------------------------------------------------

std::map<std::string, std::string> tree(const fs::path& dir) {
    std::map<std::string, std::string> files;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file()) files[e.path().lexically_relative(dir).string()] = read_file(e.path());
    return files;
}

TEST(StagedFolder, KeepsOtherFilesReplacesItsOwnAndLeavesNoStaging) {
    TempDir tmp;
    const fs::path dir = tmp.path() / "a" / "b";
    update_folder_as_unit(dir, std::vector<OutputFile>{{"x/one", "1"}, {"top", "t"}});
    EXPECT_EQ(tree(dir), (std::map<std::string, std::string>{{"x/one", "1"}, {"top", "t"}}));
    update_folder_as_unit(dir, std::vector<OutputFile>{{"top", "T"}, {"y/two", "2"}});
    EXPECT_EQ(tree(dir), (std::map<std::string, std::string>{{"x/one", "1"}, {"top", "T"}, {"y/two", "2"}}));
    EXPECT_EQ(list(tmp.path() / "a"), std::vector<std::string>{"b"});
}

TEST(StagedFolder, AFailureChangesNothing) {
    TempDir tmp;
    const fs::path dir = tmp.path() / "out";
    update_folder_as_unit(dir, std::vector<OutputFile>{{"f", "old"}});
    fs::create_directories(dir / "d");
    EXPECT_THROW(update_folder_as_unit(dir, std::vector<OutputFile>{{"f", "new"}, {"d", "a file where a folder is"}}),
                 InputError);
    EXPECT_EQ(read_file(dir / "f"), "old");
    EXPECT_EQ(list(tmp.path()), std::vector<std::string>{"out"});
    // a merge that refuses: nothing changes either
    EXPECT_THROW(update_folder_as_unit(dir, std::vector<OutputFile>{{"f", "new"}},
                                       [](const fs::path&, const std::string&, const std::string&) -> std::string {
                                           throw InputError({"f"}, "refused");
                                       }),
                 InputError);
    EXPECT_EQ(read_file(dir / "f"), "old");
    EXPECT_EQ(list(tmp.path()), std::vector<std::string>{"out"});
}

TEST(StagedFolder, AStaleStagingFolderIsRemovedByTheNextWriter) {
    TempDir tmp;
    const fs::path dir = tmp.path() / "out";
    const std::string stale = stale_staging_name("out");
    fs::create_directories(tmp.path() / stale / "glsl");
    tmp.write(stale + "/glsl/half", "x");
    update_folder_as_unit(dir, std::vector<OutputFile>{{"f", "1"}});
    EXPECT_EQ(list(tmp.path()), std::vector<std::string>{"out"});
}

// Only names provably a writer's own are removed: the exact pattern, a pid that is gone, a lock nobody holds.
TEST(StagedFolder, WhatIsNotProvablyAKilledWritersStagingIsKept) {
    TempDir tmp;
    const std::vector<std::string> kept{
        ".out.metalfit-staging.abc123",                                                // a user's folder: no pid
        ".out.metalfit-staging." + std::to_string(::getppid()) + ".0123456789abcdef",  // a running pid
        ".out.metalfit-staging." + std::to_string(dead_pid()) + ".0123456789abcdeX",   // not the pattern
        ".out.metalfit-staging." + std::to_string(dead_pid()) + ".0123456789abcdef-mine"};
    for (const std::string& name : kept) fs::create_directories(tmp.path() / name);
    const std::string stale_file = stale_staging_name("out");  // the right name, but a file: not a staging folder
    tmp.write(stale_file, "mine");
    update_folder_as_unit(tmp.path() / "out", std::vector<OutputFile>{{"f", "1"}});
    std::vector<std::string> expected = kept;
    expected.push_back(stale_file);
    expected.push_back("out");
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(list(tmp.path()), expected);
}

TEST(AtomicFile, AStaleTemporaryIsRemovedByTheNextWriterOfThatFile) {
    TempDir tmp;
    const std::string stale = stale_staging_name("out.json", "tmp"), other = stale_staging_name("other.json", "tmp");
    tmp.write(stale, "half");
    tmp.write(other, "half");
    tmp.write(".out.json.metalfit-tmp.mine", "the user's");
    write_file_atomically(tmp.path() / "out.json", "{}");
    std::vector<std::string> expected{".out.json.metalfit-tmp.mine", other, "out.json"};
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(list(tmp.path()), expected);
    {
        StreamedOutputFile out(tmp.path() / "other.json");
        out.write("{}");
        out.commit();
    }
    EXPECT_EQ(list(tmp.path()), (std::vector<std::string>{".out.json.metalfit-tmp.mine", "other.json", "out.json"}));
}

// F10: a link planted under /dev/shm (anyone's folder) is replaced, never written through; only this process's own
// descriptor links (/dev/stdout, /dev/fd/N) are written in place.
TEST(AtomicFile, ALinkUnderDevIsNotWrittenThrough) {
    if (!fs::is_directory("/dev/shm")) GTEST_SKIP() << "no /dev/shm";
    TempDir tmp;
    const fs::path victim = tmp.write("victim", "precious");
    const fs::path link = fs::path("/dev/shm") / ("metalfit-test-link-" + std::to_string(::getpid()));
    fs::remove(link);
    fs::create_symlink(victim, link);
    write_file_atomically(link, "new");
    EXPECT_EQ(read_file(victim), "precious");
    EXPECT_FALSE(fs::is_symlink(link));
    EXPECT_EQ(read_file(link), "new");
    fs::remove(link);
}

TEST(StagedFolder, NewFilesAreNotWrittenThroughLinksInTheOldFolder) {
    TempDir tmp;
    const fs::path victim = tmp.write("victim", "precious");
    const fs::path dir = tmp.path() / "out";
    fs::create_directories(dir);
    fs::create_symlink(victim, dir / "f");
    update_folder_as_unit(dir, std::vector<OutputFile>{{"f", "new"}});
    EXPECT_EQ(read_file(victim), "precious");
    EXPECT_EQ(read_file(dir / "f"), "new");
}

TEST(StagedFolder, ParallelWritersIntoOneNewNestedFolderAllSucceedAndKeepEveryFile) {
    TempDir tmp;
    const fs::path dir = tmp.path() / "n1" / "n2" / "out";
    std::vector<std::thread> writers;
    std::vector<std::string> errors(8);
    for (int i = 0; i < 8; ++i)
        writers.emplace_back([&, i] {
            try {
                update_folder_as_unit(dir, std::vector<OutputFile>{{"w" + std::to_string(i), std::to_string(i)}});
            } catch (const std::exception& e) {
                errors[static_cast<std::size_t>(i)] = e.what();
            }
        });
    for (auto& w : writers) w.join();
    for (const std::string& e : errors) EXPECT_EQ(e, "");
    EXPECT_EQ(tree(dir).size(), 8u);
    EXPECT_EQ(list(tmp.path() / "n1" / "n2"), std::vector<std::string>{"out"});
}

// F10: a link at -o that another user planted in a folder anyone can write (/dev/shm, /tmp) is not followed.
TEST(StagedFolder, ALinkAnotherUserPlantedInASharedFolderIsNotFollowed) {
    if (!fs::is_directory("/dev/shm")) GTEST_SKIP() << "no /dev/shm";
    if (::geteuid() != 0) GTEST_SKIP() << "planting a link owned by another user needs root (lchown)";
    TempDir tmp;
    const fs::path victim = tmp.path() / "victim";
    fs::create_directories(victim);
    tmp.write("victim/precious", "mine");
    const fs::path link = fs::path("/dev/shm") / ("metalfit-test-folder-link-" + std::to_string(::getpid()));
    fs::remove(link);
    fs::create_directory_symlink(victim, link);
    ASSERT_EQ(::lchown(link.c_str(), 65534, 65534), 0);
    EXPECT_THROW(update_folder_as_unit(link, std::vector<OutputFile>{{"f", "1"}}), InputError);
    EXPECT_EQ(list(victim), std::vector<std::string>{"precious"});
    fs::remove(link);
}

// A folder written inside another writer's staging (the report's glpreview renders go into the report's scratch
// folder): the inner commit's lock on its parent must not wait for the outer writer's own lock (it deadlocked).
TEST(StagedFolder, AFolderWrittenInsideAnotherWritersStagingDoesNotWaitForIt) {
    TempDir tmp;
    StagedFolder outer(tmp.path() / "out");
    const fs::path inner = outer.file("renders/x").parent_path();
    update_folder_as_unit(inner, std::vector<OutputFile>{{"sheet.png", "png"}});
    EXPECT_EQ(read_file(inner / "sheet.png"), "png");
    outer.commit();
    EXPECT_EQ(read_file(tmp.path() / "out" / "renders" / "sheet.png"), "png");
    EXPECT_EQ(list(tmp.path()), std::vector<std::string>{"out"});
}

TEST(StagedFolder, TheCurrentFolderIsRefused) {
    TempDir tmp;
    const fs::path before = fs::current_path();
    fs::current_path(tmp.path());
    EXPECT_THROW(update_folder_as_unit(".", std::vector<OutputFile>{{"f", "1"}}), UsageError);
    EXPECT_THROW(update_folder_as_unit(tmp.path().parent_path(), std::vector<OutputFile>{{"f", "1"}}), UsageError);
    fs::current_path(before);
    EXPECT_TRUE(fs::is_empty(tmp.path()));
}

TEST(AtomicFileDigest, Sha256OfAbc) {
    TempDir dir;
    const fs::path file = dir.path() / "abc.txt";
    std::ofstream(file, std::ios::binary) << "abc";
    EXPECT_EQ(sha256_file(file), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
}

TEST(AtomicFileDigest, Sha256OfEmptyAndOfALargeFile) {
    TempDir dir;
    const fs::path empty = dir.path() / "empty";
    std::ofstream(empty, std::ios::binary).flush();
    EXPECT_EQ(sha256_file(empty), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
    // One million 'a' (FIPS 180-2 test vector), larger than any single read buffer.
    const fs::path big = dir.path() / "million-a";
    std::ofstream(big, std::ios::binary) << std::string(1000000, 'a');
    EXPECT_EQ(sha256_file(big), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(AtomicFileDigest, WrittenFileDigestMatches) {
    TempDir dir;
    write_file_atomically(dir.path() / "abc", "abc");
    EXPECT_EQ(sha256_file(dir.path() / "abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
}

TEST(AtomicFileDigest, MissingFileThrowsInputError) {
    TempDir dir;
    const fs::path file = dir.path() / "missing";
    try {
        (void)sha256_file(file);
        FAIL();
    } catch (const InputError& e) {
        EXPECT_TRUE(Contains(e.what(), file.string()));
    }
}

}  // namespace test_atomic_file
}  // namespace metalfit

namespace metalfit {
namespace test_atomic_file {

// ---- Messages (issue 13, item 12) --------------------------------------------------------------------------------

TEST(SanitisedMessage, ControlBytesInvisibleCharactersAndHugeTokensAreMadeSafe) {
    EXPECT_EQ(sanitised_message("a\nb\tc\x1b[31md"), "a b c\\x1B[31md");
    EXPECT_EQ(sanitised_message("\xEF\xBB\xBFwavelength_nm"), "<U+FEFF>wavelength_nm");
    EXPECT_EQ(sanitised_message("caf\xe9 \xc2\xb5m"), "caf\\xE9 \xc2\xb5m");  // a stray Latin-1 byte; µ stays
    EXPECT_EQ(sanitised_message("x\xE2\x80\xAEy"), "x<U+202E>y");             // right-to-left override
    const std::string huge(50'000'000, 'x');
    const std::string cut = sanitised_message("found '" + huge + "'");
    EXPECT_LE(cut.size(), kMaxMessageBytes + 40);
    EXPECT_TRUE(cut.ends_with("… (49999008 more bytes)")) << cut.substr(cut.size() - 40);
    // InputError's message is sanitised too
    const InputError e({"f.csv", 2}, "non-numeric value '\xEF\xBB\xBF"
                                     "1.0\r'");
    EXPECT_STREQ(e.what(), "f.csv:2: non-numeric value '<U+FEFF>1.0 '");
}

}  // namespace test_atomic_file
}  // namespace metalfit
