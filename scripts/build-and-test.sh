#!/usr/bin/env bash
# Installs what is missing, builds everything (libraries, app, tests, benchmarks) and runs the
# CTest suite (unit, MPI at 1/2/4 ranks, regression, install + external consumer), without the
# tests labelled `long` (fine-mesh 3D verification, ~15 CPU-minutes; docs/verification.md
# "Long tests").
#   scripts/build-and-test.sh          the suite without `long` (what CI runs)
#   scripts/build-and-test.sh --long   only the `long` tests
#   scripts/build-and-test.sh --all    everything
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
select=(-LE long)
case "${1:-}" in
  "") ;;
  --long) select=(-L long) ;;
  --all) select=() ;;
  *) echo "usage: $0 [--long | --all]" >&2; exit 2 ;;
esac
sc_install_dependencies
sc_configure
sc_build
cd "$SC_BUILD_DIR"
ctest --output-on-failure -j "$SC_JOBS" --timeout 900 "${select[@]}"
