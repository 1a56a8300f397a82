# Shared set-up for the scripts: Debian packages, then configure and build a CMake preset.
# Sourced, not run.

set -euo pipefail

repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$repo_root"

# Everything the project needs from Debian: build tools, libraries, gnuplot for the plots,
# python3 for the robustness suite (tests/robustness/robustness.py), pandoc for the docs pages
# in HTML (scripts/render-docs), clang-format for the style (scripts/format-check).
debian_packages=(
  cmake g++ make pkg-config
  libglm-dev libstb-dev libcli11-dev libpcg-cpp-dev nlohmann-json3-dev libfmt-dev
  libgtest-dev libbenchmark-dev libboost-math-dev
  gnuplot-nox fonts-dejavu-core
  python3 pandoc clang-format
)

# The compilers of the portability builds (scripts/test --compiler NAME): the Debian package
# of each, installed only when that build is asked for.
declare -A compiler_packages=([clang]=clang [gcc11]=g++-11)

# ensure_packages [EXTRA...]: installs the missing packages (the project's and EXTRA) when run
# as root; otherwise prints the one command to run and exits with code 2.
ensure_packages() {
  local missing=()
  for package in "${debian_packages[@]}" "$@"; do
    if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
      missing+=("$package")
    fi
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  if [ "$(id -u)" -ne 0 ]; then
    echo "Missing Debian packages. Install them with:" >&2
    echo "sudo apt-get install -y ${missing[*]}" >&2
    exit 2
  fi
  echo "== Installing Debian packages: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
}

# configure_and_build PRESET [TARGET...]: configure once, then build with every core. Give one
# target: with Makefiles, several targets are built one after another, each on one core; the
# aggregates `chapters` (every chapter program) and `unit_tests` build theirs in parallel.
configure_and_build() {
  local preset="$1"
  shift
  echo "== Configuring (preset $preset)"
  cmake --preset "$preset" >/dev/null
  echo "== Building with $(nproc) jobs"
  if [ $# -gt 0 ]; then
    cmake --build --preset "$preset" -j "$(nproc)" --target "$@"
  else
    cmake --build --preset "$preset" -j "$(nproc)"
  fi
}

# describe_processor: one line naming the processor and its vector extensions, since the
# benchmarks' rates depend on it (the same binary differs by tens of percent between the hosts
# this project has run on).
describe_processor() {
  local model family number flags extensions=()
  model="$(grep -m1 '^model name' /proc/cpuinfo 2>/dev/null | cut -d: -f2- | sed 's/^ *//')"
  flags=" $(grep -m1 '^flags' /proc/cpuinfo 2>/dev/null | cut -d: -f2-) "
  for flag in avx2 fma avx512f; do
    [[ "$flags" == *" $flag "* ]] && extensions+=("$flag")
  done
  family="$(grep -m1 '^cpu family' /proc/cpuinfo 2>/dev/null | cut -d: -f2 | tr -d ' ')"
  number="$(grep -m1 '^model[[:space:]]*:' /proc/cpuinfo 2>/dev/null | cut -d: -f2 | tr -d ' ')"
  echo "== Processor: ${model:-unknown} (family ${family:-?}, model ${number:-?}), $(nproc) cores;" \
    "${extensions[*]:-no AVX2}"
}

