// A preview's output files as one unit (issue: a later image that cannot be written must not leave earlier ones):
// every file is written into a staging folder beside the output folder first, and only when the whole graph ran are
// they switched into the output folder together. The staging is libfit's StagedFolder (the one mechanism of every
// writer: exclusive, locked, removed by the next writer when a kill left it; signals deferred). Destroyed without
// commit(), it leaves nothing.
#pragma once

#include <filesystem>
#include <string>

#include "libfit/base/staged_folder.hpp"

namespace metalfit::glpreview {

class OutputStaging {
public:
    explicit OutputStaging(std::filesystem::path output_dir);  // makes the staging folder beside output_dir

    // Where to write the file `name` now (in the staging folder); its final path is output_dir / name.
    std::filesystem::path file(const std::string& name) { return staged_.file(name); }
    // Every staged file into output_dir as one unit; throws InputError (nothing changed) on failure.
    void commit() { staged_.commit(); }

private:
    StagedFolder staged_;
};

}  // namespace metalfit::glpreview
