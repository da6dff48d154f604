#pragma once
// Floating-point exception trapping for tests and debugging (docs/reliability.md "Floating-point
// traps"). With SC_TRAP_FPE=1 in the environment, an invalid operation (0/0, inf − inf, a
// comparison with a NaN, sqrt(−1)), a division by zero or an overflow raises SIGFPE at the
// instruction that produced it, instead of a NaN or inf spreading silently. Inexact results and
// underflow are normal in the solvers and are never trapped. CTest sets SC_TRAP_FPE=1 for every
// test (cmake/StressContactHelpers.cmake).

namespace sc::core {

/// Trap FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW on this thread if the environment variable
/// SC_TRAP_FPE is set to 1, and print a backtrace on SIGFPE. Call after MPI and Kokkos are
/// initialised (their start-up is not ours to check). Returns whether trapping is on.
bool enableFloatingPointTrapsFromEnvironment();

/// Trap those exceptions (glibc feenableexcept) and install the SIGFPE reporter.
void enableFloatingPointTraps();

/// Scope in which trapping is off, for a call into a third-party library that legitimately
/// produces such exceptions internally; restores the previous trap mask and clears the flags it
/// raised when the scope ends.
class FloatingPointTrapsSuspended {
public:
  FloatingPointTrapsSuspended();
  ~FloatingPointTrapsSuspended();
  FloatingPointTrapsSuspended(const FloatingPointTrapsSuspended&) = delete;
  FloatingPointTrapsSuspended& operator=(const FloatingPointTrapsSuspended&) = delete;

private:
  int saved_;
};

}  // namespace sc::core
