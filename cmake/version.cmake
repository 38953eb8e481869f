# ltrender's version for `ltrender --version` and the reports: project(VERSION), and `git describe`
# when built from a checkout, so a CI log says which commit made a golden or a budget figure.
# build/generated/version.cpp is written at configure time and again at every build (the target
# below), because a commit or an edit changes `git describe` without re-running cmake; it is
# rewritten only when the text changes, so an unchanged tree recompiles nothing.
function(lt_version out_file)
  set(args -DLT_VERSION=${PROJECT_VERSION} -DLT_SOURCE_DIR=${CMAKE_SOURCE_DIR} -DLT_OUT=${out_file})
  execute_process(COMMAND ${CMAKE_COMMAND} ${args} -P ${CMAKE_SOURCE_DIR}/cmake/write_version.cmake)
  add_custom_target(ltrender_version_file
    COMMAND ${CMAKE_COMMAND} ${args} -P ${CMAKE_SOURCE_DIR}/cmake/write_version.cmake
    BYPRODUCTS ${out_file} VERBATIM)
endfunction()
