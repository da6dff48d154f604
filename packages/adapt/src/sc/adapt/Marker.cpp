#include "sc/adapt/Marker.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <sc/core/Collective.hpp>

#include <sc/adapt/AdaptivitySettings.hpp>
#include <sc/core/Error.hpp>

namespace sc::adapt {
namespace {

void checkTheta(double theta)
{
  SC_THROW_IF(!(theta > 0.0 && theta <= 1.0), core::InputError,
              "'Adaptivity/Bulk parameter' = " << theta << ": valid range (0, 1].");
}

}  // namespace

std::vector<int> Marker::mark(int numElements, const std::vector<int>& ownedElements,
                              const std::vector<double>& indicators,
                              const Teuchos::Comm<int>& comm) const
{
  SC_THROW_IF(ownedElements.size() != indicators.size(), core::InternalError,
              ownedElements.size() << " owned elements but " << indicators.size() << " indicators");
  std::vector<double> local(numElements, 0.0), all(numElements, 0.0);
  for (std::size_t i = 0; i < ownedElements.size(); ++i) {
    SC_THROW_IF(!(indicators[i] >= 0.0), core::InternalError,
                "indicator of element " << ownedElements[i] << " is " << indicators[i]);
    local[ownedElements[i]] = indicators[i];
  }
  core::sumOverRanks(comm, numElements, local.data(), all.data());
  auto marked = select(all);
  std::sort(marked.begin(), marked.end());
  return marked;
}

DorflerMarker::DorflerMarker(double theta) : theta_(theta) { checkTheta(theta); }

std::vector<int> DorflerMarker::select(const std::vector<double>& eta2) const
{
  std::vector<int> order(eta2.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return eta2[a] > eta2[b] || (eta2[a] == eta2[b] && a < b); });
  // Sum in the order of the sort (largest first) so that the total and the prefix agree.
  double total = 0.0;
  for (int e : order)
    total += eta2[e];
  std::vector<int> marked;
  if (total <= 0.0) return marked;  // η = 0: nothing to refine
  double sum = 0.0;
  for (int e : order) {
    if (sum >= theta_ * total) break;
    marked.push_back(e);
    sum += eta2[e];
  }
  return marked;
}

MaximumMarker::MaximumMarker(double theta) : theta_(theta) { checkTheta(theta); }

std::vector<int> MaximumMarker::select(const std::vector<double>& eta2) const
{
  const double mx = eta2.empty() ? 0.0 : *std::max_element(eta2.begin(), eta2.end());
  std::vector<int> marked;
  if (mx <= 0.0) return marked;
  // η_T ≥ θ max η_T  ⇔  η_T² ≥ θ² max η_T².
  for (std::size_t e = 0; e < eta2.size(); ++e)
    if (eta2[e] >= theta_ * theta_ * mx) marked.push_back(static_cast<int>(e));
  return marked;
}

std::vector<int> UniformMarker::select(const std::vector<double>& eta2) const
{
  std::vector<int> marked(eta2.size());
  std::iota(marked.begin(), marked.end(), 0);
  return marked;
}

std::unique_ptr<Marker> createMarker(const AdaptivitySettings& s)
{
  if (s.marking == "Dorfler") return std::make_unique<DorflerMarker>(s.bulkParameter);
  if (s.marking == "Maximum") return std::make_unique<MaximumMarker>(s.bulkParameter);
  if (s.marking == "Uniform") return std::make_unique<UniformMarker>();
  throw core::InputError("'Adaptivity/Marking' = '" + s.marking +
                         "': valid are 'Dorfler', 'Maximum', 'Uniform'.");
}

}  // namespace sc::adapt
