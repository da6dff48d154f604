#!/usr/bin/env bash
# The main job: installs what is missing, builds the application and runs the default Hertz 2D
# scene (input/hertz2d.xml). Results go to ./output/hertz2d (summary.json, solution.xdmf/.h5,
# contact CSV). Set SC_RANKS=N to run on N MPI ranks (default 1); extra arguments are passed to
# stresscontact (e.g. --set "Adaptivity/Cycles=3").
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
sc_install_dependencies
sc_configure
sc_build --target stresscontact
sc_mpiexec -n "${SC_RANKS:-1}" "$SC_BUILD_DIR/apps/stresscontact/stresscontact" "$@"
