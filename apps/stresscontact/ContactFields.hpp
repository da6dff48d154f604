#pragma once
// The `contact` grid of a cycle's fields (docs/output.md "Fields in a run's files"): the contact
// points of this rank as a point cloud with the point values of the contact quantities, for
// ParaView.
#include <sc/io/GridPiece.hpp>

namespace sc::contact {
class ActiveSetSolver;
}

namespace sc::app {

/// This rank's contact points (in the order of the contact CSV's rows) with the fields
/// status, contact_pressure, tangential_traction, gap, slip, weight and contact_normal.
io::GridPiece contactPointGrid(const contact::ActiveSetSolver& solver, int dim, int degree);

}  // namespace sc::app
