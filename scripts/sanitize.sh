#!/usr/bin/env bash
# Hardening runs (docs/reliability.md "Sanitizers" and "Fuzzing").
# Not part of CI: a cold sanitizer build takes about 25 minutes on 2 cores.
#
#   scripts/sanitize.sh test [ctest args]   build everything with clang + AddressSanitizer +
#                                           UBSan and run the whole CTest suite under them
#   scripts/sanitize.sh fuzz [SECONDS [TARGET...]]
#                                           build the libFuzzer targets (same build) and run each
#                                           (default: all five targets) for SECONDS
#                                           (default 600), starting from its seed corpus
#
# One build directory serves both ($SC_BUILD_DIR, default <repo>/build-asan): clang is needed for
# libFuzzer, and the fuzz targets are sanitized too. Environment: SC_JOBS (default 2),
# SC_BUILD (the build command, default "cmake --build"; e.g. a lock wrapper on a shared machine).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
SC_BUILD_DIR=${SC_BUILD_DIR_ASAN:-$SC_ROOT/build-asan}
SC_BUILD=${SC_BUILD:-cmake --build}
mode=${1:-test}
shift || true

# Debian 12: clang 14 and its compiler-rt (libFuzzer, ASan/UBSan runtimes).
SC_DEBIAN_PACKAGES+=(clang libclang-rt-14-dev)
sc_install_dependencies

if [ ! -f "$SC_BUILD_DIR/build.ninja" ]; then
  # -O2 with line tables only: sanitizer reports name file:line, and the Tpetra-heavy files
  # compile far faster than with full debug information.
  sc_log "configuring $SC_BUILD_DIR (clang, -O2 with line tables, ASan + UBSan, fuzz targets)"
  CC=clang CXX=clang++ cmake -S "$SC_ROOT" -B "$SC_BUILD_DIR" -G Ninja \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -gline-tables-only -DNDEBUG" \
    -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O2 -gline-tables-only -DNDEBUG" \
    -DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache \
    -DCMAKE_INSTALL_PREFIX="$SC_BUILD_DIR/install" \
    -DSC_ENABLE_SANITIZERS=ON -DSC_ENABLE_FUZZING=ON -DSC_ENABLE_BENCHMARKS=ON
fi

# Sanitizer settings (docs/reliability.md "Sanitizers"): stop at the first report with a stack;
# leak checking off (every MPI program leaks inside Open MPI at MPI_Finalize, in MCA plugins
# whose frames LeakSanitizer cannot name, so no suppression can match them); reports of
# uninstrumented third-party code, if any, go to the suppressions files with the reason.
export ASAN_OPTIONS="halt_on_error=1:abort_on_error=1:detect_leaks=0:suppressions=$SC_ROOT/tests/sanitizers/asan.supp"
export SC_TRAP_FPE=1  # floating-point traps in the fuzzers too (CTest sets it for every test)
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:suppressions=$SC_ROOT/tests/sanitizers/ubsan.supp"

case "$mode" in
  test)
    sc_log "building all targets in $SC_BUILD_DIR"
    $SC_BUILD "$SC_BUILD_DIR" -j "$SC_JOBS"
    cd "$SC_BUILD_DIR"
    ctest --output-on-failure -j "$SC_JOBS" --timeout 1800 "$@"
    ;;
  fuzz)
    seconds=${1:-600}
    shift || true
    targets=("$@")
    [ ${#targets[@]} -gt 0 ] || targets=(fuzz_deck fuzz_set fuzz_gmsh fuzz_checkpoint fuzz_expression)
    $SC_BUILD "$SC_BUILD_DIR" -j "$SC_JOBS" --target fuzz_targets
    for target in "${targets[@]}"; do
      work="$SC_BUILD_DIR/fuzz/$target"
      mkdir -p "$work/corpus" "$work/artifacts"
      sc_log "fuzzing $target for $seconds s (corpus $work/corpus, seeds tests/fuzz/corpus/$target)"
      # -timeout: an input taking longer than 10 s is a hang; -rss_limit_mb: more is a finding.
      (cd "$work" && "$SC_BUILD_DIR/tests/fuzz/$target" -max_total_time="$seconds" -timeout=10 \
          -rss_limit_mb=4096 -print_final_stats=1 -artifact_prefix="$work/artifacts/" \
          "$work/corpus" "$SC_ROOT/tests/fuzz/corpus/$target" 2>&1 | tee "$work/log.txt" | \
          grep -E '^#[0-9]+[[:space:]]+(INITED|DONE)|^(stat::|==[0-9]+==|SUMMARY|artifact_prefix|Test unit written)' )
    done
    ;;
  *)
    echo "usage: $0 test [ctest args] | fuzz [SECONDS]" >&2
    exit 2
    ;;
esac
