# metalfit_precompile_headers(<target> [<header>...]): the standard library headers and nlohmann-json, which nearly
# every translation unit of libfit, glpreview and the bench parses, are parsed once per target into a precompiled
# header that each of its files loads instead (plus the target's own <header>s).
# Call it at the end of the target's CMakeLists.txt: a file compiled with options of its own (-fno-math-errno) is
# left out, since GCC cannot use a header precompiled under other options for it.
#
# Measured and explained in docs/development.md, "Cold builds". The test programs do not use it: their files are
# compiled in batches (cmake/UnitySources.cmake), which parse these headers once per batch already.
option(METALFIT_PRECOMPILED_HEADERS "Precompile the common headers of the libraries and executables" ON)

set(METALFIT_PRECOMPILED_COMMON_HEADERS
  <algorithm> <array> <cmath> <complex> <cstddef> <cstdint> <filesystem> <functional> <limits> <map> <memory>
  <optional> <span> <sstream> <stdexcept> <string> <string_view> <vector> <nlohmann/json.hpp>)

function(metalfit_precompile_headers target)
  if(NOT METALFIT_PRECOMPILED_HEADERS)
    return()
  endif()
  target_precompile_headers(${target} PRIVATE ${METALFIT_PRECOMPILED_COMMON_HEADERS} ${ARGN})
  # With the headers precompiled, GCC 12 inlines std::string's copies differently and reports -Wstringop-overflow
  # and -Warray-bounds false positives inside <bits/char_traits.h> (a bound above PTRDIFF_MAX on a length it cannot
  # see is small; GCC bugs 105651 and 106199), which -Werror makes errors. GCC 13 does not; the build without
  # precompiled headers keeps both warnings.
  target_compile_options(${target} PRIVATE
    $<$<AND:$<CXX_COMPILER_ID:GNU>,$<VERSION_LESS:$<CXX_COMPILER_VERSION>,13>>:-Wno-stringop-overflow -Wno-array-bounds>)
  get_target_property(sources ${target} SOURCES)
  foreach(source IN LISTS sources)
    get_source_file_property(options ${source} COMPILE_OPTIONS)
    if(options)
      set_source_files_properties(${source} PROPERTIES SKIP_PRECOMPILE_HEADERS ON)
    endif()
  endforeach()
endfunction()
