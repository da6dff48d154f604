#include "sc/core/FloatingPointTraps.hpp"

#include <cfenv>
#include <csignal>
#include <cstdlib>
#include <cstring>

#include <execinfo.h>
#include <unistd.h>

namespace sc::core {
namespace {

constexpr int kTrapped = FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW;

void write(const char* text)
{
  [[maybe_unused]] auto n = ::write(STDERR_FILENO, text, std::strlen(text));
}

// Async-signal-safe as far as glibc allows: write(2) and backtrace_symbols_fd only.
void reportFloatingPointException(int, siginfo_t* info, void*)
{
  const char* what = "floating-point exception";
  switch (info ? info->si_code : 0) {
  case FPE_FLTINV:
    what = "invalid floating-point operation (0/0, inf-inf, a NaN compared, ...)";
    break;
  case FPE_FLTDIV: what = "floating-point division by zero"; break;
  case FPE_FLTOVF: what = "floating-point overflow"; break;
  case FPE_INTDIV: what = "integer division by zero"; break;
  default: break;
  }
  write("\nstresscontact: SIGFPE trapped (SC_TRAP_FPE=1): ");
  write(what);
  write("\nbacktrace:\n");
  void* frames[64];
  backtrace_symbols_fd(frames, backtrace(frames, 64), STDERR_FILENO);
  std::signal(SIGFPE, SIG_DFL);
  std::raise(SIGFPE);
}

}  // namespace

void enableFloatingPointTraps()
{
  struct sigaction action;
  std::memset(&action, 0, sizeof action);
  action.sa_sigaction = reportFloatingPointException;
  action.sa_flags = SA_SIGINFO | SA_RESETHAND;
  sigaction(SIGFPE, &action, nullptr);
  std::feclearexcept(FE_ALL_EXCEPT);
  feenableexcept(kTrapped);
}

bool enableFloatingPointTrapsFromEnvironment()
{
  const char* env = std::getenv("SC_TRAP_FPE");
  if (!env || std::strcmp(env, "1") != 0) return false;
  enableFloatingPointTraps();
  return true;
}

FloatingPointTrapsSuspended::FloatingPointTrapsSuspended() : saved_(fegetexcept())
{
  fedisableexcept(kTrapped);
}

FloatingPointTrapsSuspended::~FloatingPointTrapsSuspended()
{
  std::feclearexcept(kTrapped);
  feenableexcept(saved_);
}

}  // namespace sc::core
