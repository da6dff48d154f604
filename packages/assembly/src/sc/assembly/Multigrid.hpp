#pragma once
// What the geometric multigrid of the stress block needs from the discretisation (docs/theory.md
// §"Linear solvers"): the exact prolongation of RT_k stresses between nested meshes, and the
// patches of the additive Schwarz (Arnold–Falk–Winther) smoother. Tpetra stays in Multigrid.cpp.
#include <vector>

#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>

#include <sc/assembly/MixedElasticityAssembler.hpp>

namespace sc::disc {
class MixedElasticitySpace;
}

namespace sc::assembly {

/// P with fine σ = P coarse σ exactly when the fine mesh refines the coarse one (RT_k spaces are
/// nested): row g (a σ DOF of `fine`, owned by this rank) holds the coefficients of the coarse
/// basis in the fine DOF, from the local L² projection on one fine element containing it, which
/// is exact. `parent[e]` = the element of the coarse mesh that contains fine element e (compose
/// RefinementStep::elementParent over several steps). Global ids are the spaces' σ ids (0 .. #σ);
/// row map = this rank's owned fine σ DOFs in the order of fine.ownedDofs(), domain map = the
/// same for `coarse` (the maps the block preconditioner uses).
Teuchos::RCP<CrsMatrix> stressProlongation(const disc::MixedElasticitySpace& coarse,
                                           const disc::MixedElasticitySpace& fine,
                                           const std::vector<int>& parent,
                                           const Teuchos::RCP<const Teuchos::Comm<int>>& comm);

/// The patches of the additive Schwarz smoother (Arnold–Falk–Winther): the σ DOFs of each vertex
/// star in 2D and of each edge star in 3D (faces that contain the vertex or edge and the interiors
/// of the elements around it, all rows), for the entities assigned to this rank (the owner of the
/// lowest-numbered element around). Patches overlap; together they cover every σ DOF. The local
/// kernel of div is spanned by curls of vertex hats (2D) and of edge functions (3D), which these
/// stars contain; 3D vertex stars would also do but hold ~450 σ DOFs at k = 1, edge stars ~90.
std::vector<std::vector<long long>> stressPatches(const disc::MixedElasticitySpace& space);

}  // namespace sc::assembly
