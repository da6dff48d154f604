#pragma once
// Resultant forces and moments of a solved stress field (docs/output.md "summary.json":
// reactions, force_balance). In the stress formulation σ_h n is known on every face from the RT
// DOFs, so the force a boundary part exerts on the body, ∫ σ_h n ds, is a face integral of the
// solution: exact with the face quadrature (φ·n dS = φ̂·n̂ dŜ is a polynomial on the reference face,
// also on curved faces) and read through the same FaceValues / ElementSolution as the estimator.
#include <array>
#include <string>
#include <vector>

#include <Teuchos_Comm.hpp>

#include <sc/assembly/MixedElasticityAssembler.hpp>

namespace sc::assembly {

/// The resultant of σ_h n on one boundary part of the mesh, summed over ranks.
struct BoundaryForce {
  std::string part;  ///< the mesh's name of the part
  std::array<double, 3>
      force{};  ///< ∫ σ_h n ds: the force the part's support or load exerts on the body
  /// ∫ (x − x₀) × σ_h n ds about the moment point x₀: 3 components in 3D; in 2D the z component
  /// in moment[2] (about the axis through (x₀, y₀) normal to the plane), moment[0] = moment[1] = 0.
  std::array<double, 3> moment{};
};

/// One entry per boundary part of the mesh, in the mesh's part order (SimplexMesh::boundaryNames).
/// Each rank integrates the boundary faces of its owned elements (face quadrature of degree
/// 2k + 2, exact for σ_h n and (x − x₀) × σ_h n on straight and curved faces); the sums are
/// reduced over ranks. Collective.
std::vector<BoundaryForce> computeBoundaryForces(const MixedElasticityAssembler& assembler,
                                                 const MultiVector& solution,
                                                 const std::array<double, 3>& momentPoint,
                                                 const Teuchos::Comm<int>& comm);

/// ∫_Ω f dx with the element quadrature the assembler gives f (degree 2k + 2), summed over ranks:
/// the discrete equilibrium div σ_h = −Π_k f then gives Σ_parts ∫ σ_h n ds = −∫_Ω f dx up to the
/// linear solver's residual. Zero without a body force. Collective.
std::array<double, 3> computeBodyForceResultant(const MixedElasticityAssembler& assembler,
                                                const ElasticityData& data,
                                                const Teuchos::Comm<int>& comm);

}  // namespace sc::assembly
