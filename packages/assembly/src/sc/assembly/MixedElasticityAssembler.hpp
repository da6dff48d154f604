#pragma once
// Tpetra assembly of the dual mixed elasticity system (docs/theory.md §"Mixed formulation"):
//
//   [ A   B1ᵀ  B2ᵀ ] [σ]   [⟨u_D, τn⟩_ΓD]       (Aσ, τ) = ((1/2μ)(σ − c_d tr σ I), τ)
//   [ B1  0    0   ] [u] = [  −(f, v)   ]       (B1 σ, v) = (div σ, v)
//   [ B2  0    0   ] [θ]   [     0      ]       (B2 σ, η) = (as σ, η)
//
// Each rank assembles its owned rows, complete, into a Tpetra::CrsMatrix: its own elements and
// the other ranks' elements that touch its rows (docs/theory.md §"Parallel model"). The traction
// condition σn = t on Γ_N (t = −p n for a pressure, and σn = 0 on free boundaries) is essential:
// the face DOFs of each row are set to the L²(F) projection of t onto the face's normal traces, and
// eliminated symmetrically inside the element matrix (a boundary face belongs to one element, so
// this is exact), which keeps the system symmetric. A Symmetry face in x_i = const fixes the
// rows j ≠ i to zero the same way (zero tangential traction) and leaves row i free with u_i = 0
// as its natural (zero) data. λ is never formed: ν = 0.5 is fine.
#include <memory>
#include <string>
#include <vector>

#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>
#include <Tpetra_CrsMatrix_fwd.hpp>
#include <Tpetra_Map_fwd.hpp>
#include <Tpetra_MultiVector_fwd.hpp>

#include <sc/core/ExactSolution.hpp>
#include <sc/core/ProblemData.hpp>

namespace sc::disc {
class MixedElasticitySpace;
}

namespace sc::assembly {

using Map = Tpetra::Map<>;
using CrsMatrix = Tpetra::CrsMatrix<>;
using MultiVector = Tpetra::MultiVector<>;

/// One term of the weak symmetry (as τ)_comp = Σ sign · τ_{row,col} (docs/theory.md §"The problem":
/// 2D τ12 − τ21; 3D (τ32 − τ23, τ13 − τ31, τ21 − τ12)), 0-based. The same table defines the skew
/// matrix S(θ) with S:τ = θ · as τ (S_{row,col} = sign · θ_comp), which the displacement
/// reconstruction adds to Aσ_h (docs/theory.md): one definition, so the two cannot disagree on the
/// sign.
struct AsymmetryTerm {
  int comp, row, col;
  double sign;
};
/// The terms of as τ in dimension d (2 terms in 2D, 6 in 3D).
const std::vector<AsymmetryTerm>& asymmetryTerms(int dim);

/// The data the elasticity system needs. Boundary parts not named in `boundaryConditions` are
/// traction-free. With an exact solution, f = −div σ comes from it, and boundary conditions with
/// `fromExactSolution` take u_D or t from it; otherwise f is `bodyForce` (docs/theory.md §"Loads
/// and supports"). The assembler and the estimator read f through bodyForceAt, so that both see
/// the same load.
struct ElasticityData {
  core::Material material;
  core::BoundaryConditions boundaryConditions;
  const core::ExactSolution* exactSolution = nullptr;
  core::BodyForce bodyForce;

  bool hasBodyForce() const { return exactSolution || !bodyForce.isZero(); }
  /// f(x), d components (zero without an exact solution or a body force).
  void bodyForceAt(const double* x, int dim, double* f) const
  {
    if (exactSolution)
      exactSolution->bodyForce(x, f);
    else
      bodyForce.evaluate(x, dim, f);
  }
};

struct AssemblyStatistics {
  double graphSeconds = 0.0;
  double assemblySeconds = 0.0;
  long long ownedElements = 0;
  long long constrainedDofs = 0;  ///< σ DOFs fixed by traction / free conditions (this rank)
  long long nonzeros = 0;         ///< global
};

class MixedElasticityAssembler {
public:
  MixedElasticityAssembler(Teuchos::RCP<const disc::MixedElasticitySpace> space,
                           Teuchos::RCP<const Teuchos::Comm<int>> comm);
  ~MixedElasticityAssembler();
  MixedElasticityAssembler(const MixedElasticityAssembler&) = delete;
  MixedElasticityAssembler& operator=(const MixedElasticityAssembler&) = delete;

