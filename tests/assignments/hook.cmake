# Adds tests/assignments to a tree whose tests/CMakeLists.txt does not (yet) add it:
# scripts/grade configures the instructor tree with -DCMAKE_PROJECT_INCLUDE=<this file>.
# The call is deferred to the end of the top-level CMakeLists.txt, when mcrt_stats exists.
function(mcrt_add_assignments_late)
  if(TARGET mcrt_stats AND NOT TARGET assignment_a1)
    include(${CMAKE_SOURCE_DIR}/tests/assignments/CMakeLists.txt)
  endif()
endfunction()
cmake_language(DEFER CALL mcrt_add_assignments_late)
