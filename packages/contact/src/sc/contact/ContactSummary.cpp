#include "sc/contact/ContactSummary.hpp"

#include <algorithm>
#include <cmath>

#include "sc/core/Collective.hpp"

namespace sc::contact {
namespace {

// Half-width / radius of the set `in` among all points: midpoint between the outermost point
// inside and the nearest point outside beyond it (on each side in 2D). `ends` (2D): the two
// ends so found, in the signed coordinate. `resolution`: the largest error of that midpoint
// when the edge lies anywhere between the two points, half their gap (2D: the mean of the two
// ends' half-gaps, as the half-width is the mean of the ends); 0 where no point lies outside.
double zoneSize(const std::vector<double>& s, const std::vector<char>& in, bool signedCoordinate,
                double* resolution, std::array<double, 2>* ends = nullptr)
{
  *resolution = 0.0;
  double maxIn = -1e300, minIn = 1e300;
  bool any = false;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (in[i]) {
      any = true;
      maxIn = std::max(maxIn, s[i]);
      minIn = std::min(minIn, s[i]);
    }
  if (!any) return 0.0;
  double nextOut = 1e300, prevOut = -1e300;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (!in[i]) {
      if (s[i] > maxIn) nextOut = std::min(nextOut, s[i]);
      if (s[i] < minIn) prevOut = std::max(prevOut, s[i]);
    }
  const double right = nextOut < 1e299 ? 0.5 * (maxIn + nextOut) : maxIn;
  const double rightGap = nextOut < 1e299 ? 0.5 * (nextOut - maxIn) : 0.0;
  if (!signedCoordinate) {
    *resolution = rightGap;
    return right;
  }
  const double left = prevOut > -1e299 ? 0.5 * (minIn + prevOut) : minIn;
  const double leftGap = prevOut > -1e299 ? 0.5 * (minIn - prevOut) : 0.0;
  if (ends) *ends = {left, right};
  *resolution = 0.5 * (leftGap + rightGap);
  return 0.5 * (right - left);
}

}  // namespace

ContactSummary summarizeContact(const std::vector<ContactPoint>& points, int dim,
                                const std::vector<double>& obstacleNormal,
                                const Teuchos::Comm<int>& comm, double pressureFloor)
{
  ContactSummary out;
  // A point carrying no more pressure than the floor counts as free here (a zero load must not
  // report a contact zone of round-off pressures).
  auto status = [pressureFloor](const ContactPoint& p) {
    return p.status != PointStatus::Free && -p.sigmaN <= pressureFloor ? PointStatus::Free
                                                                       : p.status;
  };
  // Local contributions: force, pressure, counts, centroid of active points, zone areas.
  double local[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};  // force(3), active count, centroid(3), areas(2)
  double localMax = 0.0, localMin = 1e300;
  long long counts[3] = {0, 0, 0};
  for (const auto& p : points) {
    for (int i = 0; i < dim; ++i) {
      const double ti = p.sigmaN * p.n[i] + p.sigmaT[0] * p.t1[i] + p.sigmaT[1] * p.t2[i];
      local[i] += ti * p.weight;
    }
    localMax = std::max(localMax, -p.sigmaNAtDofPoint);  // the trace at the DOF points
    ++counts[static_cast<int>(status(p))];
    if (status(p) != PointStatus::Free) {
      localMin = std::min(localMin, -p.sigmaNAtDofPoint);
      local[3] += 1.0;
      for (int i = 0; i < dim; ++i)
        local[4 + i] += p.x[i];
      // The point's share of its face: weight = ∫_F ψ_p·n with ψ_p·n = L_p (1 at p, 0 at the
      // face's other points), projected onto the plane.
      double cosine = 0.0;
      for (int i = 0; i < dim; ++i)
        cosine += p.n[i] * obstacleNormal[i];
      const double share = std::abs(p.weight * cosine);
      local[7] += share;
      if (status(p) == PointStatus::Stick) local[8] += share;
    }
  }
  double global[9];
  core::sumOverRanks(comm, 9, local, global);
  out.maxPressure = core::maxOverRanks(comm, localMax);
  const double globalMin = core::minOverRanks(comm, localMin);
  out.minPressure = globalMin < 1e299 ? globalMin : 0.0;
  long long gcounts[3];
  core::sumOverRanks(comm, 3, counts, gcounts);
  for (int i = 0; i < dim; ++i) {
    out.force[i] = global[i];
    out.center[i] = global[3] > 0 ? global[4 + i] / global[3] : 0.0;
  }
  auto fromArea = [dim](double area) { return dim == 2 ? 0.5 * area : std::sqrt(area / M_PI); };
  out.area = global[7];
  out.stickArea = global[8];
  out.equivalentZoneSize = fromArea(global[7]);
  out.equivalentStickZoneSize = fromArea(global[8]);
  out.numFree = gcounts[0];
  out.numStick = gcounts[1];
  out.numSlip = gcounts[2];

  // Zone sizes need all points: gather (coordinate, status) everywhere.
  std::vector<double> mine;
  for (const auto& p : points) {
    double rel[3] = {0, 0, 0}, along = 0.0;
    for (int i = 0; i < dim; ++i)
      rel[i] = p.x[i] - out.center[i];
    for (int i = 0; i < dim; ++i)
      along += rel[i] * obstacleNormal[i];
    double s;
    if (dim == 2) {
      // Signed coordinate along the plane's tangent (−ν_y, ν_x).
      s = -rel[0] * obstacleNormal[1] + rel[1] * obstacleNormal[0];
    } else {
      double r2 = 0.0;
      for (int i = 0; i < 3; ++i)
        r2 += std::pow(rel[i] - along * obstacleNormal[i], 2);
      s = std::sqrt(r2);
    }
    mine.push_back(s);
    mine.push_back(static_cast<double>(static_cast<int>(status(p))));
  }
  const std::vector<double> all = core::gatherAllConcatenated(comm, mine);
  const int total = static_cast<int>(all.size());
  std::vector<double> s;
  std::vector<char> active, stick;
  for (int i = 0; i + 1 < total; i += 2) {
    s.push_back(all[i]);
    active.push_back(all[i + 1] != 0.0);
    stick.push_back(all[i + 1] == 1.0);
  }
  out.zoneSize = zoneSize(s, active, dim == 2, &out.zoneResolution);
  out.stickZoneSize = zoneSize(s, stick, dim == 2, &out.stickZoneResolution,
                               dim == 2 ? &out.stickZoneEnds : nullptr);
  return out;
}

}  // namespace sc::contact
