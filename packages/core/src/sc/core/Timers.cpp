#include "sc/core/Timers.hpp"

#include "sc/core/Collective.hpp"

#include <sys/resource.h>

#include <Teuchos_TimeMonitor.hpp>

namespace sc::core {

PhaseTimers::PhaseTimers(Teuchos::RCP<const Teuchos::Comm<int>> comm)
    : comm_(std::move(comm)), start_(Teuchos::Time::wallTime())
{
}

PhaseTimers::Scope::Scope(PhaseTimers& owner, std::string phase)
    : owner_(owner), phase_(std::move(phase)),
      teuchosTimer_(Teuchos::TimeMonitor::getNewCounter("StressContact: " + phase_)),
      start_(Teuchos::Time::wallTime())
{
  teuchosTimer_->start();
}

PhaseTimers::Scope::~Scope()
{
  teuchosTimer_->stop();
  if (owner_.current_.find(phase_) == owner_.current_.end()) owner_.order_.push_back(phase_);
  owner_.current_[phase_] += Teuchos::Time::wallTime() - start_;
}

void PhaseTimers::nextCycle() { current_.clear(); }

std::map<std::string, double> PhaseTimers::cycleTimings() const
{
  // Phases are the same on every rank (the driver runs the same phases everywhere), so the
  // reduction over a std::map's values in key order is consistent.
  std::vector<double> local;
  for (const auto& [name, seconds] : current_)
    local.push_back(seconds);
  std::vector<double> global(local.size(), 0.0);
  maxOverRanks(*comm_, static_cast<int>(local.size()), local.data(), global.data());
  std::map<std::string, double> result;
  std::size_t i = 0;
  for (const auto& kv : current_)
    result[kv.first] = global[i++];
  return result;
}

double PhaseTimers::elapsed() const { return Teuchos::Time::wallTime() - start_; }

PhaseTimers::PeakMemory PhaseTimers::peakMemory() const
{
  struct rusage usage {};
  getrusage(RUSAGE_SELF, &usage);
  const double local = static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux: kB
  PeakMemory result;
  result.maxMB = maxOverRanks(*comm_, local);
  result.sumMB = sumOverRanks(*comm_, local);
  return result;
}

}  // namespace sc::core
