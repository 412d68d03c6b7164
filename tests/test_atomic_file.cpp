// Atomic output files and file digests.
#include <gtest/gtest.h>

#include "test_support.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

#include "libfit/base/atomic_file.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/base/file_digest.hpp"

namespace metalfit {
namespace {

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
    fs::permissions(dir.path(), fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                                    fs::perms::group_exec | fs::perms::others_read | fs::perms::others_exec,
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

}  // namespace
}  // namespace metalfit
