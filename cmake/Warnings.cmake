# Warnings for the project's own targets (not for the Debian headers they include).
function(mcrt_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                           -Wno-sign-conversion)
endfunction()

# Add a chapter executable chNN_name from chapters/NN_name/main.cpp.
function(mcrt_chapter name)
  add_executable(${name} main.cpp ${ARGN})
  target_link_libraries(${name} PRIVATE mcrt_common)
  mcrt_warnings(${name})
  add_dependencies(chapters ${name})  # chapters/CMakeLists.txt
endfunction()
