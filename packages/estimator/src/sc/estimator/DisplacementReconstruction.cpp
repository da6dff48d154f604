#include "sc/estimator/DisplacementReconstruction.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>

#include <Intrepid2_DefaultCubatureFactory.hpp>
#include <Intrepid2_HGRAD_TET_Cn_FEM.hpp>
#include <Intrepid2_HGRAD_TRI_Cn_FEM.hpp>
#include <Teuchos_SerialDenseMatrix.hpp>
#include <Teuchos_SerialDenseSolver.hpp>
#include <Tpetra_Export.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>

#include <sc/assembly/ElementSolution.hpp>
#include <sc/assembly/LoadsAndSupports.hpp>
#include <sc/core/Error.hpp>
#include <sc/disc/ElementValues.hpp>
#include <sc/disc/MixedElasticitySpace.hpp>
#include <sc/disc/detail/ElementMap.hpp>
#include <sc/disc/detail/Intrepid2Impl.hpp>
#include <sc/mesh/SimplexMesh.hpp>

namespace sc::estimator {
namespace {

using disc::Basis;
using disc::Device;
using disc::ElementMap;
using disc::View;
using GO = Tpetra::Map<>::global_ordinal_type;
constexpr int kMaxDegree = 5;
using NodeKey = std::array<int, kMaxDegree>;  // sorted vertex ids, each repeated p·λ_j times

}  // namespace

struct DisplacementReconstruction::Impl {
  Teuchos::RCP<Basis> basis;
  int n = 0;                                // basis functions per element (per component)
  std::vector<std::array<int, 4>> lattice;  // per reference node: p·λ_j, j = 0..d
  View cubPoints, cubWeights;               // element cubature (reference)
  View values, grads;                       // (n, nq), (n, nq, d) at the cubature points
  int cubatureDegree = 0;
  std::unique_ptr<ElementMap> cubatureMap;  // the element map at the cubature points (valuesAt)

