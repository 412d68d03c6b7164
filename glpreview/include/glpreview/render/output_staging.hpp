// A preview's output files as one unit (issue: a later image that cannot be written must not leave earlier ones):
// every file is written into a private temporary folder first, and only when the whole graph ran are they switched
// into the output folder together (libfit's update_folder_as_unit). Destroyed without commit(), it leaves nothing.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace metalfit::glpreview {

class OutputStaging {
public:
    explicit OutputStaging(std::filesystem::path output_dir);  // makes a private folder (mkdtemp) under $TMPDIR
    ~OutputStaging();
    OutputStaging(const OutputStaging&) = delete;
    OutputStaging& operator=(const OutputStaging&) = delete;

    // Where to write the file `name` now (in the private folder); its final path is output_dir / name.
    std::filesystem::path file(const std::string& name);
    // Every staged file into output_dir as one unit; throws InputError (nothing changed) on failure.
    void commit();

private:
    std::filesystem::path output_dir_;
    std::filesystem::path folder_;
    std::vector<std::string> names_;
};

}  // namespace metalfit::glpreview
