# Every dependency comes from Debian's packages. A missing one stops the configure step with
# the name of the package that provides it (scripts/test and scripts/run-chapters install them all when run as root).

macro(mcrt_require found package what)
  if(NOT ${found})
    message(FATAL_ERROR "${what} not found: install the Debian package '${package}' "
                        "(sudo apt-get install ${package}), or run scripts/test as root.")
  endif()
endmacro()

find_package(glm CONFIG QUIET)
mcrt_require(glm_FOUND libglm-dev "GLM")

find_package(CLI11 CONFIG QUIET)
mcrt_require(CLI11_FOUND libcli11-dev "CLI11")

find_package(nlohmann_json CONFIG QUIET)
mcrt_require(nlohmann_json_FOUND nlohmann-json3-dev "nlohmann-json")

find_package(PkgConfig QUIET)
mcrt_require(PKG_CONFIG_FOUND pkg-config "pkg-config")
pkg_check_modules(STB QUIET IMPORTED_TARGET stb)
mcrt_require(STB_FOUND libstb-dev "stb (stb_image_write)")

find_path(PCG_INCLUDE_DIR pcg_random.hpp)
if(PCG_INCLUDE_DIR)
  set(PCG_FOUND TRUE)
endif()
mcrt_require(PCG_FOUND libpcg-cpp-dev "pcg-cpp (pcg_random.hpp)")

find_package(fmt CONFIG QUIET)
mcrt_require(fmt_FOUND libfmt-dev "fmt")

find_package(Threads REQUIRED)

if(MCRT_BUILD_TESTS)
  find_package(GTest QUIET)
  mcrt_require(GTest_FOUND libgtest-dev "GoogleTest")
  find_package(Boost 1.74 QUIET)
  mcrt_require(Boost_FOUND libboost-math-dev "Boost.Math")
endif()

if(MCRT_BUILD_BENCHMARKS)
  find_package(benchmark CONFIG QUIET)
  mcrt_require(benchmark_FOUND libbenchmark-dev "Google Benchmark")
endif()
