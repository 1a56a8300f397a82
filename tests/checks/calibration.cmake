# Calibration run: every statistical check over hundreds of seeds on the correct code, its
# rejection rates and p-value distribution compared with its design. Label "calibration",
# excluded from the default run; `scripts/test --calibration` runs it. (The runner's source
# is calibration_runner.cpp: a name ending in _checks.cpp would be globbed into mcrt_checks.)
add_executable(calibrate_statistical_checks calibration_runner.cpp
                                            $<TARGET_OBJECTS:mcrt_checks>)
target_link_libraries(calibrate_statistical_checks PRIVATE mcrt_common mcrt_stats)
mcrt_warnings(calibrate_statistical_checks)

# Between 40 and 1000 seeds per check, as many as a 15-minute budget allows (the runner times
# each check on 20 seeds first, then plans each check again from the time left before it runs):
# the cheap checks get 1000 (a rejection rate of 0.05 measured to +-0.007), the region
# comparisons of whole images (seconds per seed) what is left, at least 40. The pilots take
# about 2 minutes on 2 idle cores; the timeout allows a machine three times slower.
add_test(NAME calibrate_statistical_checks
         COMMAND calibrate_statistical_checks --seed 1 --seeds 1000 --min-seeds 40 --budget 900
                 --out ${CMAKE_BINARY_DIR}/calibration)
set_tests_properties(calibrate_statistical_checks PROPERTIES LABELS calibration TIMEOUT 2700)
