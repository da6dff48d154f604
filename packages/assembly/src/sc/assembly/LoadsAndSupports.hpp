#pragma once
// Checks of the loads and supports against the mesh (docs/theory.md §"Loads and supports"): the
// coordinate axis normal to each Symmetry part, rigid-body motions fixed, and the formulas of
// the deck finite on the body. The mesh is replicated, so every rank computes the same result
// and an error is collective.
#include <array>
#include <map>
#include <string>

#include <sc/assembly/MixedElasticityAssembler.hpp>
#include <sc/core/ProblemData.hpp>

namespace sc::mesh {
class SimplexMesh;
}

namespace sc::assembly {

/// The axis i (0-based) of the plane x_i = const in which each Symmetry part lies. A Symmetry part
/// whose vertices do not share one coordinate (to 1e-9 of the mesh's size) is an InputError
/// naming the key and the part's extent.
std::map<std::string, int> symmetryAxes(const mesh::SimplexMesh& mesh,
                                        const core::BoundaryConditions& boundaryConditions);

/// A rigid plane obstacle of the Contact parts (Contact/Obstacle = Plane): its unit normal ν,
/// pointing towards the body.
struct ContactPlane {
  std::array<double, 3> normal{};
};

/// symmetryAxes, and: without a Displacement part the Symmetry parts must be normal to all d
/// axes (otherwise a translation or rotation of the body is free and the matrix is singular),
/// or to all but the axis a of the normal of a contact `plane` (ν = ±e_a): then the contact
/// alone holds the body along e_a, as a roller does when in contact (docs/theory.md §"Loads
/// and supports"), and the function returns a. Every formula (boundary data on its part's
/// vertices, body force on all vertices) must be finite. Throws InputError naming the keys.
/// Returns −1 when the body is held without the contact.
int checkLoadsAndSupports(const mesh::SimplexMesh& mesh, const ElasticityData& data,
                          const ContactPlane* plane = nullptr);

}  // namespace sc::assembly
