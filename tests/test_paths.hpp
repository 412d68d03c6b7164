// The absolute paths the tests use: the fixtures, the database, the executables and the build's catalog export. They
// are defined once, in <build>/tests/test_paths.cpp (configured from tests/test_paths.cpp.in, library
// metalfit_test_paths), not as -D definitions on every test's command line: the test sources then compile to the same
// command in a clone at another path, and the compiler cache (base directory: the source root) hits them.
#pragma once

namespace metalfit::test {

extern const char* const kFixturesDir;        // tests/fixtures
extern const char* const kDataDir;            // the database (data/, METALFIT_DATA_DIR)
extern const char* const kMetalfitExe;        // the metalfit executable of this build
extern const char* const kGlpreviewExe;       // the glpreview executable of this build; "" when it is not built
extern const char* const kCatalogExportDir;   // `export --all --model all --format all`, made by the build
extern const char* const kCatalogExportJson;  // its metalfit_export.json

}  // namespace metalfit::test
