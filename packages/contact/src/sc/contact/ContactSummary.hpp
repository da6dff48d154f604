#pragma once
// Global contact quantities of a solved state (docs/contact.md "Outputs"): resultant force, peak
// pressure, contact-zone half-width (2D) or radius (3D), stick-zone size, point counts.
// Zone sizes, two ways (both in the obstacle plane):
//  - outermost: from the centroid of the contact points, the midpoint between the outermost point
//    in the zone and the next point outside it (resolves a clean 2D edge to half a point spacing);
//  - equivalent: from the area A the zone's points stand for (each point its share ∫_F L_p of its
//    face, L_p the Lagrange function of the normal trace at p, projected onto the plane): A/2 in
//    2D, √(A/π) in 3D. It averages over a ragged 3D edge, where the outermost point overshoots.
#include <array>
#include <vector>

#include <Teuchos_Comm.hpp>

#include "sc/contact/ActiveSetSolver.hpp"

namespace sc::contact {

struct ContactSummary {
  std::array<double, 3> force{};  ///< ∫_ΓC σn ds (vector resultant)
  double maxPressure = 0.0;       ///< max over the face DOF points of −σ_N (≥ 0)
  double zoneSize = 0.0;       ///< half-width (2D) or radius (3D) of the contact zone (outermost)
  double stickZoneSize = 0.0;  ///< the same for the stick zone (0 without friction)
  /// The resolution of zoneSize: half the gap between the outermost point in the zone and the
  /// next point outside (2D: the mean over the two ends), the largest error of the midpoint if
  /// the edge lies anywhere between them; 0 when no point lies outside. A bound in 2D only: in
  /// 3D the next point outside lies on another ray of a ragged edge.
  double zoneResolution = 0.0;
  double stickZoneResolution = 0.0;  ///< the same for stickZoneSize
  /// 2D: the stick zone's ends (−c₋, c₊) along the plane's tangent (−ν_y, ν_x), from `center`
  /// (stickZoneSize = (c₊ + c₋)/2; after a tangential load step the zone is not centred).
  std::array<double, 2> stickZoneEnds{};
  /// 2D: the half-width from the pressure profile at the zone's ends (docs/contact.md
  /// "Outputs"): near a Hertz-type end p ≈ C√(a − s), so p² is smooth in s and vanishes at the
  /// edge; at each end the least-squares parabola of p² over the points of the zone's
  /// kFittedPositions outermost positions is extrapolated to its zero, and the half-width is the
  /// mean of the two ends. Not bound to the point spacing (the outermost-point zoneSize moves by
  /// whole gaps). 0 in 3D and where an end has fewer than 3 positions or no such zero.
  double fittedZoneSize = 0.0;
  double equivalentZoneSize = 0.0;       ///< from the zone's area: A/2 (2D), √(A/π) (3D)
  double equivalentStickZoneSize = 0.0;  ///< the same for the stick zone
  /// Area A of the contact zone (2D: length per unit thickness): Σ over the points in contact of
  /// their share |∫_F w_p ds · (n_p·ν)| of their face (Σ_p w_p = 1 on a face, so a face whose
  /// points are all in contact counts with its whole measure; n_p·ν = −1 in the obstacle frame).
  double area = 0.0;
  double stickArea = 0.0;  ///< the same over the stick points (0 without friction)
  /// The smallest −σ_N at the DOF points of the points in contact (0 when none is): with
  /// maxPressure, the range of the contact pressure over the zone's points.
  double minPressure = 0.0;
  std::array<double, 3> center{};
  long long numFree = 0, numStick = 0, numSlip = 0;
};

/// The outermost positions of each end the fitted half-width uses.
constexpr int kFittedPositions = 6;

/// `pressureFloor`: points with −σ_N ≤ pressureFloor count as free (the application passes
/// 1e-12 × 2μ, a strain of 1e-12: a zero load then reports no zone). `pressures`: the contact
/// pressure −σ_N at each point's position x (contact::pointValues: with Bernstein constraints of
/// degree ≥ 2 a control value is not the traction's value there), for the fitted half-width;
/// empty on every rank: no fitted half-width (fittedZoneSize stays 0). A rank that owns no point
/// passes an empty vector either way; the choice is made over all ranks.
ContactSummary summarizeContact(const std::vector<ContactPoint>& localPoints, int dim,
                                const std::vector<double>& obstacleNormal,
                                const Teuchos::Comm<int>& comm, double pressureFloor = 0.0,
                                const std::vector<double>& pressures = {});

}  // namespace sc::contact
