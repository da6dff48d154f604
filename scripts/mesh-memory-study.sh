#!/usr/bin/env bash
# The replicated-mesh memory study of docs/architecture.md ("Replicated mesh: memory per rank"),
# from an existing build: mesh_memory_benchmark at 1 and 2 ranks, one run at a time at nice 10,
# with `uptime` and `free -m` before each run. The largest runs need about 3 GB per rank (2D,
# 1.1·10⁷ triangles without the DOF numbering; 3D, 1.6·10⁶ tetrahedra with it), 6.5 GB in all.
#   scripts/mesh-memory-study.sh
# SC_BUILD_DIR as in common.sh.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
B="$SC_BUILD_DIR/packages/assembly/mesh_memory_benchmark"
[ -x "$B" ] || { echo "mesh-memory-study: $B not built (cmake --build $SC_BUILD_DIR --target mesh_memory_benchmark)" >&2; exit 1; }
renice -n 10 $$ > /dev/null  # this script and every run it starts
run() { uptime; free -m | sed -n 2p; "$@"; }
for n in 1 2; do
  # 2D: 1.08·10⁶ and 4.33·10⁶ triangles with the numbering, 1.10·10⁷ without it (the numbering of
  # 1.1·10⁷ triangles needs about 8.5 GB per rank: projected from the two smaller sizes).
  run sc_mpiexec -n $n "$B" --dim=2 --elements=1000000 --mesh-size=0.21
  run sc_mpiexec -n $n "$B" --dim=2 --elements=4000000 --mesh-size=0.21
  run sc_mpiexec -n $n "$B" --dim=2 --elements=10000000 --mesh-size=0.27 --no-numbering
  # 3D: 1.59·10⁶ tetrahedra with the numbering, 6.68·10⁶ without it.
  run sc_mpiexec -n $n "$B" --dim=3 --elements=1000000 --mesh-size=0.33
  run sc_mpiexec -n $n "$B" --dim=3 --elements=6000000 --mesh-size=0.34 --no-numbering
done
uptime
