# Shared by scripts/run-main.sh and scripts/build-and-test.sh: install the Debian packages that
# StressContact needs (if missing), configure with Ninja + ccache (Release), build with -j2.
# Environment: SC_BUILD_DIR (default <repo>/build), SC_JOBS (default 2).
set -euo pipefail

SC_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
SC_BUILD_DIR=${SC_BUILD_DIR:-$SC_ROOT/build}
SC_JOBS=${SC_JOBS:-2}
# ccache hashes the compiler's arguments, which hold absolute paths: with the source root as base
# directory they are rewritten as relative ones, so that another clone of the repository (CI's,
# a second work tree) finds the objects this one compiled.
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$SC_ROOT}"

# Debian 12 packages. Debian's Trilinos CMake configuration also needs the Scotch headers.
SC_DEBIAN_PACKAGES=(
  cmake ninja-build ccache g++ make pkg-config
  openmpi-bin libopenmpi-dev
  trilinos-all-dev trilinos-dev libptscotch-dev libscotch-dev
  libhdf5-openmpi-dev libmetis-dev libgmsh-dev libmumps-dev libopenblas0-serial libboost-dev nlohmann-json3-dev
  libmuparser-dev
  # scripts/plot-run.py and its tests plot_run_<deck>, run with /usr/bin/python3
  python3-matplotlib python3-h5py
  # tests/SpenceHalfPlane.py (test spence_half_plane: elliptic integrals, root finding)
  python3-scipy
)

sc_log() { printf '[stresscontact setup] %s\n' "$*"; }

sc_install_dependencies() {
  local missing=()
  for p in "${SC_DEBIAN_PACKAGES[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
      missing+=("$p")
    fi
  done
  if [ ${#missing[@]} -eq 0 ]; then
    sc_log "all ${#SC_DEBIAN_PACKAGES[@]} Debian packages are installed"
    return
  fi
  local sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    if command -v sudo >/dev/null 2>&1; then
      sudo="sudo"
    else
      sc_log "ERROR: missing Debian packages: ${missing[*]}"
      sc_log "Run this script as root, or install sudo, or install them by hand with apt-get."
      exit 1
    fi
  fi
  sc_log "installing ${#missing[@]} missing Debian packages: ${missing[*]}"
  $sudo apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
}

sc_configure() {
  if [ ! -f "$SC_BUILD_DIR/build.ninja" ]; then
    sc_log "configuring in $SC_BUILD_DIR (Release, Ninja, ccache)"
    cmake -S "$SC_ROOT" -B "$SC_BUILD_DIR" -G Ninja \
      -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache \
      -DCMAKE_INSTALL_PREFIX="$SC_BUILD_DIR/install"
  fi
}

sc_build() {
  sc_log "building with -j$SC_JOBS $*"
  cmake --build "$SC_BUILD_DIR" -j "$SC_JOBS" "$@"
}

sc_mpiexec() {
  local flags=(--oversubscribe)
  [ "$(id -u)" -eq 0 ] && flags+=(--allow-run-as-root)
  mpiexec "${flags[@]}" "$@"
}
