#pragma once
// The contact state carried from the points of the previous cycle to those of the next mesh
// (nested iteration: each cycle's Newton starts from the previous cycle's state), with the
// friction history of load steps (docs/theory.md §"Load steps").
#include <vector>

#include <Teuchos_Comm.hpp>

#include <sc/contact/ContactPoint.hpp>

namespace sc::mesh {
class SimplexMesh;
}

namespace sc::contact {

/// Start `points` (this rank's points on `mesh`) from the states of the previous cycle's points
/// through the refinement history. `parentFace[f]`: the face of the previous mesh that contains
/// face f of `mesh`, -1 off the boundary (mesh::boundaryFaceParents of the refinement step;
/// empty: no history, all points start free). `previous`: this rank's points of the previous
/// cycle (their `face`, `index` and `x` in the previous mesh). Each point takes the state (status,
/// slip direction) of the nearest point of its face's parent face: an unrefined face keeps its
/// points' states, each half (2D) or quarter (3D) of a refined face those of the parent's points
/// on its side. At degree k ≥ 2 a face has several points and a child face takes, point by point,
/// the nearest of the parent's; where two are equally near (a new vertex halfway between two
/// Bernstein control points, 3D), a contact state wins over free and stick over slip, then the
/// lower index in the parent face. The load-step history is the affine fit of the parent face's
/// per-weight values (disc::fitAffineOnFace) at the point's weight centroid. Depends on the mesh
/// only, not on the rank count. Collective.
void transferContactState(std::vector<ContactPoint>& points,
                          const std::vector<ContactPoint>& previous,
                          const std::vector<int>& parentFace, const mesh::SimplexMesh& mesh,
                          const Teuchos::Comm<int>& comm);

}  // namespace sc::contact
