#!/usr/bin/env bash
# The elasticity_benchmark tables of docs/benchmarks.md ("Mixed elasticity: assembly and direct
# solves"), from an existing build: MUMPS at 1 rank over the sizes, the largest sizes at 1, 2 and
# 4 ranks, KLU2 against MUMPS. One run at a time at nice 10, `uptime` before each run and at the
# end. Peak memory about 3.5 GB (3D, 478k DOFs, 1 rank); about 5 minutes on an idle machine.
#   scripts/elasticity-benchmark.sh
# SC_BUILD_DIR as in common.sh.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
B="$SC_BUILD_DIR/packages/assembly/elasticity_benchmark"
[ -x "$B" ] || { echo "elasticity-benchmark: $B not built (cmake --build $SC_BUILD_DIR --target elasticity_benchmark)" >&2; exit 1; }
renice -n 10 $$ > /dev/null  # this script and every run it starts
run() { uptime; "$@"; }
# MUMPS, 1 rank, every size
run sc_mpiexec -n 1 "$B" --max-dofs=800000 --solvers=MUMPS
run sc_mpiexec -n 1 "$B" --dim=3 --max-dofs=300000 --solvers=MUMPS
run sc_mpiexec -n 1 "$B" --dim=3 --mesh-size=0.4 --max-dofs=600000 --solvers=MUMPS
# The largest sizes at 2 and 4 ranks (4 ranks oversubscribe a 2-core machine)
for n in 2 4; do
  run sc_mpiexec -n $n "$B" --min-dofs=700000 --max-dofs=800000 --solvers=MUMPS
  run sc_mpiexec -n $n "$B" --dim=3 --min-dofs=200000 --max-dofs=300000 --solvers=MUMPS
  run sc_mpiexec -n $n "$B" --dim=3 --mesh-size=0.4 --min-dofs=400000 --max-dofs=600000 --solvers=MUMPS
done
# KLU2 against MUMPS, 1 rank
run sc_mpiexec -n 1 "$B" --max-dofs=50000 --solvers=KLU2,MUMPS
run sc_mpiexec -n 1 "$B" --dim=3 --max-dofs=34000 --solvers=KLU2,MUMPS
run sc_mpiexec -n 1 "$B" --dim=3 --mesh-size=0.4 --max-dofs=9000 --solvers=KLU2,MUMPS
uptime
