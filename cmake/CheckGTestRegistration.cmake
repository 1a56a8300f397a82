# Every GoogleTest executable is registered through mcrt_discover_gtests (cmake/GoogleTests.cmake),
# the one place that keeps the target unit_tests whole: no CMake file below ROOT calls
# gtest_discover_tests itself. An error names the file and the line.
#
#   cmake -DROOT=<source folder> -P cmake/CheckGTestRegistration.cmake   (the test gtest_registration)
cmake_policy(VERSION 3.22)
file(GLOB_RECURSE files ${ROOT}/CMakeLists.txt ${ROOT}/*.cmake)
set(errors "")
foreach(file IN LISTS files)
  file(RELATIVE_PATH relative ${ROOT} ${file})
  # build folders, and the planted violation when ROOT is the project (tests/layering/)
  if(relative MATCHES "^(build[^/]*|out|\\.git|tests/layering)/" OR relative STREQUAL "cmake/GoogleTests.cmake")
    continue()
  endif()
  file(STRINGS ${file} calls REGEX "^[ \t]*gtest_discover_tests[ \t]*\\(")
  foreach(line IN LISTS calls)
    list(APPEND errors "${relative}: ${line}")
  endforeach()
endforeach()
if(errors)
  string(REPLACE ";" "\n  " text "${errors}")
  message(FATAL_ERROR "register GoogleTest executables with mcrt_discover_gtests (cmake/GoogleTests.cmake), "
                      "so that a unit test joins the target unit_tests:\n  ${text}")
endif()
message(STATUS "gtest registration: every GoogleTest executable below ${ROOT} goes through mcrt_discover_gtests")
