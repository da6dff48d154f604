#pragma once
// The finite element spaces of the dual mixed method (docs/theory.md §"Mixed formulation") on a
// simplicial mesh:
//   σ: d rows, each in RT_k   (Intrepid2 Basis_HDIV_{TRI,TET}_In_FEM(k+1), Piola-mapped)
//   u: d components in DP_k   (Basis_HGRAD_{TRI,TET}_Cn_FEM(k), element-local DOFs)
//   θ: r components in CP_k   (same basis, continuous; r = 1 in 2D, 3 in 3D)
// with a global DOF numbering that neighbours agree on: DOFs on shared faces, edges and vertices
// are numbered per mesh entity, and element basis functions are corrected with Intrepid2's
// OrientationTools (orientation from global vertex ids), so that the j-th DOF of an entity is the
// same function seen from both sides. The numbering is independent of the partition, so the
// global system is the same matrix at any rank count.
//
// Global layout: [σ row 0 | σ row 1 | (σ row 2) | u_0 | u_1 | (u_2) | θ_0 | (θ_1 | θ_2)].
// Element-local layout: the same blocks, each of the element basis' cardinality.
#include <memory>
#include <vector>

#include <Teuchos_RCP.hpp>

namespace sc::mesh {
class SimplexMesh;
class CurvedElements;
}  // namespace sc::mesh

namespace sc::disc {

class MixedElasticitySpace {
public:
  /// `elementOwner`: owning rank of every element (METIS partition); `rank`: this rank.
  /// `curved` (Mesh/Geometry order = 2): the quadratic geometry of the elements at curved
  /// boundaries, on which the bases are mapped by the non-affine Piola maps; null: all affine.
  MixedElasticitySpace(Teuchos::RCP<const mesh::SimplexMesh> mesh, int degree,
                       std::vector<int> elementOwner, int rank,
                       Teuchos::RCP<const mesh::CurvedElements> curved = Teuchos::null);
  ~MixedElasticitySpace();
  MixedElasticitySpace(const MixedElasticitySpace&) = delete;
  MixedElasticitySpace& operator=(const MixedElasticitySpace&) = delete;

  const mesh::SimplexMesh& mesh() const { return *mesh_; }
  Teuchos::RCP<const mesh::SimplexMesh> meshPtr() const { return mesh_; }
  int dim() const { return dim_; }
  int degree() const { return degree_; }
  int rank() const { return rank_; }
  int numRotationComponents() const { return dim_ == 2 ? 1 : 3; }
  /// The quadratic boundary geometry, or null (all elements affine).
  const mesh::CurvedElements* curvedElements() const { return curved_.get(); }
  Teuchos::RCP<const mesh::CurvedElements> curvedElementsPtr() const { return curved_; }
  /// True if element e has a curved (quadratic) map.
  bool isCurved(int e) const;
  /// 1 (all elements affine) or 2 (quadratic geometry at curved boundaries).
  int geometryOrder() const { return curved_.is_null() ? 1 : 2; }

  // Element-local sizes and offsets.
  int stressBasisSize() const { return nRT_; }        ///< RT_k functions per row
  int displacementBasisSize() const { return nDP_; }  ///< P_k functions per component
  int rotationBasisSize() const { return nCP_; }      ///< P_k functions per component
  int stressFaceDofs() const { return nFaceRT_; }     ///< RT DOFs per face and row
  int localSize() const { return dim_ * nRT_ + dim_ * nDP_ + numRotationComponents() * nCP_; }
  int stressOffset(int row) const { return row * nRT_; }
  int displacementOffset(int comp) const { return dim_ * nRT_ + comp * nDP_; }
  int rotationOffset(int comp) const { return dim_ * nRT_ + dim_ * nDP_ + comp * nCP_; }

  // Global sizes.
  long long numStressDofs() const { return dim_ * nRTGlobal_; }
  long long numDisplacementDofs() const { return dim_ * nDPGlobal_; }
  long long numRotationDofs() const { return numRotationComponents() * nCPGlobal_; }
  long long numGlobalDofs() const
  {
    return numStressDofs() + numDisplacementDofs() + numRotationDofs();
  }
  long long displacementBegin() const { return numStressDofs(); }
  long long rotationBegin() const { return numStressDofs() + numDisplacementDofs(); }

  /// Global ids of element e's DOFs, localSize() entries in the element-local layout.
  const long long* elementDofs(int e) const
  {
    return &elementDofs_[static_cast<std::size_t>(e) * localSize()];
  }
  /// Rank owning a global DOF (the lowest owner among the elements that share it).
  int dofOwner(long long gid) const { return dofOwner_[static_cast<std::size_t>(gid)]; }
  /// This rank's DOFs (sorted) and the DOFs of its elements (sorted, unique).
  const std::vector<long long>& ownedDofs() const { return ownedDofs_; }
  const std::vector<long long>& overlapDofs() const { return overlapDofs_; }
  const std::vector<int>& ownedElements() const { return ownedElements_; }
  const std::vector<int>& elementOwner() const { return elementOwner_; }

  /// Element-local indices (0..nRT-1, within one row block) of the RT DOFs on the element's
  /// face opposite local vertex `localFace` (mesh convention).
  const std::vector<int>& stressFaceLocalDofs(int localFace) const
  {
    return faceLocalRT_[localFace];
  }

  /// Intrepid2 objects, for ElementValues / FaceValues (opaque outside the package).
  struct Impl;
  const Impl& impl() const { return *impl_; }

private:
  void numberDofs();

  Teuchos::RCP<const mesh::SimplexMesh> mesh_;
  Teuchos::RCP<const mesh::CurvedElements> curved_;
  int dim_, degree_, rank_;
  std::unique_ptr<Impl> impl_;
  int nRT_ = 0, nDP_ = 0, nCP_ = 0, nFaceRT_ = 0;
  long long nRTGlobal_ = 0, nDPGlobal_ = 0, nCPGlobal_ = 0;
  std::vector<int> elementOwner_;
  std::vector<int> ownedElements_;
  std::vector<long long> elementDofs_;
  std::vector<int> dofOwner_;
  std::vector<long long> ownedDofs_, overlapDofs_;
  std::vector<std::vector<int>> faceLocalRT_;  // mesh local face -> local RT dofs
};

}  // namespace sc::disc
