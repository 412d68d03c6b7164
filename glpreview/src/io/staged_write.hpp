// An image file written as a unit: the writer fills a temporary file in a new private folder beside the target
// (mkdtemp: a name nobody can plant a link at), which is then renamed over the target.
#pragma once

#include <filesystem>
#include <functional>

namespace metalfit::glpreview {

// `write` writes the image to the path it is given and throws std::exception saying why it could not; any failure
// becomes InputError naming `file` ("cannot write the image: ..."), and no partial file is left.
void write_staged(const std::filesystem::path& file, const std::function<void(const std::filesystem::path&)>& write);

}  // namespace metalfit::glpreview
