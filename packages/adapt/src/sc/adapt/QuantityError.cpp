#include "sc/adapt/QuantityError.hpp"

#include <algorithm>
#include <cmath>

#include <sc/core/Error.hpp>

namespace sc::adapt {

double estimateQuantityError(const std::vector<QuantitySample>& history, double floor,
                             const QuantityErrorSettings& settings)
{
  SC_THROW_IF(settings.window < 1 || !(settings.safetyFactor >= 1.0) || !(floor >= 0.0) ||
                  !(settings.rate >= 0.0),
              core::InternalError,
              "estimateQuantityError: window " << settings.window << ", safety factor "
                                               << settings.safetyFactor << ", rate "
                                               << settings.rate << ", floor " << floor);
  const int n = static_cast<int>(history.size()) - 1;
  if (n < 1) return -1.0;
  const QuantitySample& last = history[n];
  if (!(last.eta > 0.0) || !std::isfinite(last.value)) return -1.0;
  double error = -1.0;
  for (int j = std::max(0, n - settings.window); j < n; ++j) {
    const QuantitySample& s = history[j];
    // Only a cycle with a larger η says how fast the quantity moves per unit of η.
    if (!(s.eta > last.eta) || !std::isfinite(s.value)) continue;
    const double change = std::abs(s.value - last.value);
    if (settings.rate == 0.0) {
      error = std::max(error, change);
      continue;
    }
    const double now = std::pow(last.eta, settings.rate);
    error = std::max(error, change * now / (std::pow(s.eta, settings.rate) - now));
  }
  if (error < 0.0) return -1.0;
  return std::max(settings.safetyFactor * error, floor);
}

}  // namespace sc::adapt
