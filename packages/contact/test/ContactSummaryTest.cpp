// contact::summarizeContact's zone sizes and their resolution (ContactSummary.hpp) on synthetic
// points whose statuses are set by hand (every point on rank 0): the half-width is the mean of
// the two ends, each the midpoint between the outermost point in the zone and the next point
// outside; the resolution is half the gap between those two points (2D: the mean over the two
// ends). Expected values by hand (analytic, from the coordinates below).
#include <array>
#include <cmath>
#include <vector>

#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_UnitTestHarness.hpp>

#include <sc/contact/ContactSummary.hpp>

namespace {

using sc::contact::ContactPoint;
using sc::contact::PointStatus;

ContactPoint point(double x, double y, double z, PointStatus status)
{
  ContactPoint p;
  p.x = {x, y, z};
  p.status = status;
  p.sigmaN = p.sigmaNAtDofPoint = status == PointStatus::Free ? 0.0 : -1.0;
  return p;
}

}  // namespace

// 2D, obstacle normal (0, 1): points on y = 0 at x = −0.5, −0.3, −0.2, −0.1, 0, 0.1, 0.2, 0.4,
// 0.6; in contact |x| ≤ 0.2 (centroid 0), stick |x| ≤ 0.1. Zone ends 0.3 (gap 0.2 → 0.4) and
// −0.25 (gap −0.3 → −0.2): half-width 0.275, resolution (0.1 + 0.05)/2 = 0.075. Stick ends ±0.15
// (gaps 0.1): 0.15, resolution 0.05.
TEUCHOS_UNIT_TEST(ContactSummary, ZoneResolution2D)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  std::vector<ContactPoint> points;
  if (comm->getRank() == 0)
    for (double x : {-0.5, -0.3, -0.2, -0.1, 0.0, 0.1, 0.2, 0.4, 0.6}) {
      const double a = std::abs(x);
      points.push_back(point(x, 0.0, 0.0,
                             a <= 0.1 + 1e-12   ? PointStatus::Stick
                             : a <= 0.2 + 1e-12 ? PointStatus::Slip
                                                : PointStatus::Free));
    }
  const auto s = sc::contact::summarizeContact(points, 2, {0.0, 1.0, 0.0}, *comm);
  TEST_FLOATING_EQUALITY(s.zoneSize, 0.275, 1e-12);
  TEST_FLOATING_EQUALITY(s.zoneResolution, 0.075, 1e-12);
  TEST_FLOATING_EQUALITY(s.stickZoneSize, 0.15, 1e-12);
  TEST_FLOATING_EQUALITY(s.stickZoneResolution, 0.05, 1e-12);
}

// 3D, obstacle normal (0, 0, 1): in contact the origin and (±0.1, 0, 0), (0, ±0.1, 0); free
// (±0.25, 0, 0), (0, ±0.3, 0). Radius: midpoint of 0.1 and 0.25 = 0.175, resolution 0.075. No
// stick zone: 0 and 0. A zone with no point outside it: radius the outermost point, resolution 0.
TEUCHOS_UNIT_TEST(ContactSummary, ZoneResolution3D)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  std::vector<ContactPoint> points, all;
  if (comm->getRank() == 0) {
    for (const std::array<double, 2>& xy :
         std::vector<std::array<double, 2>>{{0, 0}, {0.1, 0}, {-0.1, 0}, {0, 0.1}, {0, -0.1}})
      points.push_back(point(xy[0], xy[1], 0.0, PointStatus::Slip));
    all = points;
    for (const std::array<double, 2>& xy :
         std::vector<std::array<double, 2>>{{0.25, 0}, {-0.25, 0}, {0, 0.3}, {0, -0.3}})
      points.push_back(point(xy[0], xy[1], 0.0, PointStatus::Free));
  }
  const auto s = sc::contact::summarizeContact(points, 3, {0.0, 0.0, 1.0}, *comm);
  TEST_FLOATING_EQUALITY(s.zoneSize, 0.175, 1e-12);
  TEST_FLOATING_EQUALITY(s.zoneResolution, 0.075, 1e-12);
  TEST_EQUALITY(s.stickZoneSize, 0.0);
  TEST_EQUALITY(s.stickZoneResolution, 0.0);
  const auto inside = sc::contact::summarizeContact(all, 3, {0.0, 0.0, 1.0}, *comm);
  TEST_FLOATING_EQUALITY(inside.zoneSize, 0.1, 1e-12);
  TEST_EQUALITY(inside.zoneResolution, 0.0);
}

// 2D, the fitted half-width (ContactSummary::fittedZoneSize): points on y = 0 at x = −0.5, −0.45,
// …, 0.5 carrying the Hertz pressure p = √(1 − x²/a²), a = 0.33, in contact where |x| < a (|x| ≤
// 0.3), free beyond. p² = 1 − x²/a² is a parabola, so the least-squares parabola of each end is
// exact and its zero is ±a: fitted half-width 0.33 (analytic), where the outermost point's
// midpoint gives (0.3 + 0.35)/2 = 0.325. In 3D there is none (0).
TEUCHOS_UNIT_TEST(ContactSummary, FittedHalfWidth2D)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const double a = 0.33;
  std::vector<ContactPoint> points;
  std::vector<double> pressures;
  if (comm->getRank() == 0)
    for (int i = -10; i <= 10; ++i) {
      const double x = 0.05 * i;
      const bool in = std::abs(x) < a;
      points.push_back(point(x, 0.0, 0.0, in ? PointStatus::Slip : PointStatus::Free));
      pressures.push_back(in ? std::sqrt(1.0 - x * x / (a * a)) : 0.0);
    }
  const auto s = sc::contact::summarizeContact(points, 2, {0.0, 1.0, 0.0}, *comm, 0.0, pressures);
  TEST_FLOATING_EQUALITY(s.zoneSize, 0.325, 1e-12);
  TEST_FLOATING_EQUALITY(s.fittedZoneSize, a, 1e-10);
  const auto s3 = sc::contact::summarizeContact(points, 3, {0.0, 0.0, 1.0}, *comm, 0.0, pressures);
  TEST_EQUALITY(s3.fittedZoneSize, 0.0);
}