  /// Assemble matrix and right-hand side (the graph is built on the first call and reused).
  void assemble(const ElasticityData& data);

  Teuchos::RCP<const CrsMatrix> matrix() const;
  Teuchos::RCP<const MultiVector> rhs() const;
  Teuchos::RCP<const Map> ownedMap() const;
  /// Owned DOFs followed by the shared DOFs of this rank's elements.
  Teuchos::RCP<const Map> overlapMap() const;
  Teuchos::RCP<MultiVector> createVector() const;
  /// The values of an owned-map vector on the overlap map (for element-wise postprocessing).
  Teuchos::RCP<MultiVector> toOverlap(const MultiVector& owned) const;
  const AssemblyStatistics& statistics() const { return stats_; }
  /// Symmetric block scaling D (√(2μ) on σ DOFs, 1/√(2μ) on u and θ DOFs): D M D has an A block of
  /// order one whatever E is, which a row/column equilibration cannot find (the rows of σ have O(1)
  /// entries from B either way). Solve D M D y = D b, x = D y (docs/theory.md §"Contact and
  /// friction": "equilibrate").
  Teuchos::RCP<const MultiVector> physicalScaling(double twoMu) const;
  const disc::MixedElasticitySpace& space() const { return *space_; }
  /// The L² mass matrices of the displacement (element-block diagonal) and rotation fields, (u, v)
  /// and (θ, η), in one matrix with the system's graph and maps (σ rows zero, no 2μ): the u and θ
  /// blocks of the block-diagonal preconditioner (docs/theory.md §"Linear solvers"). Computed on
  /// the first call after assemble() and cached until the next assemble().
  Teuchos::RCP<const CrsMatrix> fieldMassMatrix() const;

  struct Impl;

private:
  void buildGraph();

  Teuchos::RCP<const disc::MixedElasticitySpace> space_;
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  std::unique_ptr<Impl> impl_;
  AssemblyStatistics stats_;
};

/// L² errors against an exact solution (summed over ranks): ‖σ−σ_h‖, ‖div(σ−σ_h)‖, ‖u−u_h‖,
/// ‖θ−θ_h‖, and the norms of the exact fields for relative errors.
struct ErrorNorms {
  double stress = 0.0, stressDiv = 0.0, displacement = 0.0, rotation = 0.0;
  double stressNorm = 0.0, stressDivNorm = 0.0, displacementNorm = 0.0, rotationNorm = 0.0;
  /// ‖A^{1/2}(σ − σ_h)‖ when a material is given, −1 otherwise.
  double stressEnergy = -1.0;
};

ErrorNorms computeErrors(const MixedElasticityAssembler& assembler, const MultiVector& solution,
                         const core::ExactSolution& exact, const Teuchos::Comm<int>& comm,
                         const core::Material* material = nullptr);

/// Energy norm of the stress error ‖A^{1/2}(σ − σ_h)‖ = (A(σ − σ_h), σ − σ_h)^{1/2}, summed over
/// ranks: the norm in which the estimator's efficiency is measured (docs/theory.md).
double computeStressEnergyError(const MixedElasticityAssembler& assembler,
                                const MultiVector& solution, const core::ExactSolution& exact,
                                const core::Material& material, const Teuchos::Comm<int>& comm);

/// Cell averages of the solution on this rank's owned elements (in ownedElements() order), for
/// output: σ (d×d row-major), von Mises stress, pressure −tr σ / d, u (d), θ (r).
struct CellAverages {
  std::vector<double> stress, vonMises, pressure, displacement, rotation;
};
CellAverages computeCellAverages(const MixedElasticityAssembler& assembler,
                                 const MultiVector& solution);

}  // namespace sc::assembly
