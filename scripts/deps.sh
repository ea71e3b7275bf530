# Sourced by scripts/run and scripts/test: installs the Debian packages IMESS needs
# when any is missing (fresh Debian 12 machine), and nothing otherwise.
# (telnet: the README's tour talks to messd with it.)
imess_packages=(cmake ninja-build g++ pkg-config libboost-dev libeigen3-dev libspdlog-dev
                nlohmann-json3-dev catch2 libncurses-dev ccache telnet)
imess_packages+=(libmosquitto-dev)  # messmqtt and messfleet talk MQTT through libmosquitto (docs/mqtt.md)
imess_packages+=(libjs-three)  # three.js, which messd serves as /three/ for the web panel's 3-D view (scripts/run, tests)
# Only for scripts/bench: cyclictest (rt-tests), the floor bench_rt measures messd against,
# and matplotlib for the plots.
imess_bench_packages=(rt-tests python3 python3-matplotlib)
imess_bench_packages+=(chromium chromium-driver python3-selenium)  # scripts/bench web: the panel in a real browser

# Only for scripts/package and the suite's packaging test: dpkg-dev, whose dpkg-shlibdeps
# computes the package's Depends (lintian, which scripts/package adds, is optional for the test).
imess_package_packages=(dpkg-dev)

# Only for scripts/test: the independent readers the export and FreeCAD plugin tests use
# (ezdxf for DXF; freecadcmd for STEP, IGES, PLY, ASC and the plugin; Debian's python3 comes
# with them; Xvfb, the X server without a screen the plugin's test in a real FreeCAD window runs
# on), Chromium for the inspection report's layout (tests/clients/report), what scripts/bench
# needs, which the suite's smoke test runs, and what the packaging test packs with; Debian's
# chromium, its chromedriver and python3-selenium drive the web panel in a real browser (tests/web).
imess_test_packages=(python3-ezdxf freecad-python3 xvfb chromium chromium-driver python3-selenium
                     "${imess_bench_packages[@]}" "${imess_package_packages[@]}")  # python3 among them
imess_test_packages+=(libxml2-utils)  # xmllint: messcap's QIF documents validated against the QIF 3.0 schemas (tests/data/qif)
# LinuxCNC's own G-code interpreter, rs274 (tests/programs/test_rs274.cpp judges ours by it);
# without its recommendations, which would bring a real-time kernel and a desktop.
imess_test_packages_bare=(linuxcnc-uspace)
# The MQTT broker tests/mqtt starts on a free loopback port (its own configuration, no root);
# without recommendations, and Debian's own mosquitto service stays unused.
imess_test_packages_bare+=(mosquitto)

imess_install_deps() {   # imess_install_deps [test|bench]: the build packages, plus the test or bench ones
  local wanted=("${imess_packages[@]}")
  [ "${1:-}" = test ] && wanted+=("${imess_test_packages[@]}")
  [ "${1:-}" = bench ] && wanted+=("${imess_bench_packages[@]}")
  imess_install_packages "${wanted[@]}" || return 1
  if [ "${1:-}" = test ]; then imess_install_packages --no-install-recommends "${imess_test_packages_bare[@]}"; fi
}

imess_install_packages() {   # imess_install_packages [--no-install-recommends] PKG...: apt-get install those not installed
  local apt_flags=()
  [ "${1:-}" = --no-install-recommends ] && { apt_flags=(--no-install-recommends); shift; }
  local wanted=("$@")
  local missing=()
  for p in "${wanted[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "scripts: installing missing Debian packages: ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq || { echo "scripts: apt-get update failed" >&2; return 1; }
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${apt_flags[@]}" "${missing[@]}" \
    || { echo "scripts: could not install ${missing[*]}" >&2; return 1; }
}

imess_ccache_env() {   # the ccache settings every build of the tree uses (scripts/test, run, bench, fuzz)
  # A rebuild (another build dir, a fresh clone at another path) reuses what compiled; the
  # sloppiness lets ccache cache the files compiled with a precompiled header
  # (cmake/Precompiled.cmake); 20 GB holds the Dev, sanitized, fuzz and Release builds together.
  export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$imess_root} CCACHE_NOHASHDIR=${CCACHE_NOHASHDIR:-1}
  export CCACHE_MAXSIZE=${CCACHE_MAXSIZE:-20G}
  export CCACHE_SLOPPINESS=${CCACHE_SLOPPINESS:-pch_defines,time_macros,include_file_mtime,include_file_ctime}
}

imess_build() {   # imess_build <build-dir> [targets...]: configure, then build (all by default)
  local dir=$1; shift
  imess_ccache_env
  # IMESS_BUILD_TYPE: Dev unless said (-O1, no debug information: see CMakeLists.txt).
  cmake -S "$imess_root" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE="${IMESS_BUILD_TYPE:-Dev}" \
        -DCMAKE_CXX_COMPILER_LAUNCHER=ccache >/dev/null || return 1
  if [ $# -gt 0 ]; then
    cmake --build "$dir" -j "$(nproc)" --target "$@"
  else
    cmake --build "$dir" -j "$(nproc)"
  fi
}

# Only for scripts/fuzz: clang and its libFuzzer runtime (libclang_rt.fuzzer in libclang-rt-14-dev).
imess_fuzz_packages=(clang libclang-rt-14-dev)
imess_install_fuzz_deps() { imess_install_packages "${imess_fuzz_packages[@]}"; }
