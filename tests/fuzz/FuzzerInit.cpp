// libFuzzer's start-up hook for the fuzz_<target> programs: floating-point exceptions trap under
// SC_TRAP_FPE=1 (scripts/sanitize.sh sets it), so that a NaN, a division by zero or an overflow
// in the code under test is a finding (libFuzzer reports SIGFPE as a crash).
#include <sc/core/FloatingPointTraps.hpp>

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  sc::core::enableFloatingPointTrapsFromEnvironment();
  return 0;
}