  std::vector<long long> elementNodes;  // all elements, n global node ids each
  std::vector<int> overlapIndex;        // global node -> index among this rank's nodes, or -1
  std::vector<long long> overlapNodes;  // this rank's nodes (those of its elements), sorted
  std::vector<long long> vertexNode;    // mesh vertex -> node at that vertex
  std::vector<double> coords;           // 3 per overlap node
  std::vector<double> values_;          // d per overlap node: u^R
  Teuchos::RCP<const Tpetra::Map<>> ownedMap, overlapMap;
  Teuchos::RCP<const Tpetra::Export<>> exporter;
  Teuchos::RCP<const Tpetra::Import<>> importer;
};

DisplacementReconstruction::DisplacementReconstruction(const disc::MixedElasticitySpace& space,
                                                       int degree,
                                                       Teuchos::RCP<const Teuchos::Comm<int>> comm)
    : space_(space), comm_(std::move(comm)), degree_(degree), impl_(std::make_unique<Impl>())
{
  SC_THROW_IF(degree != space.degree() && degree != space.degree() + 1, core::InputError,
              "reconstruction degree "
                  << degree << " for k = " << space.degree()
                  << ": valid are k and k+1 ('Estimator/Reconstruction degree').");
  SC_THROW_IF(degree > kMaxDegree, core::InputError,
              "reconstruction degree " << degree << " > " << kMaxDegree << " is not supported.");
  const auto& m = space.mesh();
  const int d = space.dim(), p = degree;
  auto& I = *impl_;
  if (d == 2)
    I.basis = Teuchos::rcp(new Intrepid2::Basis_HGRAD_TRI_Cn_FEM<Device, double, double>(
        p, Intrepid2::POINTTYPE_EQUISPACED));
  else
    I.basis = Teuchos::rcp(new Intrepid2::Basis_HGRAD_TET_Cn_FEM<Device, double, double>(
        p, Intrepid2::POINTTYPE_EQUISPACED));
  I.n = I.basis->getCardinality();
  {
    View dofCoords("dofCoords", I.n, d);
    I.basis->getDofCoords(dofCoords);
    I.lattice.resize(I.n);
    for (int a = 0; a < I.n; ++a) {
      double sum = 0.0;
      for (int j = 0; j < d; ++j) {
        I.lattice[a][j + 1] = static_cast<int>(std::lround(p * dofCoords(a, j)));
        sum += dofCoords(a, j);
      }
      I.lattice[a][0] = static_cast<int>(std::lround(p * (1.0 - sum)));
    }
  }
  I.cubatureDegree = 2 * std::max(p, space.degree()) + 4;
  {
    auto cub =
        Intrepid2::DefaultCubatureFactory::create<Device>(space.impl().topology, I.cubatureDegree);
    const int nq = cub->getNumPoints();
    I.cubPoints = View("points", nq, d);
    I.cubWeights = View("weights", nq);
    cub->getCubature(I.cubPoints, I.cubWeights);
    I.values = View("values", I.n, nq);
    I.grads = View("grads", I.n, nq, d);
    I.basis->getValues(I.values, I.cubPoints, Intrepid2::OPERATOR_VALUE);
    I.basis->getValues(I.grads, I.cubPoints, Intrepid2::OPERATOR_GRAD);
  }

  // Global node numbering from the replicated mesh: every rank numbers all nodes the same way.
  const int nE = m.numElements();
  std::vector<NodeKey> keys(static_cast<std::size_t>(nE) * I.n);
  for (int e = 0; e < nE; ++e) {
    const int* v = m.elementVertices(e);
    for (int a = 0; a < I.n; ++a) {
      NodeKey key;
      key.fill(-1);
      int pos = 0;
      for (int j = 0; j <= d; ++j)
        for (int r = 0; r < I.lattice[a][j]; ++r)
          key[pos++] = v[j];
      std::sort(key.begin(), key.begin() + p);
      keys[static_cast<std::size_t>(e) * I.n + a] = key;
    }
  }
  std::vector<std::size_t> order(keys.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t x, std::size_t y) { return keys[x] < keys[y]; });
  I.elementNodes.assign(keys.size(), -1);
  long long id = -1;
  for (std::size_t i = 0; i < order.size(); ++i) {
    if (i == 0 || keys[order[i]] != keys[order[i - 1]]) ++id;
    I.elementNodes[order[i]] = id;
  }
  numNodes_ = id + 1;
  keys.clear();
  keys.shrink_to_fit();

  // Owner of a node: the lowest owner among its elements (as for the DOFs of the space).
  const int rank = space.rank();
  const auto& owner = space.elementOwner();
  std::vector<int> nodeOwner(numNodes_, comm_->getSize());
  I.vertexNode.assign(m.numVertices(), -1);
  for (int e = 0; e < nE; ++e)
    for (int a = 0; a < I.n; ++a) {
      const long long g = I.elementNodes[static_cast<std::size_t>(e) * I.n + a];
      nodeOwner[g] = std::min(nodeOwner[g], owner[e]);
      for (int j = 0; j <= d; ++j)
        if (I.lattice[a][j] == p) I.vertexNode[m.elementVertices(e)[j]] = g;
    }
  std::vector<GO> ownedGids;
  for (long long g = 0; g < numNodes_; ++g)
    if (nodeOwner[g] == rank) ownedGids.push_back(g);
  for (int e : space.ownedElements())
    for (int a = 0; a < I.n; ++a)
      I.overlapNodes.push_back(I.elementNodes[static_cast<std::size_t>(e) * I.n + a]);
  std::sort(I.overlapNodes.begin(), I.overlapNodes.end());
  I.overlapNodes.erase(std::unique(I.overlapNodes.begin(), I.overlapNodes.end()),
                       I.overlapNodes.end());
  I.overlapIndex.assign(numNodes_, -1);
  for (std::size_t i = 0; i < I.overlapNodes.size(); ++i)
    I.overlapIndex[I.overlapNodes[i]] = static_cast<int>(i);
  std::vector<GO> overlapGids(I.overlapNodes.begin(), I.overlapNodes.end());
  I.ownedMap =
      Teuchos::rcp(new Tpetra::Map<>(numNodes_, Teuchos::ArrayView<const GO>(ownedGids), 0, comm_));
  I.overlapMap =
      Teuchos::rcp(new Tpetra::Map<>(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                                     Teuchos::ArrayView<const GO>(overlapGids), 0, comm_));
  I.exporter = Teuchos::rcp(new Tpetra::Export<>(I.overlapMap, I.ownedMap));
  I.importer = Teuchos::rcp(new Tpetra::Import<>(I.ownedMap, I.overlapMap));

