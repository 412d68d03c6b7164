# metalfit_embed_files(<entries-var> <count-var> <dir> <suffix> <delimiter> <name>...): for each <dir>/<name><suffix>,
# one C++ initialiser line {"<name>", R"<delimiter>(<file text>)<delimiter>"}, and a configure dependency on the file
# so that editing it re-embeds it. Used for the GLSL of libfit's models and of glpreview's shaders.
function(metalfit_embed_files entries_var count_var dir suffix delimiter)
  set(entries "")
  foreach(name IN LISTS ARGN)
    set(path ${dir}/${name}${suffix})
    file(READ ${path} text)
    string(APPEND entries "    {\"${name}\", R\"${delimiter}(${text})${delimiter}\"},\n")
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${path})
  endforeach()
  list(LENGTH ARGN count)
  set(${entries_var} "${entries}" PARENT_SCOPE)
  set(${count_var} ${count} PARENT_SCOPE)
endfunction()
