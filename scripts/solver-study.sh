#!/usr/bin/env bash
# The Krylov solver study of docs/solvers.md, from an existing build:
#   scripts/solver-study.sh iterations   # MINRES iterations: levels x ν, exact S_σ and multigrid
#   scripts/solver-study.sh cost         # time and peak memory vs DOFs: MUMPS, Iterative with the
#                                        # exact S_σ, Iterative with multigrid; 1, 2 and 4 ranks
#   scripts/solver-study.sh large        # 3D at 2·10⁶ DOFs: multigrid at 1, 2, 4 ranks, and MUMPS
#                                        # under a memory limit (SC_STUDY_MEMORY_GB, default 22)
#   scripts/solver-study.sh contact      # Hertz 2D adaptive (14 cycles), Stress block = Multigrid:
#                                        # Krylov iterations per Newton step and cycle, frictionless
#                                        # and Coulomb, ν = 0.28 and 0.4999 (1 rank)
# Output: the benchmark lines (one per size and solver) with `uptime` before and after each run.
# SC_BUILD_DIR as in common.sh; SC_STUDY_MAX_2D / SC_STUDY_MAX_3D bound the sizes of "cost".
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
B="$SC_BUILD_DIR/packages/assembly/elasticity_benchmark"
[ -x "$B" ] || { echo "solver-study: $B not built (cmake --build $SC_BUILD_DIR --target elasticity_benchmark)" >&2; exit 1; }
what=${1:-iterations}
run() { uptime; "$@"; uptime; }
case "$what" in
  iterations)
    for nu in 0.3 0.49 0.4999 0.5; do
      for sb in MUMPS Multigrid; do
        run "$B" --dim=2 --solvers=Iterative --stress-block=$sb --nu=$nu --max-dofs=200000
        run "$B" --dim=3 --solvers=Iterative --stress-block=$sb --nu=$nu --max-dofs=300000
        run "$B" --dim=2 --degree=2 --solvers=Iterative --stress-block=$sb --nu=$nu --max-dofs=110000
      done
    done ;;
  cost)
    for n in 1 2 4; do
      for s in MUMPS Iterative:MUMPS Iterative:Multigrid; do  # one process per solver: peak memory
        solver=${s%%:*}; sb=${s#*:}; [ "$sb" = "$s" ] && sb=MUMPS
        run sc_mpiexec -n $n "$B" --dim=2 --solvers=$solver --stress-block=$sb --min-dofs=40000 --max-dofs="${SC_STUDY_MAX_2D:-800000}"
        run sc_mpiexec -n $n "$B" --dim=3 --solvers=$solver --stress-block=$sb --min-dofs=30000 --max-dofs="${SC_STUDY_MAX_3D:-300000}"
      done
    done ;;
  large)
    kb=$(( ${SC_STUDY_MEMORY_GB:-22} * 1024 * 1024 ))
    for n in 1 2 4; do  # the memory limit is per process: the total is shared by the ranks
      ( ulimit -v $(( kb / n )); run sc_mpiexec -n $n "$B" --dim=3 --solvers=Iterative --stress-block=Multigrid --min-dofs=1000000 --max-dofs=2500000 )
    done
    ( ulimit -v $kb; run sc_mpiexec -n 1 "$B" --dim=3 --solvers=MUMPS --min-dofs=1000000 --max-dofs=2500000 ) ;;
  contact)
    app="$SC_BUILD_DIR/apps/stresscontact/stresscontact"
    out=$(mktemp -d)
    for law in None Coulomb; do
      for nu in 0.28 0.4999; do
        echo "== Hertz 2D, Friction law = $law, nu = $nu"
        uptime
        rc=0
        "$app" "$SC_ROOT/input/hertz2d.xml" --set "Contact/Friction law=$law" \
          --set "Material/Poisson ratio=$nu" --set "Adaptivity/Cycles=${SC_STUDY_CYCLES:-14}" \
          --set "Linear Solver/Type=Iterative" --set "Linear Solver/Iterative/Stress block=Multigrid" \
          --set "Output/Directory=$out/run" > "$out/log" 2>&1 || rc=$?
        uptime
        [ $rc -eq 0 ] || echo "  exit $rc: $(grep -v '^-*$' "$out/log" | tail -1)"
        echo "  semismooth Newton failures (fixed-point fallback): $(grep -c 'falling back to the Coulomb fixed point' "$out/log" || true)"
        [ -f "$out/run/summary.json" ] || continue
        grep -o 'stress multigrid: .*' "$out/log" | sed 's/^/  /' > "$out/levels"
        /usr/bin/python3 - "$out/run/summary.json" "$out/levels" <<'PY'
import json, sys
cycles = json.load(open(sys.argv[1]))["cycles"]
levels = open(sys.argv[2]).read().splitlines()
for i, c in enumerate(cycles):
    print(f"cycle {i:2d} DOFs {c['dofs']['total']:7d} iterations {c['linear_iterations']['per_solve']} {levels[i].strip() if i < len(levels) else ''}")
PY
      done
    done
    rm -rf "$out" ;;
  *) echo "solver-study: unknown study '$what' (iterations, cost, large, contact)" >&2; exit 1 ;;
esac