  // Node coordinates on the element's geometry (the same as σ_h's: straight, or the quadratic
  // map of a curved element, on which u^R is isoparametric-mapped like the stress).
  I.coords.assign(3 * I.overlapNodes.size(), 0.0);
  View dofCoords("dofCoords", I.n, d);
  I.basis->getDofCoords(dofCoords);
  ElementMap nodeMap(space, dofCoords);
  for (int e : space.ownedElements()) {
    nodeMap.reinit(e);
    for (int a = 0; a < I.n; ++a) {
      const int l = I.overlapIndex[I.elementNodes[static_cast<std::size_t>(e) * I.n + a]];
      for (int i = 0; i < 3; ++i)
        I.coords[3 * l + i] = nodeMap.x(a)[i];
    }
  }
}

DisplacementReconstruction::~DisplacementReconstruction() = default;

int DisplacementReconstruction::cubatureDegree() const { return impl_->cubatureDegree; }

void DisplacementReconstruction::reconstruct(assembly::ElementSolution& solution,
                                             const assembly::ElasticityData& data)
{
  auto& I = *impl_;
  const auto& S = space_;
  const auto& m = S.mesh();
  const int d = S.dim(), n = I.n, nq = I.cubPoints.extent(0);
  const double inv2mu = 1.0 / (2.0 * data.material.shearModulus());
  const double cd = data.material.complianceCoefficient(d);
  const auto& terms = assembly::asymmetryTerms(d);

  // Sums of u°(node) over the elements of this rank, and counts (column d).
  Tpetra::MultiVector<> sums(I.overlapMap, d + 1);
  std::vector<Teuchos::ArrayRCP<double>> col(d + 1);
  for (int i = 0; i <= d; ++i)
    col[i] = sums.getDataNonConst(i);

  disc::ElementValues ev(S, I.cubatureDegree);
  SC_THROW_IF(ev.numPoints() != nq, core::InternalError, "cubature mismatch in the reconstruction");
  Teuchos::SerialDenseMatrix<int, double> K(n + 1, n + 1), B(n + 1, d);
  std::vector<double> grad(static_cast<std::size_t>(n) * nq * d);
  assembly::PointValues v;
  ElementMap F(S, I.cubPoints);
  for (int e : S.ownedElements()) {
    ev.reinit(e);
    solution.gather(e);
    F.reinit(e);
    for (int q = 0; q < nq; ++q) {
      double G[3][3];
      F.inverseTranspose(q, G);
      for (int a = 0; a < n; ++a)
        for (int i = 0; i < d; ++i) {
          double s = 0.0;
          for (int j = 0; j < d; ++j)
            s += G[i][j] * I.grads(a, q, j);
          grad[(static_cast<std::size_t>(a) * nq + q) * d + i] = s;
        }
    }
    K.putScalar(0.0);
    B.putScalar(0.0);
    for (int q = 0; q < nq; ++q) {
      solution.evaluate(ev, q, v);
      const double w = ev.weight(q);
      // z_h = Aσ_h + S(θ_h).
      double z[9], trace = 0.0;
      for (int i = 0; i < d; ++i)
        trace += v.sigma[i * d + i];
      for (int i = 0; i < d; ++i)
        for (int j = 0; j < d; ++j)
          z[i * d + j] = inv2mu * (v.sigma[i * d + j] - (i == j ? cd * trace : 0.0));
      for (const auto& t : terms)
        z[t.row * d + t.col] += t.sign * v.theta[t.comp];
      for (int a = 0; a < n; ++a) {
        const double* ga = &grad[(static_cast<std::size_t>(a) * nq + q) * d];
        for (int b = 0; b <= a; ++b) {
          const double* gb = &grad[(static_cast<std::size_t>(b) * nq + q) * d];
          double dot = 0.0;
          for (int j = 0; j < d; ++j)
            dot += ga[j] * gb[j];
          K(a, b) += w * dot;
        }
        K(a, n) += w * I.values(a, q);
        for (int i = 0; i < d; ++i) {
          double s = 0.0;
          for (int j = 0; j < d; ++j)
            s += z[i * d + j] * ga[j];
          B(a, i) += w * s;
        }
      }
      for (int i = 0; i < d; ++i)
        B(n, i) += w * v.u[i];
    }
    for (int a = 0; a < n; ++a) {
      for (int b = 0; b < a; ++b)
        K(b, a) = K(a, b);
      K(n, a) = K(a, n);
    }
    Teuchos::SerialDenseSolver<int, double> solver;
    solver.setMatrix(Teuchos::rcpFromRef(K));
    solver.setVectors(Teuchos::rcpFromRef(B), Teuchos::rcpFromRef(B));
    // The mean row (∫φ ~ |T|) and the stiffness (~ h^{d−2}) differ in scale by h².
    solver.factorWithEquilibration(true);
    SC_THROW_IF(solver.factor() != 0 || solver.solve() != 0, core::InternalError,
                "local Neumann problem of the reconstruction is singular on element " << e);
    // Nodal basis: the coefficients are u° at the Lagrange nodes.
    for (int a = 0; a < n; ++a) {
      const int l = I.overlapIndex[I.elementNodes[static_cast<std::size_t>(e) * n + a]];
      for (int i = 0; i < d; ++i)
        col[i][l] += B(a, i);
      col[d][l] += 1.0;
    }
  }
  col.clear();

  // Sum and count over ranks, average on the owner, bring the averages back to every rank.
  Tpetra::MultiVector<> owned(I.ownedMap, d + 1);
  owned.doExport(sums, *I.exporter, Tpetra::ADD);
  {
    std::vector<Teuchos::ArrayRCP<double>> oc(d + 1);
    for (int i = 0; i <= d; ++i)
      oc[i] = owned.getDataNonConst(i);
    for (std::size_t l = 0; l < I.ownedMap->getNodeNumElements(); ++l)
      for (int i = 0; i < d; ++i)
        oc[i][l] /= oc[d][l];
  }
  sums.doImport(owned, *I.importer, Tpetra::INSERT);
  I.values_.assign(I.overlapNodes.size() * d, 0.0);
  for (int i = 0; i < d; ++i) {
    auto c = sums.getData(i);
    for (std::size_t l = 0; l < I.overlapNodes.size(); ++l)
      I.values_[l * d + i] = c[l];
  }

  // Step 3: u^R = u_D at the nodes of Γ_D faces; at the other nodes of Symmetry / Normal
  // displacement faces the nearest value with u^R·n_j = g_j for every such part j at the node
  // (one part: u^R − (u^R·n − g) n; u^R_a = 0 on x_a = const), and of Components faces
  // likewise u^R·e_i = g_i for each displacement component i. All boundary faces are known on
  // every rank, so a node is set whichever element of it this rank has.
  const auto frameParts = assembly::normalFrameParts(m, data.boundaryConditions);
  std::vector<char> dirichletNode(I.overlapNodes.size(), 0);
  std::map<int, std::vector<std::array<double, 4>>> frameNodes;  // node -> (n, g) per part
  for (int pass = 0; pass < 2; ++pass)
    for (int f : m.boundaryFaces()) {
      const core::BoundaryCondition* bc =
          data.boundaryConditions.find(m.boundaryName(m.faceBoundaryId(f)));
      if (!bc || (pass == 0 ? bc->type != core::BoundaryType::Displacement
                            : !bc->inNormalFrame() && !bc->hasDisplacementComponent()))
        continue;
      const int e = m.faceElements(f)[0];
      const int* faces = m.elementFaces(e);
      int lf = 0;
      while (faces[lf] != f)
        ++lf;
      for (int a = 0; a < n; ++a) {
        if (I.lattice[a][lf] != 0) continue;  // not on the face opposite local vertex lf
        const int l = I.overlapIndex[I.elementNodes[static_cast<std::size_t>(e) * n + a]];
        if (l < 0) continue;
        if (pass == 1) {
          if (dirichletNode[l]) continue;
          auto add = [&list = frameNodes[l]](const double* normal, double g) {
            bool seen = false;
            for (const auto& c : list)
              seen = seen || (c[0] == normal[0] && c[1] == normal[1] && c[2] == normal[2]);
            if (!seen) list.push_back({normal[0], normal[1], normal[2], g});
          };
          if (bc->type == core::BoundaryType::Components) {
            double g[3] = {0, 0, 0};
            const double unusedNormal[3] = {0, 0, 0};  // the displacement components ignore it
            bc->evaluate(&I.coords[3 * l], unusedNormal, d, data.exactSolution, g);
            for (int i = 0; i < d; ++i)
              if (bc->displacementComponent(i)) {
                double axis[3] = {0, 0, 0};
                axis[i] = 1.0;
                add(axis, g[i]);
              }
            continue;
          }
          const double* normal = frameParts.at(bc->boundary).normal.data();
          double gn[3] = {0, 0, 0};  // g n
          bc->evaluate(&I.coords[3 * l], normal, d, data.exactSolution, gn);
          double g = 0.0;
          for (int i = 0; i < d; ++i)
            g += gn[i] * normal[i];
          add(normal, g);
          continue;
        }
        dirichletNode[l] = 1;
        double uD[3] = {0, 0, 0};
        const double unusedNormal[3] = {0, 0, 0};  // u_D does not depend on the normal
        bc->evaluate(&I.coords[3 * l], unusedNormal, d, data.exactSolution, uD);
        for (int i = 0; i < d; ++i)
          I.values_[l * d + i] = uD[i];
      }
    }
  for (const auto& [l, constraints] : frameNodes) {
    // Least-squares projection u ← u + Σ_j λ_j n_j with (n_i·n_j) λ = g − N u, by Gram–Schmidt
    // over the constraints (a constraint dependent on the earlier ones is skipped).
    double* u = &I.values_[static_cast<std::size_t>(l) * d];
    std::vector<std::array<double, 4>> basis;  // orthonormal directions q, with target q·u
    for (const auto& c : constraints) {
      double q[3] = {c[0], c[1], c[2]}, target = c[3];
      for (const auto& b : basis) {
        const double dot = q[0] * b[0] + q[1] * b[1] + q[2] * b[2];
        for (int i = 0; i < 3; ++i)
          q[i] -= dot * b[i];
        target -= dot * b[3];
      }
      const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
      if (norm < 1e-8) continue;
      basis.push_back({q[0] / norm, q[1] / norm, q[2] / norm, target / norm});
    }
    for (const auto& b : basis) {
      double un = 0.0;
      for (int i = 0; i < d; ++i)
        un += u[i] * b[i];
      for (int i = 0; i < d; ++i)
        u[i] += (b[3] - un) * b[i];
    }
  }
}

