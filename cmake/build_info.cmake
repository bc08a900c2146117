# tumble_build_info: buildVersion() and buildCommit() (src/base/build_info.h). The commit is read
# at every build, not at configure time, so that a new HEAD or an edit shows up without
# re-running CMake; the generated source is rewritten only when its text changes, so an
# unchanged commit recompiles nothing.
set(tumble_build_info_cpp ${CMAKE_BINARY_DIR}/generated/build_info.cpp)
find_package(Git QUIET)
add_custom_target(tumble_build_commit
  COMMAND ${CMAKE_COMMAND}
          -DGIT_EXECUTABLE=${GIT_EXECUTABLE}
          -DSOURCE_DIR=${CMAKE_SOURCE_DIR}
          -DVERSION=${PROJECT_VERSION}
          -DOUTPUT=${tumble_build_info_cpp}
          -P ${CMAKE_SOURCE_DIR}/cmake/write_build_info.cmake
  BYPRODUCTS ${tumble_build_info_cpp}
  COMMENT "Reading the git commit for --version"
  VERBATIM)
# Depends on nothing else, so any target may link it without pulling in the rest of tumble.
add_library(tumble_build_info STATIC ${tumble_build_info_cpp})
target_include_directories(tumble_build_info PUBLIC ${CMAKE_SOURCE_DIR}/src)
add_dependencies(tumble_build_info tumble_build_commit)
