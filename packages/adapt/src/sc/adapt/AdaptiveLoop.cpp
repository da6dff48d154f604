#include "sc/adapt/AdaptiveLoop.hpp"

#include <algorithm>
#include <optional>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_Time.hpp>

#include <sc/adapt/Marker.hpp>
#include <sc/adapt/StopCriteria.hpp>
#include <sc/core/Error.hpp>
#include <sc/core/Progress.hpp>
#include <sc/core/Timers.hpp>

namespace sc::adapt {

AdaptiveLoop::AdaptiveLoop(const AdaptivitySettings& settings,
                           Teuchos::RCP<const Teuchos::Comm<int>> comm, core::Progress* progress,
                           core::PhaseTimers* timers)
    : settings_(settings), comm_(std::move(comm)), progress_(progress), timers_(timers),
      marker_(createMarker(settings)), stop_(std::make_unique<StopCriteria>(settings)),
      startTime_(Teuchos::Time::wallTime())
{
  SC_THROW_IF(comm_.is_null(), core::InternalError, "AdaptiveLoop needs a communicator");
  // Rank 0's clock, as for every time of the budget: each rank's decision must be the same.
  Teuchos::broadcast<int, double>(*comm_, 0, &startTime_);
}

AdaptiveLoop::~AdaptiveLoop() = default;

std::string AdaptiveLoop::run(AdaptiveProblem& problem, int firstCycle,
                              std::vector<int> markedBeforeFirstCycle, int cycleOffset)
{
  SC_THROW_IF(firstCycle < 0, core::InternalError, "first cycle " << firstCycle);
  Marking marking;
  marking.uniform = !settings_.needsIndicators();
  if (!marking.uniform) marking.elements = std::move(markedBeforeFirstCycle);
  // The time budget: rank 0's clock, so that every rank takes the same decision.
  const auto now = [this] {
    double t = Teuchos::Time::wallTime();
    Teuchos::broadcast<int, double>(*comm_, 0, &t);
    return t;
  };
  double previousDecision = now();
  long long previousDofs = 0;
  for (int cycle = firstCycle;; ++cycle) {
    const int global = cycle + cycleOffset;  // the number the problem's steps see
    if (progress_) progress_->setCycle(global, settings_.cycles + cycleOffset);
    if (cycle > 0) problem.refine(marking);
    problem.solve(global);
    const CycleEstimate estimate = problem.estimate(global);
    std::string reason =
        stop_->reason(cycle, estimate.dofs, estimate.available ? estimate.eta : -1.0,
                      estimate.available ? estimate.norm : -1.0);
    // Accuracy targets (all met: stop), or say which are not met when stopping for another reason.
    if (reason.empty())
      reason = stop_->targetsReason(estimate.quantities);
    else
      reason += stop_->unmetTargets(estimate.quantities);
    marking = Marking();
    marking.uniform = !settings_.needsIndicators();
    if (reason.empty()) {
      marking = mark(estimate);
      const NextMeshForecast next = problem.forecastNextMesh(marking);
      reason = stop_->memoryReason(next.dofs, next.bytes, next.limitBytes, next.limitSource);
      if (!reason.empty()) reason += stop_->unmetTargets(estimate.quantities);
    }
    // The time budget: the next cycle is forecast from this one's time (since the last
    // decision: this cycle's refine, solve, estimate and the previous cycle's output) scaled by
    // the growth of the DOFs over this cycle.
    const double decision = now();
    if (reason.empty()) {
      const double growth =
          previousDofs > 0 && estimate.dofs > previousDofs
              ? static_cast<double>(estimate.dofs) / static_cast<double>(previousDofs)
              : 1.0;
      reason = stop_->budgetReason(decision - startTime_, (decision - previousDecision) * growth,
                                   estimate.quantities);
    }
    previousDecision = decision;
    previousDofs = estimate.dofs;
    if (!reason.empty()) marking.elements.clear();  // nothing is refined after the last cycle
    problem.output(global, marking, reason);
    if (!reason.empty()) {
      if (progress_) progress_->report("stop", reason);
      return reason;
    }
    // The next cycle can start from here (a run that stops now needs no checkpoint).
    problem.checkpoint(global, marking);
  }
}

Marking AdaptiveLoop::mark(const CycleEstimate& estimate) const
{
  Marking marking;
  marking.uniform = !settings_.needsIndicators();
  if (marking.uniform) return marking;
  SC_THROW_IF(!estimate.available, core::InternalError,
              "'Adaptivity/Marking' = "
                  << settings_.marking
                  << " needs element indicators, but the cycle has no estimate");
  std::optional<core::PhaseTimers::Scope> t;
  if (timers_) t.emplace(*timers_, "mark");
  marking.elements =
      marker_->mark(estimate.numElements, estimate.ownedElements, estimate.indicators, *comm_);
  t.reset();
  if (progress_)
    progress_->report("mark", marker_->name() + ": " + std::to_string(marking.elements.size()) +
                                  " of " + std::to_string(estimate.numElements) + " elements");
  return marking;
}

}  // namespace sc::adapt
