#pragma once
// What the geometric multigrid of the stress block (StressMultigrid.hpp) needs from the
// discretisation (docs/theory.md §"Linear solvers"): the exact prolongation of RT_k stresses
// between nested meshes, the patches of the additive Schwarz (Arnold–Falk–Winther) smoother, and
// the hierarchy of a run's meshes from which the levels are chosen. Tpetra stays in
// StressHierarchy.cpp.
#include <vector>

#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>

#include <sc/solvers/LinearSolver.hpp>

namespace sc::disc {
class MixedElasticitySpace;
}
namespace sc::mesh {
class SimplexMesh;
}
namespace sc::solvers {

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

/// The nested meshes of a run (the initial mesh and every refinement of it, uniform or adaptive),
/// from which the multigrid levels of the stress block are chosen (docs/solvers.md, "Geometric
/// multigrid"): the finest mesh, then going coarser a mesh whenever it has at most 1/ratio of the
/// elements of the last level chosen, the first mesh replacing the coarsest one chosen (a single
/// level, solved directly, until a mesh has `ratio` times the first one's elements); the parents
/// are composed over the meshes skipped. So adaptive cycles that add a few elements each still give
/// a hierarchy whose levels shrink geometrically. All meshes are kept (a few per cent of the
/// finest level's memory in 2D).
class StressHierarchy {
public:
  StressHierarchy(int degree, Teuchos::RCP<const Teuchos::Comm<int>> comm, double ratio = 2.0);
  ~StressHierarchy();
  /// The first mesh (no parent), or a refinement of the last one added: parent[e] = the element
  /// of the previous mesh that contains element e (mesh::RefinementStep::elementParent).
  void addMesh(Teuchos::RCP<const mesh::SimplexMesh> mesh, const std::vector<int>& parent);
  int numMeshes() const { return static_cast<int>(meshes_.size()); }
  int meshElements(int i) const;
  /// The levels for `finest`, the space on the last mesh added (coarsest first; a single level
  /// when only one mesh is known: the stress block is then solved directly). The coarser levels'
  /// spaces are built (partitioned) here.
  std::vector<MultigridLevel> levels(const disc::MixedElasticitySpace& finest) const;
  /// The mesh indices the last call of levels() chose (coarsest first).
  const std::vector<int>& chosen() const { return chosen_; }

private:
  int degree_;
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  double ratio_;
  std::vector<Teuchos::RCP<const mesh::SimplexMesh>> meshes_;
  std::vector<std::vector<int>> parents_;  // parents_[i]: elements of mesh i -> mesh i − 1
  mutable std::vector<int> chosen_;
};

}  // namespace sc::solvers
