#include "sc/contact/ContactSummary.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "sc/core/Collective.hpp"
#include "sc/core/Error.hpp"

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

// One end of a 2D zone from its pressure profile (ContactSummary::fittedZoneSize): `s` the
// coordinate increasing outwards, `p` the pressure, `in` the zone's points. The least-squares
// parabola p² = c₀ + c₁ x + c₂ x² over the points of the zone's `positions` outermost distinct
// positions (all of them, if the zone has fewer, but at least 3), and its smallest zero beyond
// the middle of those positions; none where there is none.
std::optional<double> fittedEnd(const std::vector<double>& s, const std::vector<double>& p,
                                const std::vector<char>& in, int positions)
{
  std::vector<double> distinct;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (in[i]) distinct.push_back(s[i]);
  std::sort(distinct.begin(), distinct.end());
  double scale = 0.0;
  for (double x : distinct)
    scale = std::max(scale, std::abs(x));
  // The points of two faces at one vertex are one position.
  const double same = 1e-9 * scale;
  distinct.erase(std::unique(distinct.begin(), distinct.end(),
                             [same](double a, double b) { return b - a <= same; }),
                 distinct.end());
  const int used = std::min(positions, static_cast<int>(distinct.size()));
  if (used < 3) return std::nullopt;
  const double outermost = distinct.back();
  const double innermost = distinct[distinct.size() - used];
  const double span = outermost - innermost;
  if (!(span > 0.0)) return std::nullopt;
  // The pressures relative to their largest value here: p² of a stiff material (E up to 1e100,
  // 'Material/Young modulus') would overflow in the discriminant below; the zero is unchanged.
  double pScale = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (in[i] && s[i] >= innermost - same) pScale = std::max(pScale, std::abs(p[i]));
  if (!(pScale > 0.0) || !std::isfinite(pScale)) return std::nullopt;
  // Normal equations in x = (s − outermost)/span (conditioning), the unknowns c₀, c₁, c₂.
  double m[3][4] = {};
  for (std::size_t i = 0; i < s.size(); ++i)
    if (in[i] && s[i] >= innermost - same) {
      const double q = p[i] / pScale;
      const double x = (s[i] - outermost) / span, y = q * q;
      const double row[3] = {1.0, x, x * x};
      for (int a = 0; a < 3; ++a) {
        for (int b = 0; b < 3; ++b)
          m[a][b] += row[a] * row[b];
        m[a][3] += row[a] * y;
      }
    }
  // Gaussian elimination with partial pivoting; a (nearly) singular system has no fit (x is in
  // [−1, 0], so the entries are at most the number of points, m[0][0]).
  const double tiny = 1e-12 * m[0][0];
  for (int k = 0; k < 3; ++k) {
    int pivot = k;
    for (int r = k + 1; r < 3; ++r)
      if (std::abs(m[r][k]) > std::abs(m[pivot][k])) pivot = r;
    if (!(std::abs(m[pivot][k]) > tiny)) return std::nullopt;
    std::swap(m[k], m[pivot]);
    for (int r = k + 1; r < 3; ++r) {
      const double f = m[r][k] / m[k][k];
      for (int c = k; c < 4; ++c)
        m[r][c] -= f * m[k][c];
    }
  }
  double c[3];
  for (int k = 2; k >= 0; --k) {
    c[k] = m[k][3];
    for (int j = k + 1; j < 3; ++j)
      c[k] -= m[k][j] * c[j];
    c[k] /= m[k][k];
  }
  // The zeros of c₀ + c₁ x + c₂ x², the smallest beyond the middle of the positions (x = −½).
  std::vector<double> roots;
  if (std::abs(c[2]) <= 1e-12 * (std::abs(c[0]) + std::abs(c[1]))) {
    if (c[1] != 0.0) roots.push_back(-c[0] / c[1]);
  } else {
    const double disc = c[1] * c[1] - 4.0 * c[2] * c[0];
    if (disc < 0.0) return std::nullopt;
    // The stable pair of formulas (no cancellation).
    const double q = -0.5 * (c[1] + std::copysign(std::sqrt(disc), c[1]));
    roots.push_back(q / c[2]);
    if (q != 0.0) roots.push_back(c[0] / q);
  }
  std::optional<double> end;
  for (double x : roots)
    if (std::isfinite(x) && x > -0.5 && (!end || outermost + x * span < *end))
      end = outermost + x * span;
  return end;
}

}  // namespace

ContactSummary summarizeContact(const std::vector<ContactPoint>& points, int dim,
                                const std::vector<double>& obstacleNormal,
                                const Teuchos::Comm<int>& comm, double pressureFloor,
                                const std::vector<double>& pressures)
{
  SC_THROW_IF(!pressures.empty() && pressures.size() != points.size(), core::InternalError,
              "contact::summarizeContact: " << pressures.size() << " pressures for "
                                            << points.size() << " points");
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

  // Zone sizes need all points: gather (coordinate, status, pressure) everywhere.
  std::vector<double> mine;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const auto& p = points[k];
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
    mine.push_back(pressures.empty() ? -p.sigmaN : pressures[k]);
  }
  const std::vector<double> all = core::gatherAllConcatenated(comm, mine);
  const int total = static_cast<int>(all.size());
  std::vector<double> s, pressure;
  std::vector<char> active, stick;
  for (int i = 0; i + 2 < total; i += 3) {
    s.push_back(all[i]);
    active.push_back(all[i + 1] != 0.0);
    stick.push_back(all[i + 1] == 1.0);
    pressure.push_back(all[i + 2]);
  }
  out.zoneSize = zoneSize(s, active, dim == 2, &out.zoneResolution);
  // Whether pressures were given is decided over all ranks: a rank owning no contact point has
  // an empty vector, and every rank must report the same summary.
  const bool fit = core::maxOverRanks(comm, pressures.empty() ? 0 : 1) > 0;
  if (dim == 2 && fit) {
    std::vector<double> mirrored(s.size());
    for (std::size_t i = 0; i < s.size(); ++i)
      mirrored[i] = -s[i];
    const auto right = fittedEnd(s, pressure, active, kFittedPositions);
    const auto left = fittedEnd(mirrored, pressure, active, kFittedPositions);
    if (right && left && *right + *left > 0.0) out.fittedZoneSize = 0.5 * (*right + *left);
  }
  out.stickZoneSize = zoneSize(s, stick, dim == 2, &out.stickZoneResolution,
                               dim == 2 ? &out.stickZoneEnds : nullptr);
  return out;
}

}  // namespace sc::contact
