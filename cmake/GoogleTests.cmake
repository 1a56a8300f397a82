# mcrt_discover_gtests(TARGET [TEST_PREFIX prefix] LABELS label...): registers the tests of a
# GoogleTest executable with CTest, with the given labels.
#
# The target `unit_tests` builds every executable that a test labelled "unit" runs, in one
# parallel build: the sanitizer and portability passes of scripts/test build it, then run that
# label. A GoogleTest executable left unbuilt would drop out of the label without a word (CTest
# registers an unlabelled *_NOT_BUILT in place of its tests), so every GoogleTest executable is
# registered here, and one labelled "unit" joins unit_tests in the same call.
include_guard(GLOBAL)
include(GoogleTest)
add_custom_target(unit_tests)

function(mcrt_discover_gtests target)
  cmake_parse_arguments(arg "" "TEST_PREFIX" "LABELS" ${ARGN})
  gtest_discover_tests(${target} TEST_PREFIX "${arg_TEST_PREFIX}" PROPERTIES LABELS "${arg_LABELS}"
                       DISCOVERY_TIMEOUT 60)
  if("unit" IN_LIST arg_LABELS)
    add_dependencies(unit_tests ${target})
  endif()
endfunction()
