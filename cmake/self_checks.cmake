# The student repository's tests (`ctest --preset student`): for each lab, its
# self-check, `course grade LAB` on the visible checkpoints, which fails until
# every check of the lab passes. A starting copy fails them all; a finished
# lab passes its own.
foreach(dir ${LAB_DIRS})
  get_filename_component(name ${dir} NAME)
  string(REGEX REPLACE "^[0-9][0-9]_" "" id ${name})
  string(REPLACE "_" "-" id ${id})
  add_test(NAME check.${id}
           COMMAND course grade ${id} --out ${CMAKE_BINARY_DIR}/self-check/${id})
  set_tests_properties(check.${id} PROPERTIES LABELS "self-check" TIMEOUT 600
                       ENVIRONMENT "LAB_ROOT=${CMAKE_SOURCE_DIR}")
endforeach()
