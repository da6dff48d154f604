#!/usr/bin/env bash
# The Krylov solver study of docs/solvers.md (issue #10), from an existing build:
#   scripts/solver-study.sh iterations   # MINRES iterations: levels x ν, 2D/3D k = 1, 2D k = 2
#   scripts/solver-study.sh cost         # time and peak memory vs DOFs, MUMPS vs Iterative, 1/2/4 ranks
# Output: the benchmark lines (one per size and solver) with `uptime` before and after.
# SC_BUILD_DIR as in common.sh; SC_STUDY_MAX_2D / SC_STUDY_MAX_3D bound the sizes of "cost".
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
B="$SC_BUILD_DIR/packages/assembly/elasticity_benchmark"
[ -x "$B" ] || { echo "solver-study: $B not built (cmake --build $SC_BUILD_DIR --target elasticity_benchmark)" >&2; exit 1; }
what=${1:-iterations}
uptime
case "$what" in
  iterations)
    for nu in 0.3 0.49 0.4999 0.5; do
      "$B" --dim=2 --solvers=Iterative --nu=$nu --max-dofs=50000
      "$B" --dim=3 --solvers=Iterative --nu=$nu --max-dofs=300000
      "$B" --dim=2 --degree=2 --solvers=Iterative --nu=$nu --max-dofs=110000
    done ;;
  cost)
    for n in 1 2 4; do
      for s in MUMPS Iterative; do  # one process per solver: peak memory is per process
        sc_mpiexec -n $n "$B" --dim=2 --solvers=$s --min-dofs=40000 --max-dofs="${SC_STUDY_MAX_2D:-800000}"
        sc_mpiexec -n $n "$B" --dim=3 --solvers=$s --min-dofs=30000 --max-dofs="${SC_STUDY_MAX_3D:-300000}"
      done
    done ;;
  *) echo "solver-study: unknown study '$what' (iterations, cost)" >&2; exit 1 ;;
esac
uptime
