# Sourced by scripts/run and scripts/test: installs the Debian packages IMESS needs
# when any is missing (fresh Debian 12 machine), and nothing otherwise.
imess_packages=(cmake ninja-build g++ pkg-config libboost-dev libeigen3-dev libspdlog-dev
                nlohmann-json3-dev catch2 libncurses-dev)

imess_install_deps() {
  local missing=()
  for p in "${imess_packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "scripts: installing missing Debian packages: ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq || { echo "scripts: apt-get update failed" >&2; return 1; }
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" \
    || { echo "scripts: could not install ${missing[*]}" >&2; return 1; }
}

imess_build() {   # imess_build <build-dir> [targets...]: configure, then build (all by default)
  local dir=$1; shift
  cmake -S "$imess_root" -B "$dir" -G Ninja >/dev/null || return 1
  if [ $# -gt 0 ]; then
    cmake --build "$dir" -j "$(nproc)" --target "$@"
  else
    cmake --build "$dir" -j "$(nproc)"
  fi
}
