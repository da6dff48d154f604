#include "sc/disc/FaceDofPoints.hpp"

#include <algorithm>
#include <cmath>

#include <Intrepid2_CellTools.hpp>
#include <Intrepid2_OrientationTools.hpp>
#include <Intrepid2_PointTools.hpp>

#include <sc/core/Error.hpp>
#include <sc/mesh/SimplexMesh.hpp>

#include "sc/disc/ElementValues.hpp"
#include "sc/disc/MixedElasticitySpace.hpp"
#include "sc/disc/detail/AffineMap.hpp"
#include "sc/disc/detail/ElementMap.hpp"
#include "sc/disc/detail/Intrepid2Impl.hpp"

namespace sc::disc {

std::vector<FaceDofPoint> stressFaceDofPoints(const MixedElasticitySpace& space, int e, int lf)
{
  const auto& si = space.impl();
  const auto& m = space.mesh();
  const int d = si.dim, n = space.degree() + 1;  // Intrepid2 order
  const int side = si.meshFaceToSide[lf];
  const shards::CellTopology sideTopo = si.topology.getCellTopologyData(d - 1, 0);
  // Interior lattice points of the side: order n+1 on an edge (n points), n+2 on a triangle
  // (n(n+1)/2 points) — as many as the side has DOFs.
  const int order = d == 2 ? n + 1 : n + 2;
  const int np = Intrepid2::PointTools::getLatticeSize(sideTopo, order, 1);
  const auto& faceDofs = space.stressFaceLocalDofs(lf);
  SC_THROW_IF(np != static_cast<int>(faceDofs.size()), core::InternalError,
              "face lattice has " << np << " points for " << faceDofs.size() << " face DOFs");
  View param("param", np, d - 1), ref("ref", np, d);
  Intrepid2::PointTools::getLattice(param, sideTopo, order, 1, si.rtPoints);
  Intrepid2::CellTools<Device>::mapToReferenceSubcell(ref, param, d - 1, side, si.topology);
  const int nRT = si.rt->getCardinality();
  View vals("vals", nRT, np, d), oriented("oriented", 1, nRT, np, d);
  si.rt->getValues(vals, ref, Intrepid2::OPERATOR_VALUE);
  Kokkos::DynRankView<Intrepid2::Orientation, Device> ort("ort", 1);
  ort(0) = si.orientation(m.elementVertices(e));
  Intrepid2::OrientationTools<Device>::modifyBasisByOrientation(oriented, vals, ort, si.rt.get());

  const AffineMap F(m, e);
  const int f = m.elementFaces(e)[lf];
  auto faceNormal = m.faceNormal(f);
  if (m.faceElements(f)[0] != e)
    for (double& c : faceNormal)
      c = -c;
  // The map at the lattice points: J, det J and the outward normal per point (constant on an
  // affine element, where this is the arithmetic of AffineMap).
  ElementMap map(space, ref);
  map.reinit(e);
  std::vector<std::array<double, 3>> normals(np, faceNormal);
  if (map.curved())
    for (int l = 0; l < np; ++l) {
      double stretch = 0.0;
      map.sideFrame(l, side, normals[l], stretch);
    }

  // T(l, j) = (φ_j·n)(p_l) for the face DOFs.
  const int nF = static_cast<int>(faceDofs.size());
  std::vector<double> T(static_cast<std::size_t>(np) * nF);
  for (int l = 0; l < np; ++l) {
    const double* J = map.jacobian(l);
    for (int j = 0; j < nF; ++j) {
      double flux = 0.0;
      for (int i = 0; i < d; ++i) {
        double phi = 0.0;
        for (int k = 0; k < d; ++k)
          phi += J[3 * i + k] * oriented(0, faceDofs[j], l, k);
        flux += phi / map.det(l) * normals[l][i];
      }
      T[l * nF + j] = flux;
    }
  }
  std::vector<FaceDofPoint> points(nF);
  std::vector<bool> used(nF, false);
  for (int l = 0; l < np; ++l) {
    int best = 0;
    for (int j = 1; j < nF; ++j)
      if (std::abs(T[l * nF + j]) > std::abs(T[l * nF + best])) best = j;
    const double s = T[l * nF + best];
    for (int j = 0; j < nF; ++j)
      SC_THROW_IF(
          j != best && std::abs(T[l * nF + j]) > 1e-10 * std::abs(s), core::InternalError,
          "RT face DOFs of element "
              << e
              << " are not point values at the face lattice "
                 "(the contact method needs nodal DOFs, docs/theory.md §\"Contact and friction\")");
    SC_THROW_IF(used[best], core::InternalError, "two lattice points share face DOF " << best);
    used[best] = true;
    FaceDofPoint& p = points[best];
    p.localDof = faceDofs[best];
    p.scale = s;
    p.normal = normals[l];
    for (int i = 0; i < d; ++i) {
      p.xAffine[i] = F.x0[i];
      for (int k = 0; k < d; ++k)
        p.xAffine[i] += F.J[i][k] * ref(l, k);
      p.x[i] = map.x(l)[i];
    }
  }
  return points;
}

double minRelativeFaceDofWeight(int dim, int degree)
{
  // One reference simplex, all faces on one boundary part.
  std::vector<double> x = dim == 2 ? std::vector<double>{0, 0, 1, 0, 0, 1}
                                   : std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  std::vector<int> cells(dim + 1), faces, parts;
  for (int v = 0; v <= dim; ++v)
    cells[v] = v;
  for (int f = 0; f <= dim; ++f) {  // the face opposite vertex f
    for (int v = 0; v <= dim; ++v)
      if (v != f) faces.push_back(v);
    parts.push_back(0);
  }
  auto mesh = Teuchos::rcp(
      new mesh::SimplexMesh(dim, x, cells, faces, parts, {"Boundary"}, "reference simplex"));
  const MixedElasticitySpace space(mesh, degree, std::vector<int>{0}, 0);
  FaceValues fv(space, 2 * degree + 2);
  double worst = 1e300;
  for (int lf = 0; lf <= dim; ++lf) {
    fv.reinit(0, lf);
    const double area = mesh->faceMeasure(mesh->elementFaces(0)[lf]);
    for (const auto& dp : stressFaceDofPoints(space, 0, lf)) {
      double w = 0.0;
      for (int q = 0; q < fv.numPoints(); ++q)
        w += fv.weight(q) * fv.stressNormal(dp.localDof, q) / dp.scale;
      worst = std::min(worst, w / area);
    }
  }
  return worst;
}

}  // namespace sc::disc
