#!/usr/bin/env bash
# Installs what is missing, builds everything (libraries, app, tests, benchmarks) and runs the
# whole CTest suite (unit, MPI at 1/2/4 ranks, regression, install + external consumer).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
sc_install_dependencies
sc_configure
sc_build
cd "$SC_BUILD_DIR"
ctest --output-on-failure -j "$SC_JOBS" --timeout 900
