# cmake -DAPP=stresscontact -DCHECK=check_summary -DDECK=input/hertz2d.xml -DOUT=dir -P this
# Mesh/Memory limit (GB) counts all the run's memory, the program's own included (docs/mesh.md
# "Resource limits"):
# 1. A limit below what the program holds before any mesh (VmRSS, here about 0.11 GB on 1 rank) is
#    an input error naming the key, that baseline and a valid value (unchecked, 0.1 GB is accepted
#    and the run peaks at 0.278 GB).
# 2. With the limit 0.15 GB above that baseline (read from the message of 1, since it depends on
#    the build and the machine), the adaptive run stops on memory before a cycle would exceed the
#    limit, and its peak resident memory (summary.json, all ranks) stays within 5% of the limit
#    (measured: a peak of 0.250 GB under 0.262 GB, 2026-12-03; a forecast of the mesh, matrices and solver
#    alone lets hertz2d.xml peak at 0.278 GB under a limit of 0.1 GB).
execute_process(COMMAND ${APP} --check ${DECK} --set "Mesh/Memory limit (GB)=0.001"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
message("${out}")
set(regex "'Mesh/Memory limit \\(GB\\)' = 0.001 is below the memory the program holds before any mesh is made: ([0-9]+)\\.?([0-9]*) GB \\(VmRSS of /proc/self/status, summed over the 1 rank: libraries, MPI, Kokkos\\)\\. The limit covers that memory and the run's data on top of it .* Give more than [0-9.]+ GB, e\\.g\\. [0-9.]+ \\(about [0-9.]+ GB for the run's data\\), or 0 for the memory available")
if(NOT rc STREQUAL "1" OR NOT "${out}" MATCHES "${regex}")
  message(FATAL_ERROR "expected exit status 1 and the message ${regex}; got status ${rc}")
endif()
# The baseline in micro-GB (integer arithmetic: CMake has no floating point).
string(SUBSTRING "${CMAKE_MATCH_2}000000" 0 6 fraction)
math(EXPR baseline "${CMAKE_MATCH_1} * 1000000 + 1${fraction} - 1000000")
math(EXPR limit "${baseline} + 150000")
math(EXPR whole "${limit} / 1000000")
math(EXPR fraction "1000000 + ${limit} % 1000000")
string(SUBSTRING "${fraction}" 1 6 fraction)
set(limitGB "${whole}.${fraction}")
math(EXPR peakMB "${limit} * 1050 / 1048576")  # 1.05 × the limit, in the MB (2^20) of summary.json
message("baseline ${baseline} micro-GB: limit ${limitGB} GB, peak allowed ${peakMB} MB")

file(REMOVE_RECURSE "${OUT}")
execute_process(COMMAND ${APP} ${DECK} --set "Mesh/Memory limit (GB)=${limitGB}" --output ${OUT}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
message("${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the run with the limit ${limitGB} GB failed with status ${rc}")
endif()
set(stop "stop \\| memory: the next mesh would have about [0-9.e+]+ DOFs needing about [0-9.]+ GB, above the memory limit of [0-9.]+ GB \\('Mesh/Memory limit \\(GB\\)', of which the program held [0-9.]+ GB before the mesh \\(VmRSS, 1 rank\\)\\)")
if(NOT "${out}" MATCHES "${stop}")
  message(FATAL_ERROR "the run did not stop on memory: ${stop}")
endif()
execute_process(COMMAND ${CHECK} ${OUT}/summary.json "eq:/converged=true"
                        "exists:/cycles/-1/stop_reason" "le:/cycles/-1/memory/peak_rss_sum_mb=${peakMB}"
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "summary.json checks failed")
endif()