void DisplacementReconstruction::valuesAt(int e, const disc::ElementValues& ev,
                                          std::vector<double>& u, std::vector<double>& grad) const
{
  auto& I = *impl_;  // the cached cubature map is filled on first use
  const int d = space_.dim(), n = I.n, nq = ev.numPoints();
  SC_THROW_IF(
      nq != static_cast<int>(I.cubPoints.extent(0)), core::InternalError,
      "DisplacementReconstruction::valuesAt needs ElementValues of degree cubatureDegree()");
  if (!I.cubatureMap) I.cubatureMap = std::make_unique<ElementMap>(space_, I.cubPoints);
  ElementMap& F = *I.cubatureMap;
  F.reinit(e);
  {
    // The points of `ev` must be this tabulation's (same cubature rule, same order).
    double dist = 0.0;
    for (int j = 0; j < d; ++j)
      dist += std::abs(F.x(0)[j] - ev.point(0)[j]);
    SC_THROW_IF(dist > 1e-10 * space_.mesh().elementDiameter(e), core::InternalError,
                "DisplacementReconstruction::valuesAt: ElementValues not reinit'ed on element "
                    << e);
  }
  u.assign(static_cast<std::size_t>(nq) * d, 0.0);
  grad.assign(static_cast<std::size_t>(nq) * d * d, 0.0);
  // J^{-T} once per point (constant on affine elements, varying on curved ones).
  std::vector<std::array<std::array<double, 3>, 3>> Gq(nq);
  for (int q = 0; q < nq; ++q) {
    double G[3][3];
    F.inverseTranspose(q, G);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        Gq[q][i][j] = G[i][j];
  }
  for (int a = 0; a < n; ++a) {
    const int l = I.overlapIndex[I.elementNodes[static_cast<std::size_t>(e) * n + a]];
    const double* c = &I.values_[static_cast<std::size_t>(l) * d];
    for (int q = 0; q < nq; ++q) {
      const auto& G = Gq[q];
      double g[3] = {0, 0, 0};
      for (int i = 0; i < d; ++i)
        for (int j = 0; j < d; ++j)
          g[i] += G[i][j] * I.grads(a, q, j);
      for (int i = 0; i < d; ++i) {
        u[q * d + i] += c[i] * I.values(a, q);
        for (int j = 0; j < d; ++j)
          grad[(q * d + i) * d + j] += c[i] * g[j];
      }
    }
  }
}

