#pragma once
// Global contact quantities of a solved state (issue #5 outputs): resultant force, peak
// pressure, contact-zone half-width (2D) or radius (3D), stick-zone size, point counts.
// Zone sizes are measured in the obstacle plane from the centroid of the contact points, as the
// midpoint between the outermost point in the zone and the next point outside it.
#include <array>
#include <vector>

#include <Teuchos_Comm.hpp>

#include "sc/contact/ActiveSetSolver.hpp"

namespace sc::contact {

struct ContactSummary {
  std::array<double, 3> force{};  ///< ∫_ΓC σn ds (vector resultant)
  double maxPressure = 0.0;       ///< max over points of −σ_N (≥ 0)
  double zoneSize = 0.0;          ///< half-width (2D) or radius (3D) of the contact zone
  double stickZoneSize = 0.0;     ///< the same for the stick zone (0 without friction)
  std::array<double, 3> center{};
  long long numFree = 0, numStick = 0, numSlip = 0;
};

ContactSummary summarizeContact(const std::vector<ContactPoint>& localPoints, int dim,
                                const std::vector<double>& obstacleNormal,
                                const Teuchos::Comm<int>& comm);

}  // namespace sc::contact
