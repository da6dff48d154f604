// The load steps of a run (docs/theory.md §"Load steps"): each step's loads made current, the
// loop over the steps (each an adaptive loop; a restart continues the checkpoint's step), and
// the step's record in summary.json (docs/output.md).
#include "Simulation.hpp"

#include <sstream>

#include <nlohmann/json.hpp>

#include <sc/adapt/AdaptiveLoop.hpp>
#include <sc/contact/ContactProblem.hpp>
#include <sc/core/Expression.hpp>
#include <sc/io/RunSummary.hpp>
#include <sc/mesh/SimplexMesh.hpp>

#include "CycleResults.hpp"

namespace sc::app {

void Simulation::applyLoadStep(int step)
{
  loadStep_ = step;
  auto loads = settings_.atStep(step);
  boundaryConditions_ = std::move(loads.conditions);
  bodyForce_ = std::move(loads.bodyForce);
  core::Expression::setLoadTime(settings_.loadSteps.times[step]);
  if (!boundaryConditions_.hasContact()) return;
  contact_ = std::move(loads.contact);
  balancedStopping_.setDiscretisationError(-1.0);  // η of another load is not this step's
}

std::string Simulation::runLoadSteps(int firstCycle, std::vector<int> marked)
{
  std::string stopReason;
  // The load steps (docs/theory.md §"Load steps"), from the first, or from the checkpoint's
  // (resume_): each step after the first starts from the last mesh and contact state of the
  // step before, whose r_T becomes the friction history. A restart continues a step from the
  // checkpoint's cycle, or starts the next step when the checkpoint is of a step's last cycle.
  for (int step = resume_.step; step < settings_.loadSteps.numSteps(); ++step) {
    const bool continues = step == resume_.step && !resume_.startsStep;
    if (step > 0) {
      applyLoadStep(step);
      std::ostringstream os;
      os << "load step " << step + 1 << " of " << settings_.loadSteps.numSteps()
         << ", t = " << settings_.loadSteps.times[step];
      progress_.message(os.str());
    }
    if (step > 0 && !continues && contactProblem_)
      contactProblem_->commitLoadStep(*mesh_);  // the same mesh, r_T the friction history
    stepFirstCycle_ = continues ? resume_.stepFirstCycle : lastCycle_ + 1;
    adapt::AdaptiveLoop& loop = step == 0 ? *loop_ : *laterStepLoop_;
    if (continues)
      stopReason =
          loop.run(*this, firstCycle - stepFirstCycle_, std::move(marked), stepFirstCycle_);
    else
      stopReason = loop.run(*this, 0, {}, stepFirstCycle_);
    // The next step can start from here: a checkpoint of the step's last cycle (the loop
    // writes none for the cycle it stops at).
    if (step + 1 < settings_.loadSteps.numSteps()) timedCheckpoint(lastCycle_, {}, true);
  }
  return stopReason;
}

void Simulation::recordLoadStep()
{
  // Load steps (docs/output.md): the step and its time, and the 2D stick zone's two ends
  // (after a tangential step the zone is not centred).
  auto& c = summary_->currentCycle();
  c["load_step"] = {{"step", loadStep_ + 1}, {"time", settings_.loadSteps.times[loadStep_]}};
  // The values the step prescribes from tables (Values per step, Obstacle displacement).
  auto& prescribed = c["load_step"]["prescribed"];
  prescribed = nlohmann::ordered_json::object();
  for (const auto& bc : boundaryConditions_.conditions)
    if (!settings_.conditions.find(bc.boundary)->valuesPerStep.empty())
      prescribed[bc.boundary] = bc.value;
  if (!settings_.bodyForce.valuesPerStep.empty()) prescribed["body_force"] = bodyForce_.value;
  if (!settings_.loadSteps.obstacleDisplacement.empty())
    prescribed["obstacle"] =
        settings_.loadSteps.obstacleDisplacementAt(loadStep_, settings_.problem.dimension);
  if (results_->contact && settings_.problem.dimension == 2) {
    // The ends as coordinates along the plane's direction τ = (ν_y, −ν_x) (x for ν = (0, 1)):
    // the summary's ends are signed coordinates s along −τ = (−ν_y, ν_x) from the zone's
    // centre, so the end at s lies at centre·τ − s.
    const auto& cs = results_->contact->summary;
    const auto& nu = contact_.obstacleNormal;
    const double centre = cs.center[0] * nu[1] - cs.center[1] * nu[0];
    c["contact"]["stick_zone_ends"] = {centre - cs.stickZoneEnds[1], centre - cs.stickZoneEnds[0]};
  }
}

}  // namespace sc::app