void DisplacementReconstruction::valueAt(int e, const double* x, double* u) const
{
  const auto& I = *impl_;
  const int d = space_.dim(), n = I.n;
  const auto ref =
      ElementMap::toReference(space_, e, std::vector<double>{x[0], x[1], d == 3 ? x[2] : 0.0});
  View xh("xh", 1, d), vals("vals", n, 1);
  for (int j = 0; j < d; ++j)
    xh(0, j) = ref[j];
  I.basis->getValues(vals, xh, Intrepid2::OPERATOR_VALUE);
  for (int i = 0; i < d; ++i)
    u[i] = 0.0;
  for (int a = 0; a < n; ++a) {
    const int l = I.overlapIndex[I.elementNodes[static_cast<std::size_t>(e) * n + a]];
    for (int i = 0; i < d; ++i)
      u[i] += I.values_[static_cast<std::size_t>(l) * d + i] * vals(a, 0);
  }
}

void DisplacementReconstruction::vertexValue(int v, double* u) const
{
  const auto& I = *impl_;
  const int d = space_.dim();
  const long long g = I.vertexNode[v];
  const int l = g < 0 ? -1 : I.overlapIndex[g];
  SC_THROW_IF(l < 0, core::InternalError,
              "u^R asked at vertex " << v << ", not of this rank's elements");
  for (int i = 0; i < d; ++i)
    u[i] = I.values_[static_cast<std::size_t>(l) * d + i];
}

}  // namespace sc::estimator
