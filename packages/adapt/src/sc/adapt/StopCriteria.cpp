#include "sc/adapt/StopCriteria.hpp"

#include <cmath>
#include <sstream>
#include <tuple>
#include <utility>

#include <sc/core/Error.hpp>

namespace sc::adapt {

StopCriteria::StopCriteria(const AdaptivitySettings& s) : settings_(s)
{
  SC_THROW_IF(!(s.targetError >= 0.0), core::InputError,
              "'Adaptivity/Target error' = " << s.targetError << ": valid range [0, inf).");
  SC_THROW_IF(s.maxDofs < 1, core::InputError,
              "'Adaptivity/Max DOFs' = " << s.maxDofs << ": valid range [1, 2147483647].");
  SC_THROW_IF(s.cycles < 0, core::InputError,
              "'Adaptivity/Cycles' = " << s.cycles << ": valid range [0, 100].");
  for (const auto& [key, value] : {std::pair{"Target force error", s.targetForceError},
                                   {"Target width error", s.targetWidthError},
                                   {"Target pressure error", s.targetPressureError},
                                   {"Target stick width error", s.targetStickError}})
    SC_THROW_IF(!(value >= 0.0 && value <= 1.0), core::InputError,
                "'Adaptivity/" << key << "' = " << value
                               << ": valid range [0, 1] (relative; 0: no target).");
  SC_THROW_IF(!(s.timeBudget >= 0.0), core::InputError,
              "'Adaptivity/Time budget' = " << s.timeBudget
                                            << ": valid range [0, inf) seconds (0: none).");
}

std::vector<TargetStatus>
StopCriteria::targets(const std::vector<QuantityEstimate>& quantities) const
{
  std::vector<TargetStatus> out;
  for (const auto& [name, key, target] :
       {std::tuple{"force", "Target force error", settings_.targetForceError},
        {"width", "Target width error", settings_.targetWidthError},
        {"pressure", "Target pressure error", settings_.targetPressureError},
        {"stick width", "Target stick width error", settings_.targetStickError}}) {
    if (!(target > 0.0)) continue;
    TargetStatus t;
    t.name = name;
    t.key = std::string("Adaptivity/") + key;
    t.target = target;
    for (const auto& q : quantities)
      if (q.name == name && q.error >= 0.0 && q.value != 0.0)
        t.relativeError = q.error / std::abs(q.value);
    t.met = t.relativeError >= 0.0 && t.relativeError <= target;
    out.push_back(t);
  }
  return out;
}

namespace {

/// "force 2.1e-04 <= 1e-03, width 2.3e-02 > 1e-02 (Target width error), ..." over `list`.
std::string describe(const std::vector<TargetStatus>& list)
{
  std::ostringstream os;
  os.precision(2);
  bool first = true;
  for (const auto& t : list) {
    os << (first ? "" : ", ") << t.name << " ";
    first = false;
    if (t.relativeError < 0.0)
      os << "not estimated yet";
    else
      os << std::scientific << t.relativeError << std::defaultfloat << (t.met ? " <= " : " > ")
         << t.target;
  }
  return os.str();
}

}  // namespace

std::string StopCriteria::targetsReason(const std::vector<QuantityEstimate>& quantities) const
{
  const auto list = targets(quantities);
  if (list.empty()) return "";
  for (const auto& t : list)
    if (!t.met) return "";
  return "accuracy targets met (estimated relative errors): " + describe(list);
}

std::string StopCriteria::unmetTargets(const std::vector<QuantityEstimate>& quantities) const
{
  const auto list = targets(quantities);
  std::vector<TargetStatus> unmet;
  for (const auto& t : list)
    if (!t.met) unmet.push_back(t);
  if (unmet.empty()) return "";
  return "; accuracy targets not met (estimated relative errors): " + describe(unmet);
}

std::string StopCriteria::budgetReason(double elapsed, double nextSeconds,
                                       const std::vector<QuantityEstimate>& quantities) const
{
  if (!(settings_.timeBudget > 0.0) || elapsed + nextSeconds <= settings_.timeBudget) return "";
  std::ostringstream os;
  os.precision(3);
  os << "time budget: the next cycle would end at about " << elapsed + nextSeconds
     << " s (this cycle's time scaled by the DOFs' growth), beyond Time budget = "
     << settings_.timeBudget << " s; this cycle is the best within the budget"
     << unmetTargets(quantities);
  return os.str();
}

std::string StopCriteria::reason(int cycle, long long dofs, double eta, double stressNorm) const
{
  std::ostringstream os;
  if (cycle >= settings_.cycles)
    os << "Cycles = " << settings_.cycles << " reached";
  else if (dofs >= settings_.maxDofs)
    os << dofs << " DOFs >= Max DOFs = " << settings_.maxDofs;
  else if (settings_.targetError > 0.0 && eta >= 0.0 && stressNorm >= 0.0 &&
           eta <= settings_.targetError * stressNorm)
    os << "eta = " << eta << " <= Target error " << settings_.targetError
       << " x |A^1/2 sigma_h| = " << settings_.targetError * stressNorm;
  return os.str();
}

std::string StopCriteria::memoryReason(double nextDofs, double nextBytes, double limitBytes,
                                       const std::string& limitSource) const
{
  if (!(nextBytes > limitBytes)) return "";
  std::ostringstream os;
  os.precision(3);
  os << "memory: the next mesh would have about " << nextDofs << " DOFs needing about "
     << nextBytes / 1e9 << " GB, above the memory limit of " << limitBytes / 1e9 << " GB ("
     << limitSource << ")";
  return os.str();
}

}  // namespace sc::adapt
