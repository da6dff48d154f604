#pragma once
// The displacement reconstruction u^R ∈ continuous P_p(T)^d, p = k+1 (default) or k, from a
// mixed solution (σ_h, u_h, θ_h) (docs/theory.md §"Displacement reconstruction"):
//   1. per element T, u°|T ∈ P_p(T)^d with (∇u°, ∇v)_T = (z_h, ∇v)_T for all v ∈ P_p(T)^d and
//      (u°, e_i)_T = (u_h, e_i)_T, where z_h = Aσ_h + S(θ_h) and S:τ = θ · as τ (the skew matrix
//      of the assembler's weak symmetry, assembly::asymmetryTerms): one small dense solve;
//   2. u^R at each Lagrange node of continuous P_p = the average of u° over the elements that
//      share the node (a sum-and-count exchange of shared nodes between ranks);
//   3. u^R = u_D at the Lagrange nodes of Γ_D faces.
// Lagrange nodes are the equispaced lattice points of Intrepid2's HGRAD Cn basis of degree p,
// named by the multiset of global vertex ids of their barycentric lattice coordinates, so the
// node numbering (and u^R, up to the order of floating-point sums) does not depend on the
// partition.
#include <memory>
#include <vector>

#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>

#include <sc/assembly/MixedElasticityAssembler.hpp>

namespace sc::disc {
class ElementValues;
class FaceValues;
}  // namespace sc::disc
namespace sc::assembly {
class ElementSolution;
}

namespace sc::estimator {

class DisplacementReconstruction {
public:
  /// `degree`: polynomial degree p of u^R (the space's k or k+1).
  DisplacementReconstruction(const disc::MixedElasticitySpace& space, int degree,
                             Teuchos::RCP<const Teuchos::Comm<int>> comm);
  ~DisplacementReconstruction();
  DisplacementReconstruction(const DisplacementReconstruction&) = delete;
  DisplacementReconstruction& operator=(const DisplacementReconstruction&) = delete;

  /// Steps 1–3 for the solution read through `solution`; `data` gives the material (A) and u_D.
  void reconstruct(assembly::ElementSolution& solution, const assembly::ElasticityData& data);

  int degree() const { return degree_; }
  long long numGlobalNodes() const { return numNodes_; }
  /// Cubature degree of the element values that valuesAt() expects (exact for |∇u^R|² and for
  /// the P_k × P_p products of the estimator, plus 4 for data such as f).
  int cubatureDegree() const;

  /// u^R (nq × d) and ∇u^R (nq × d × d, (∇u)_ij = ∂_j u_i) at the points of `ev`, an
  /// ElementValues of cubatureDegree() reinit'ed on an owned element e.
  void valuesAt(int e, const disc::ElementValues& ev, std::vector<double>& u,
                std::vector<double>& grad) const;
  /// u^R (d values) at a physical point x of owned element e.
  void valueAt(int e, const double* x, double* u) const;
  /// u^R at mesh vertex v, which must be a vertex of one of this rank's elements.
  void vertexValue(int v, double* u) const;

  struct Impl;

private:
  const disc::MixedElasticitySpace& space_;
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  int degree_;
  long long numNodes_ = 0;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sc::estimator
