#include "glpreview/render/output_staging.hpp"

namespace metalfit::glpreview {

OutputStaging::OutputStaging(std::filesystem::path output_dir)
    : staged_(output_dir, StagedFolder::Existing::keep_other_files) {}

}  // namespace metalfit::glpreview
