# The manifest of the files an executable is built from, beside it as
# NAME.sources (build/bin/lab.sources): `course grade`, `course bless` and
# `course warm-cache` refuse a `lab` older than one of them, which would
# grade the code as it was before an edit (grading/commands/lab_sources.hpp;
# docs/contract.md, `course`, Exit status).
#
# The files: the sources of the target and of every library of this
# project it links (the objects of an OBJECT library included), the files a
# library declares it builds in (the target property LAB_EMBEDDED_FILES: the
# pages of `lab serve`), and the headers these include in quotes, found
# beside the including file, from the source tree's top, or, for a lab's
# file, in its folder and its shaders/NN_name/ (the names C++ and GLSL
# share, shared.glsl). Not listed: the shaders `lab` reads at run time
# (framework/gl/shader.cpp reads them from this tree), which need no
# rebuild, and files generated into the build folder. Each listed file is
# also a link dependency of the target (LINK_DEPENDS): a build after any of
# them changed links it again, so what course calls out of date and what
# the build remakes are the same files.
#
# The list is made when CMake configures: a header first included after
# that is listed from the next configure on.

# Appends `target`'s files, and those of the libraries it links, to the
# global property LAB_BUILT_FROM; each target once.
function(lab_collect_built_from target)
  get_property(done GLOBAL PROPERTY LAB_BUILT_FROM_TARGETS)
  get_target_property(imported ${target} IMPORTED)
  if(imported OR target IN_LIST done)
    return()
  endif()
  set_property(GLOBAL APPEND PROPERTY LAB_BUILT_FROM_TARGETS ${target})
  get_target_property(dir ${target} SOURCE_DIR)
  set(files "")
  set(linked "")
  foreach(prop SOURCES INTERFACE_SOURCES LAB_EMBEDDED_FILES)
    get_target_property(entries ${target} ${prop})
    if(NOT entries)
      continue()
    endif()
    foreach(entry ${entries})
      if(entry MATCHES "^\\$<TARGET_OBJECTS:([^>]+)>$")
        list(APPEND linked ${CMAKE_MATCH_1})
      elseif(NOT entry MATCHES "\\$<")
        get_filename_component(path ${entry} ABSOLUTE BASE_DIR ${dir})
        string(FIND "${path}" "${CMAKE_BINARY_DIR}/" in_build)
        if(NOT in_build EQUAL 0)
          list(APPEND files ${path})
        endif()
      endif()
    endforeach()
  endforeach()
  set_property(GLOBAL APPEND PROPERTY LAB_BUILT_FROM ${files})
  foreach(prop LINK_LIBRARIES INTERFACE_LINK_LIBRARIES)
    get_target_property(libs ${target} ${prop})
    if(libs)
      foreach(lib ${libs})
        string(REGEX REPLACE "^\\$<LINK_ONLY:(.+)>$" "\\1" lib "${lib}")
        list(APPEND linked ${lib})
      endforeach()
    endif()
  endforeach()
  foreach(lib ${linked})
    if(TARGET ${lib})
      lab_collect_built_from(${lib})
    endif()
  endforeach()
endfunction()

# `files` and the headers they include in quotes, transitively, in `out`.
function(lab_with_headers files out)
  set(all ${files})
  set(pending ${files})
  while(pending)
    list(POP_FRONT pending file)
    if(NOT file MATCHES "\\.(c|cpp|h|hpp|glsl)$")
      continue()
    endif()
    get_filename_component(here ${file} DIRECTORY)
    set(dirs ${here} ${CMAKE_SOURCE_DIR})
    file(RELATIVE_PATH rel ${CMAKE_SOURCE_DIR} ${file})
    if(rel MATCHES "^(labs|shaders)/([0-9][0-9]_[^/]+)/")
      list(APPEND dirs ${CMAKE_SOURCE_DIR}/labs/${CMAKE_MATCH_2}
           ${CMAKE_SOURCE_DIR}/shaders/${CMAKE_MATCH_2})
    endif()
    file(STRINGS ${file} lines REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
    foreach(line ${lines})
      string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"([^\"]+)\".*" "\\1" name "${line}")
      foreach(dir ${dirs})
        get_filename_component(header ${dir}/${name} ABSOLUTE)
        if(EXISTS ${header} AND NOT IS_DIRECTORY ${header})
          if(NOT header IN_LIST all)
            list(APPEND all ${header})
            list(APPEND pending ${header})
          endif()
          break()
        endif()
      endforeach()
    endforeach()
  endwhile()
  set(${out} ${all} PARENT_SCOPE)
endfunction()

# Writes $<TARGET_FILE:target>.sources and makes its files link dependencies
# of `target`. Call it once every library the target links is defined.
function(lab_write_built_from target)
  set_property(GLOBAL PROPERTY LAB_BUILT_FROM "")
  set_property(GLOBAL PROPERTY LAB_BUILT_FROM_TARGETS "")
  lab_collect_built_from(${target})
  get_property(sources GLOBAL PROPERTY LAB_BUILT_FROM)
  list(REMOVE_DUPLICATES sources)
  lab_with_headers("${sources}" files)
  list(SORT files)
  set_property(TARGET ${target} APPEND PROPERTY LINK_DEPENDS ${files})
  set(text "# The files ${target} is built from (cmake/lab_sources.cmake): course refuses\n")
  string(APPEND text "# to run a ${target} older than one of them. Written by CMake.\n")
  string(APPEND text "source ${CMAKE_SOURCE_DIR}\nbuild ${CMAKE_BINARY_DIR}\n")
  foreach(file ${files})
    file(RELATIVE_PATH rel ${CMAKE_SOURCE_DIR} ${file})
    if(rel MATCHES "^\\.\\./")
      string(APPEND text "file ${file}\n")
    else()
      string(APPEND text "file ${rel}\n")
    endif()
  endforeach()
  file(GENERATE OUTPUT $<TARGET_FILE:${target}>.sources CONTENT "${text}")
endfunction()
