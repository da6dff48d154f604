#include "sc/disc/MixedElasticitySpace.hpp"

#include <algorithm>
#include <climits>
#include <unordered_map>

#include <Intrepid2_HDIV_TET_In_FEM.hpp>
#include <Intrepid2_HDIV_TRI_In_FEM.hpp>
#include <Intrepid2_HGRAD_TET_Cn_FEM.hpp>
#include <Intrepid2_HGRAD_TRI_Cn_FEM.hpp>
#include <Shards_CellTopology.hpp>

#include <sc/core/Error.hpp>
#include <sc/mesh/CurvedElements.hpp>
#include <sc/mesh/SimplexMesh.hpp>

#include "sc/disc/detail/Intrepid2Impl.hpp"

namespace sc::disc {

MixedElasticitySpace::Impl::Impl(int d, int k) : dim(d)
{
  // The contact method constrains the normal traction at the face DOF points, so the points'
  // interpolatory weights ∫_F L_p must be positive (docs/contact.md "Degree"). The equispaced open
  // lattice has negative weights from k = 2 on (the middle of 1/4, 1/2, 3/4 has −1/3): a
  // point-wise non-positive traction could then pull on average. Gauss–Lobatto (warp-blend) points
  // keep them positive. k = 1 keeps the equispaced points 1/3, 2/3 it was verified with.
  rtPoints = k == 1 ? Intrepid2::POINTTYPE_EQUISPACED : Intrepid2::POINTTYPE_WARPBLEND;
  if (d == 2) {
    topology = shards::CellTopology(shards::getCellTopologyData<shards::Triangle<3>>());
    // Intrepid2's HDIV order n spans RT_{n-1} (docs/theory.md §"Mixed formulation"): order k+1 for
    // RT_k.
    rt =
        Teuchos::rcp(new Intrepid2::Basis_HDIV_TRI_In_FEM<Device, double, double>(k + 1, rtPoints));
    pk = Teuchos::rcp(new Intrepid2::Basis_HGRAD_TRI_Cn_FEM<Device, double, double>(k));
  } else {
    topology = shards::CellTopology(shards::getCellTopologyData<shards::Tetrahedron<4>>());
    rt =
        Teuchos::rcp(new Intrepid2::Basis_HDIV_TET_In_FEM<Device, double, double>(k + 1, rtPoints));
    pk = Teuchos::rcp(new Intrepid2::Basis_HGRAD_TET_Cn_FEM<Device, double, double>(k));
  }
  // A side's vertices are all but one; the missing one names the mesh's local face.
  for (int s = 0; s <= d; ++s) {
    std::array<bool, 4> present{};
    for (unsigned i = 0; i < topology.getVertexCount(d - 1, s); ++i)
      present[topology.getNodeMap(d - 1, s, i)] = true;
    for (int v = 0; v <= d; ++v)
      if (!present[v]) {
        sideToMeshFace[s] = v;
        meshFaceToSide[v] = s;
      }
  }
}

Intrepid2::Orientation MixedElasticitySpace::Impl::orientation(const int* globalVertices) const
{
  Kokkos::View<int*, Kokkos::HostSpace> nodes("nodes", dim + 1);
  for (int i = 0; i <= dim; ++i)
    nodes(i) = globalVertices[i];
  return Intrepid2::Orientation::getOrientation(topology, nodes);
}

MixedElasticitySpace::MixedElasticitySpace(Teuchos::RCP<const mesh::SimplexMesh> mesh, int degree,
                                           std::vector<int> elementOwner, int rank,
                                           Teuchos::RCP<const mesh::CurvedElements> curved)
    : mesh_(std::move(mesh)), curved_(std::move(curved)), dim_(mesh_->dim()), degree_(degree),
      rank_(rank), elementOwner_(std::move(elementOwner))
{
  SC_THROW_IF(degree < 1, core::InputError,
              "'Discretization/Degree' = "
                  << degree
                  << ": the method needs k >= 1 (docs/theory.md §\"Mixed formulation\").");
  SC_THROW_IF(static_cast<int>(elementOwner_.size()) != mesh_->numElements(), core::InternalError,
              "partition has " << elementOwner_.size() << " entries for " << mesh_->numElements()
                               << " elements");
  SC_THROW_IF(!curved_.is_null() && &curved_->mesh() != mesh_.get(), core::InternalError,
              "MixedElasticitySpace: the curved geometry belongs to another mesh");
  impl_ = std::make_unique<Impl>(dim_, degree_);
  nRT_ = impl_->rt->getCardinality();
  nDP_ = nCP_ = impl_->pk->getCardinality();
  nFaceRT_ = impl_->rt->getDofCount(dim_ - 1, 0);
  for (int e = 0; e < mesh_->numElements(); ++e)
    if (elementOwner_[e] == rank_) ownedElements_.push_back(e);
  numberDofs();
}

MixedElasticitySpace::~MixedElasticitySpace() = default;

void MixedElasticitySpace::numberDofs()
{
  const mesh::SimplexMesh& m = *mesh_;
  const Basis& rt = *impl_->rt;
  const Basis& pk = *impl_->pk;
  const shards::CellTopology& topo = impl_->topology;
  const int d = dim_, ne = m.numElements(), nf = m.numFaces(), nv = m.numVertices();

  // RT (one row): face DOFs per mesh face, then interior DOFs per element.
  const int nIntRT = rt.getDofCount(d, 0);
  nRTGlobal_ = static_cast<long long>(nf) * nFaceRT_ + static_cast<long long>(ne) * nIntRT;
  nDPGlobal_ = static_cast<long long>(ne) * nDP_;

  // CP: vertex, edge, face (3D) and interior DOFs. Edges are mesh faces in 2D; in 3D they are
  // numbered here, only when the degree puts DOFs on them.
  const int cpVertex = pk.getDofCount(0, 0);
  const int cpEdge = pk.getDofCount(1, 0);
  const int cpFace = d == 3 ? pk.getDofCount(2, 0) : 0;
  const int cpCell = pk.getDofCount(d, 0);
  std::unordered_map<long long, int> edgeIndex;  // 3D: key min*nv + max
  if (d == 3 && cpEdge > 0) {
    for (int e = 0; e < ne; ++e) {
      const int* v = m.elementVertices(e);
      for (int a = 0; a < 4; ++a)
        for (int b = a + 1; b < 4; ++b) {
          const long long key =
              static_cast<long long>(std::min(v[a], v[b])) * nv + std::max(v[a], v[b]);
          edgeIndex.emplace(key, static_cast<int>(edgeIndex.size()));
        }
    }
  }
  const long long numEdges = d == 2 ? nf : static_cast<long long>(edgeIndex.size());
  const long long edgeBegin = static_cast<long long>(nv) * cpVertex;
  const long long faceBegin = edgeBegin + numEdges * cpEdge;
  const long long cellBegin = faceBegin + (d == 3 ? static_cast<long long>(nf) * cpFace : 0);
  nCPGlobal_ = cellBegin + static_cast<long long>(ne) * cpCell;

  // Local RT DOFs of each mesh-local face.
  faceLocalRT_.assign(d + 1, {});
  for (int a = 0; a < nRT_; ++a) {
    const auto tag = rt.getDofTag(a);
    if (tag(0) == d - 1) faceLocalRT_[impl_->sideToMeshFace[tag(1)]].push_back(a);
  }

  const int r = numRotationComponents();
  const int L = localSize();
  elementDofs_.assign(static_cast<std::size_t>(ne) * L, -1);
  std::vector<long long> rtLocal(nRT_), cpLocal(nCP_);
  for (int e = 0; e < ne; ++e) {
    const int* gv = m.elementVertices(e);
    const int* faces = m.elementFaces(e);
    for (int a = 0; a < nRT_; ++a) {
      const auto tag = rt.getDofTag(a);
      rtLocal[a] =
          tag(0) == d - 1
              ? static_cast<long long>(faces[impl_->sideToMeshFace[tag(1)]]) * nFaceRT_ + tag(2)
              : static_cast<long long>(nf) * nFaceRT_ + static_cast<long long>(e) * nIntRT + tag(2);
    }
    for (int a = 0; a < nCP_; ++a) {
      const auto tag = pk.getDofTag(a);
      const int scDim = tag(0), scOrd = tag(1), j = tag(2);
      long long g = -1;
      if (scDim == 0) {
        g = static_cast<long long>(gv[topo.getNodeMap(0, scOrd, 0)]) * cpVertex + j;
      } else if (scDim == 1 && d == 2) {
        g = edgeBegin + static_cast<long long>(faces[impl_->sideToMeshFace[scOrd]]) * cpEdge + j;
      } else if (scDim == 1) {
        const int va = gv[topo.getNodeMap(1, scOrd, 0)], vb = gv[topo.getNodeMap(1, scOrd, 1)];
        const long long key = static_cast<long long>(std::min(va, vb)) * nv + std::max(va, vb);
        g = edgeBegin + static_cast<long long>(edgeIndex.at(key)) * cpEdge + j;
      } else if (scDim == 2 && d == 3) {
        g = faceBegin + static_cast<long long>(faces[impl_->sideToMeshFace[scOrd]]) * cpFace + j;
      } else {
        g = cellBegin + static_cast<long long>(e) * cpCell + j;
      }
      cpLocal[a] = g;
    }
    long long* out = &elementDofs_[static_cast<std::size_t>(e) * L];
    for (int row = 0; row < d; ++row)
      for (int a = 0; a < nRT_; ++a)
        out[stressOffset(row) + a] = row * nRTGlobal_ + rtLocal[a];
    for (int c = 0; c < d; ++c)
      for (int a = 0; a < nDP_; ++a)
        out[displacementOffset(c) + a] =
            numStressDofs() + c * nDPGlobal_ + static_cast<long long>(e) * nDP_ + a;
    for (int c = 0; c < r; ++c)
      for (int a = 0; a < nCP_; ++a)
        out[rotationOffset(c) + a] = rotationBegin() + c * nCPGlobal_ + cpLocal[a];
  }

  // Ownership: the lowest rank among the owners of the elements sharing a DOF.
  dofOwner_.assign(static_cast<std::size_t>(numGlobalDofs()), INT_MAX);
  for (int e = 0; e < ne; ++e) {
    const long long* g = elementDofs(e);
    for (int i = 0; i < L; ++i)
      dofOwner_[g[i]] = std::min(dofOwner_[g[i]], elementOwner_[e]);
  }
  for (long long g = 0; g < numGlobalDofs(); ++g) {
    SC_THROW_IF(dofOwner_[g] == INT_MAX, core::InternalError,
                "global DOF " << g << " belongs to no element (numbering bug)");
    if (dofOwner_[g] == rank_) ownedDofs_.push_back(g);
  }
  for (int e : ownedElements_) {
    const long long* g = elementDofs(e);
    overlapDofs_.insert(overlapDofs_.end(), g, g + L);
  }
  std::sort(overlapDofs_.begin(), overlapDofs_.end());
  overlapDofs_.erase(std::unique(overlapDofs_.begin(), overlapDofs_.end()), overlapDofs_.end());
}

}  // namespace sc::disc

namespace sc::disc {
bool MixedElasticitySpace::isCurved(int e) const
{
  return !curved_.is_null() && curved_->isCurved(e);
}
}  // namespace sc::disc
