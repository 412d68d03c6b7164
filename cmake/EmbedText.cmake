# metalfit_embed_files(<entries-var> <count-var> <delimiter> <NAME|NAME_WE> <file>...): for each file, one C++
# initialiser line {"<name>", R"<delimiter>(<file text>)<delimiter>"}, where <name> is the file's name (NAME) or its
# name without the extension (NAME_WE), and a configure dependency on the file so that editing it re-embeds it.
# Used for the GLSL of libfit's models and of glpreview's shaders.
function(metalfit_embed_files entries_var count_var delimiter name_component)
  set(entries "")
  foreach(path IN LISTS ARGN)
    get_filename_component(name ${path} ${name_component})
    file(READ ${path} text)
    string(APPEND entries "    {\"${name}\", R\"${delimiter}(${text})${delimiter}\"},\n")
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${path})
  endforeach()
  list(LENGTH ARGN count)
  set(${entries_var} "${entries}" PARENT_SCOPE)
  set(${count_var} ${count} PARENT_SCOPE)
endfunction()
