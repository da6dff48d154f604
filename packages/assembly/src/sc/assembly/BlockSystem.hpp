#pragma once
// The mixed elasticity system (docs/theory.md §"Mixed formulation") as a 3×3 block operator, for
// block preconditioners (Teko) and anything else that wants the fields apart:
//
//   [ A   B1ᵀ  B2ᵀ ]      block 0: σ (all d rows of RT_k)
//   [ B1  0    0   ]      block 1: u (all d components of DP_k)
//   [ B2  0    0   ]      block 2: θ (all r components of CP_k)
//
// The blocks are copied out of the assembled monolithic matrix M (global layout [σ | u | θ] of
// disc::MixedElasticitySpace), so both views hold the same numbers, including the traction rows
// eliminated in M. Numbering: each field has its own Tpetra::Map with index base 0; the global id
// of a DOF in its field map is its monolithic id minus the field's first id (layout().begin(f)),
// and every rank owns the same DOFs as in M. The uu, uθ, θu and θθ blocks are structurally
// zero (M stores explicit zeros there, from the element graph): they are null blocks, which is
// what Thyra::DefaultBlockedLinearOp skips in apply and Teko::isZeroOp reports as zero.
//
// Thyra/Teko/Tpetra headers stay in BlockSystem.cpp; include Thyra_LinearOpBase.hpp etc. where
// the returned objects are used.
#include <memory>

#include <Teuchos_RCP.hpp>

#include <sc/assembly/MixedElasticityAssembler.hpp>

namespace Thyra {
template <class Scalar>
class LinearOpBase;
template <class Scalar>
class MultiVectorBase;
template <class Scalar>
class ProductVectorSpaceBase;
}  // namespace Thyra

namespace sc::assembly {

/// Global sizes of the three fields in the monolithic layout [σ | u | θ].
struct FieldLayout {
  long long stressDofs = 0, displacementDofs = 0, rotationDofs = 0;

  long long size(int field) const;
  /// First monolithic global id of the field (0, #σ, #σ + #u).
  long long begin(int field) const
  {
    return field == 0 ? 0 : field == 1 ? stressDofs : stressDofs + displacementDofs;
  }
  long long total() const { return stressDofs + displacementDofs + rotationDofs; }
  /// Field of a monolithic global id.
  int fieldOf(long long gid) const { return gid < begin(1) ? 0 : gid < begin(2) ? 1 : 2; }
};

class BlockSystem {
public:
  enum Field : int { Stress = 0, Displacement = 1, Rotation = 2 };
  static constexpr int numFields = 3;

  /// The blocks of an assembled system. `twoMu` = 1 gives the blocks of M; `twoMu` = 2μ gives
  /// those of D M D with D = assembler.physicalScaling(2μ): A times 2μ, B1 and B2 unchanged
  /// (√(2μ)·1/√(2μ) = 1). Vectors are not scaled by split/merge: as in the monolithic route,
  /// solve with D b and multiply the solution by D.
  explicit BlockSystem(const MixedElasticityAssembler& assembler, double twoMu = 1.0);
  /// The same from any fill-complete monolithic matrix whose row, domain and range maps are the
  /// owned DOF map and whose global ids follow `layout`. Throws core::InternalError (on every
  /// rank) if it has non-zero values in the zero blocks.
  BlockSystem(Teuchos::RCP<const CrsMatrix> monolithic, const FieldLayout& layout,
              double twoMu = 1.0);
  ~BlockSystem();
  BlockSystem(const BlockSystem&) = delete;
  BlockSystem& operator=(const BlockSystem&) = delete;

  const FieldLayout& layout() const { return layout_; }
  double twoMu() const { return twoMu_; }
  Teuchos::RCP<const Map> monolithicMap() const;
  /// Owned DOFs of one field on this rank, global ids renumbered from 0 (see the file comment).
  Teuchos::RCP<const Map> fieldMap(int field) const;
  /// Block (row, col): row map and range map fieldMap(row), domain map fieldMap(col). Null for
  /// the structurally zero blocks (1,1), (1,2), (2,1), (2,2).
  Teuchos::RCP<const CrsMatrix> block(int row, int col) const;
  /// Thyra::DefaultBlockedLinearOp of Thyra::TpetraLinearOp blocks (null blocks as above); a
  /// Thyra::PhysicallyBlockedLinearOpBase, so Teko::toBlockedLinearOp accepts it.
  Teuchos::RCP<const Thyra::LinearOpBase<double>> blockedOperator() const;
  /// Range = domain space of blockedOperator(): the product of the three field spaces.
  Teuchos::RCP<const Thyra::ProductVectorSpaceBase<double>> productSpace() const;

  /// Copy a monolithic (owned-map) multivector into a new Thyra product multivector whose
  /// blocks are Tpetra multivectors on the field maps.
  Teuchos::RCP<Thyra::MultiVectorBase<double>> split(const MultiVector& x) const;
  /// Copy a product multivector of productSpace() (from split() or productSpace()->createMember(s))
  /// back into a monolithic multivector with the same number of columns.
  void merge(const Thyra::MultiVectorBase<double>& blocked, MultiVector& x) const;

  struct Impl;

private:
  void build(const CrsMatrix& monolithic);

  FieldLayout layout_;
  double twoMu_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sc::assembly
