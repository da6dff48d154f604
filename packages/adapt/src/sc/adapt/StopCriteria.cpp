#include "sc/adapt/StopCriteria.hpp"

#include <sstream>

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
    os << "eta = " << eta << " <= Target error " << settings_.targetError << " x |A^1/2 sigma_h| = "
       << settings_.targetError * stressNorm;
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
