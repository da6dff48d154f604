#include "sc/disc/detail/ElementMap.hpp"

#include <cmath>

#include <Intrepid2_CellTools.hpp>
#include <Intrepid2_HGRAD_TET_C2_FEM.hpp>
#include <Intrepid2_HGRAD_TRI_C2_FEM.hpp>

#include <sc/core/Error.hpp>
#include <sc/mesh/CurvedElements.hpp>
#include <sc/mesh/SimplexMesh.hpp>

#include "sc/disc/MixedElasticitySpace.hpp"
#include "sc/disc/detail/AffineMap.hpp"

namespace sc::disc {
namespace {

using CellTools = Intrepid2::CellTools<Device>;

Teuchos::RCP<Basis> quadraticBasis(int d)
{
  if (d == 2) return Teuchos::rcp(new Intrepid2::Basis_HGRAD_TRI_C2_FEM<Device, double, double>());
  return Teuchos::rcp(new Intrepid2::Basis_HGRAD_TET_C2_FEM<Device, double, double>());
}

shards::CellTopology quadraticTopology(int d)
{
  return d == 2 ? shards::CellTopology(shards::getCellTopologyData<shards::Triangle<6>>())
                : shards::CellTopology(shards::getCellTopologyData<shards::Tetrahedron<10>>());
}

View nodeWorkset(const MixedElasticitySpace& space, int e)
{
  const auto& c = *space.curvedElements();
  const int d = space.dim(), nN = c.nodesPerElement();
  std::vector<double> xyz(3 * static_cast<std::size_t>(nN));
  c.nodes(e, xyz.data());
  View nodes("nodes", 1, nN, d);
  for (int a = 0; a < nN; ++a)
    for (int i = 0; i < d; ++i)
      nodes(0, a, i) = xyz[3 * a + i];
  return nodes;
}

}  // namespace

ElementMap::ElementMap(const MixedElasticitySpace& space, const View& refPoints)
    : space_(space), d_(space.dim()), nq_(static_cast<int>(refPoints.extent(0))),
      refPoints_(refPoints)
{
  x_.assign(3 * static_cast<std::size_t>(nq_), 0.0);
  J_.assign(9 * static_cast<std::size_t>(nq_), 0.0);
  det_.assign(nq_, 0.0);
  if (!space.curvedElements()) return;
  auto basis = quadraticBasis(d_);
  const int nN = basis->getCardinality();
  p2Values_ = View("p2Values", nN, nq_);
  p2Grads_ = View("p2Grads", nN, nq_, d_);
  basis->getValues(p2Values_, refPoints, Intrepid2::OPERATOR_VALUE);
  basis->getValues(p2Grads_, refPoints, Intrepid2::OPERATOR_GRAD);
  const auto& topo = space.impl().topology;
  sideTangents_.assign(static_cast<std::size_t>(d_ + 1) * (d_ - 1), {0, 0, 0});
  for (int s = 0; s <= d_; ++s) {
    if (d_ == 2) {
      View t("t", 2);
      CellTools::getReferenceEdgeTangent(t, s, topo);
      sideTangents_[s] = {t(0), t(1), 0.0};
    } else {
      View u("u", 3), v("v", 3);
      CellTools::getReferenceFaceTangents(u, v, s, topo);
      sideTangents_[2 * s] = {u(0), u(1), u(2)};
      sideTangents_[2 * s + 1] = {v(0), v(1), v(2)};
    }
  }
}

void ElementMap::reinit(int e)
{
  element_ = e;
  curved_ = space_.isCurved(e);
  if (!curved_) {
    // The affine path: the same arithmetic as AffineMap everywhere else (bit-identical results
    // on straight meshes whatever the geometry order).
    const AffineMap F(space_.mesh(), e);
    for (int q = 0; q < nq_; ++q) {
      double xh[3] = {0, 0, 0};
      for (int i = 0; i < d_; ++i)
        xh[i] = refPoints_(q, i);
      F.map(xh, d_, &x_[3 * q]);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          J_[9 * q + 3 * i + j] = F.J[i][j];
      det_[q] = F.det;
    }
    return;
  }
  const View nodes = nodeWorkset(space_, e);
  const int nN = static_cast<int>(nodes.extent(1));
  View jac("jac", 1, nq_, d_, d_), det("det", 1, nq_);
  CellTools::setJacobian(jac, nodes, p2Grads_);
  CellTools::setJacobianDet(det, jac);
  for (int q = 0; q < nq_; ++q) {
    for (int i = 0; i < 3; ++i)
      x_[3 * q + i] = 0.0;
    for (int a = 0; a < nN; ++a)
      for (int i = 0; i < d_; ++i)
        x_[3 * q + i] += nodes(0, a, i) * p2Values_(a, q);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        J_[9 * q + 3 * i + j] = i < d_ && j < d_ ? jac(0, q, i, j) : 0.0;
    det_[q] = det(0, q);
    SC_THROW_IF(!(det_[q] > 0.0), core::InputError,
                "the quadratic (curved-boundary) map of element "
                    << e << " is not invertible "
                    << "(det J = " << det_[q] << " at a quadrature point): the mesh is too coarse "
                    << "for the boundary's curvature. Make 'Mesh/Initial mesh size' smaller or set "
                    << "'Mesh/Geometry order' = 1.");
  }
}

void ElementMap::inverseTranspose(int q, double G[3][3]) const
{
  double J[3][3], inv[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      J[i][j] = jacobian(q)[3 * i + j];
  invertJacobian(d_, J, det_[q], inv);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      G[i][j] = inv[j][i];
}

void ElementMap::sideFrame(int q, int side, std::array<double, 3>& n, double& stretch) const
{
  SC_THROW_IF(sideTangents_.empty(), core::InternalError,
              "ElementMap::sideFrame needs a curved space");
  const double* J = jacobian(q);
  auto apply = [&](const std::array<double, 3>& t) {
    std::array<double, 3> v{0, 0, 0};
    for (int i = 0; i < d_; ++i)
      for (int j = 0; j < d_; ++j)
        v[i] += J[3 * i + j] * t[j];
    return v;
  };
  if (d_ == 2) {
    const auto t = apply(sideTangents_[side]);
    n = {t[1], -t[0], 0.0};
  } else {
    const auto u = apply(sideTangents_[2 * side]), v = apply(sideTangents_[2 * side + 1]);
    n = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  }
  stretch = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (double& c : n)
    c /= stretch;
  // CellTools' side parametrisations are positively oriented (outward normals on the reference
  // cell) and det J > 0; checked against the straight face's outward normal all the same.
  const auto& m = space_.mesh();
  const int f = m.elementFaces(element_)[space_.impl().sideToMeshFace[side]];
  auto ns = m.faceNormal(f);
  const double sign = m.faceElements(f)[0] == element_ ? 1.0 : -1.0;
  const double dot = sign * (ns[0] * n[0] + ns[1] * n[1] + ns[2] * n[2]);
  SC_THROW_IF(!(dot > 0.0), core::InputError,
              "the curved face "
                  << f << " of element " << element_ << " turns by more than 90° "
                  << "from its chord: the mesh is too coarse for the boundary's curvature. Make "
                  << "'Mesh/Initial mesh size' smaller or set 'Mesh/Geometry order' = 1.");
}

std::vector<double> ElementMap::toReference(const MixedElasticitySpace& space, int e,
                                            const std::vector<double>& physicalPoints)
{
  const int d = space.dim(), n = static_cast<int>(physicalPoints.size() / 3);
  std::vector<double> xh(static_cast<std::size_t>(n) * d, 0.0);
  if (!space.isCurved(e)) {
    const AffineMap F(space.mesh(), e);
    double inv[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    F.inverse(d, inv);
    for (int q = 0; q < n; ++q)
      for (int i = 0; i < d; ++i) {
        double v = 0.0;
        for (int j = 0; j < d; ++j)
          v += inv[i][j] * (physicalPoints[q * 3 + j] - F.x0[j]);
        xh[q * d + i] = v;
      }
    return xh;
  }
  View phys("phys", 1, n, d), ref("ref", 1, n, d);
  for (int q = 0; q < n; ++q)
    for (int i = 0; i < d; ++i)
      phys(0, q, i) = physicalPoints[q * 3 + i];
  CellTools::mapToReferenceFrame(ref, phys, nodeWorkset(space, e), quadraticTopology(d));
  for (int q = 0; q < n; ++q)
    for (int i = 0; i < d; ++i)
      xh[q * d + i] = ref(0, q, i);
  return xh;
}

}  // namespace sc::disc
