#include "sc/core/Progress.hpp"

#include <cstdio>
#include <iomanip>

#include <Teuchos_Time.hpp>

namespace sc::core {

Progress::Progress(Teuchos::RCP<const Teuchos::Comm<int>> comm, std::ostream& out, bool quiet)
    : out_(out), rank_(comm->getRank()), quiet_(quiet), start_(Teuchos::Time::wallTime())
{
}

void Progress::setCycle(int cycle, int totalCycles)
{
  cycle_ = cycle;
  totalCycles_ = totalCycles;
}

void Progress::report(const std::string& phase, const std::string& detail) const
{
  if (rank_ != 0 || quiet_) return;
  char stamp[32];
  std::snprintf(stamp, sizeof(stamp), "[%9.2f s] ", Teuchos::Time::wallTime() - start_);
  out_ << stamp;
  if (cycle_ >= 0) out_ << "cycle " << cycle_ << "/" << totalCycles_ << " | ";
  out_ << phase;
  if (!detail.empty()) out_ << " | " << detail;
  out_ << std::endl;
}

void Progress::message(const std::string& text) const
{
  if (rank_ == 0 && !quiet_) out_ << text << std::endl;
}

}  // namespace sc::core
