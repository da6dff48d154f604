// The point values of the XDMF contact grid (contact::pointValues, docs/output.md "Fields in a
// run's files") against σ_h evaluated directly: at every contact point, the traction
// t = σ_h(x) n_F of the face's element (its RT basis at x, face DOFs only: the other RT
// functions have no normal trace on the face) in the point's frame must equal the point values,
// on straight faces, where both are the same polynomial: 3D at k = 1 (Bernstein coefficients on
// the vertices, which are values there) and k = 2 (control points at the edge midpoints, where
// coefficients are not values), 2D at k = 1, 2 (point constraints: the coefficients are the
// values). Also the weights (Σ_p W_p = Σ_F |F|: the constraint bases sum to 1 on a face) and the
// gaps and slips of the contact conditions (r_N = G on active points, r_T = 0 on stick points).
#include <algorithm>
#include <array>
#include <cmath>
#include <set>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_UnitTestHarness.hpp>
#include <Tpetra_MultiVector.hpp>

#include <sc/assembly/MixedElasticitySystem.hpp>
#include <sc/contact/ActiveSetSolver.hpp>
#include <sc/contact/Obstacle.hpp>
#include <sc/disc/ElementValues.hpp>
#include <sc/disc/MixedElasticitySpace.hpp>
#include <sc/mesh/BisectionRefiner.hpp>
#include <sc/mesh/MeshFactory.hpp>
#include <sc/mesh/SimplexMesh.hpp>
#include <sc/solvers/LinearSolverFactory.hpp>

#include "ContactTestSettings.hpp"

namespace {

struct Case {
  int dim, degree;
  double meshSize, displacement;
};

// Half disc / half ball (E = 2.5, ν = 0.25) pressed by `displacement` onto the plane through the
// origin, Coulomb μ_F = 0.4, straight faces; checks as above.
void checkPointValues(const Case& c, Teuchos::FancyOStream& out, bool& success)
{
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const int d = c.dim;
  Teuchos::ParameterList meshList;
  meshList.set("Source", std::string(d == 2 ? "Half disc" : "Half ball"));
  meshList.set("Initial mesh size", c.meshSize);
  auto refiner = sc::mesh::MeshFactory::build(meshList, d, *comm);
  auto m = refiner->mesh();
  sc::assembly::MixedElasticitySystem system(m, c.degree, comm, Teuchos::null);
  const auto& space = system.space();
  sc::core::BoundaryConditions bcs;
  std::vector<double> uD(d, 0.0);
  uD[d - 1] = -c.displacement;
  bcs.conditions.push_back({"Top", sc::core::BoundaryType::Displacement, uD, false});
  const std::string contactName = d == 2 ? "Arc" : "Cap";
  bcs.conditions.push_back({contactName, sc::core::BoundaryType::Contact, {}, false});
  const sc::core::Material material{2.5, 0.25};
  system.assemble({material, bcs, nullptr});
  sc::contact::ContactSettings cs = sc::contact::testing::defaultContactSettings();
  cs.obstaclePoint.assign(d, 0.0);
  cs.obstacleNormal.assign(d, 0.0);
  cs.obstacleNormal[d - 1] = 1.0;
  cs.frictionLaw = sc::contact::FrictionLaw::Coulomb;
  cs.frictionCoefficient = 0.4;
  sc::contact::ActiveSetSolver contact(space, cs, material, {contactName}, comm);
  Teuchos::ParameterList solverList;
  solverList.set("Type", std::string("MUMPS"));
  auto solver = sc::solvers::createLinearSolver(solverList);
  const auto& assembler = system.assembler();
  auto x = assembler.createVector();
  system.prepareSolver(*solver);
  contact.solve(*assembler.matrix(), *assembler.rhs(), *solver, *x);
  TEST_ASSERT(contact.statistics().converged);
  TEST_EQUALITY(contact.bernsteinConstraints(), d == 3);

  const auto& points = contact.points();
  const auto values = sc::contact::pointValues(points, d, c.degree, contact.bernsteinConstraints());
  TEST_EQUALITY(values.size(), points.size());
  auto xv = x->getData(0);
  const auto& map = *x->getMap();
  // Local maxima: |σ_N| over the points, the differences, the gap of active points, the slip of
  // stick points; the sums of the weights and of the contact faces' measures; counts.
  double local[6] = {0, 0, 0, 0, 0, 0};
  double weights[2] = {0, 0};
  long long counts[2] = {0, 0};  // active points, stick points
  std::set<int> faces;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& p = points[i];
    const auto& v = values[i];
    const int e = m->faceElements(p.face)[0];
    int lf = 0;
    while (m->elementFaces(e)[lf] != p.face)
      ++lf;
    sc::disc::FaceValues fv(space, 2);
    fv.reinit(e, lf);
    const auto nF = fv.normal(0);
    if (faces.insert(p.face).second) weights[1] += fv.measure();
    weights[0] += p.weight;
    sc::disc::ElementValues ev(space, 1);
    ev.reinitAtPoints(e, {p.x[0], p.x[1], p.x[2]});
    std::array<double, 3> t{0, 0, 0};
    for (int a : space.stressFaceLocalDofs(lf)) {
      double phiN = 0.0;
      for (int k = 0; k < d; ++k)
        phiN += ev.stress(a, 0, k) * nF[k];
      for (int row = 0; row < d; ++row)
        t[row] += xv[map.getLocalElement(space.elementDofs(e)[space.stressOffset(row) + a])] * phiN;
    }
    auto dot = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
      return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    };
    local[0] = std::max(local[0], std::abs(dot(t, p.n)));
    local[1] = std::max(local[1], std::abs(v.pressure + dot(t, p.n)));
    local[2] = std::max(
        {local[2], std::abs(v.sigmaT[0] - dot(t, p.t1)), std::abs(v.sigmaT[1] - dot(t, p.t2))});
    // How far the values are from the coefficients (non-zero where that matters: 3D, k = 2).
    local[3] = std::max(local[3], std::abs(v.pressure + p.sigmaN));
    if (p.status != sc::contact::PointStatus::Free) {
      ++counts[0];
      local[4] = std::max(local[4], std::abs(v.gap));
    } else {
      local[4] = std::max(local[4], -v.gap);  // the gap left open is not negative
    }
    if (p.status == sc::contact::PointStatus::Stick) {
      ++counts[1];
      local[5] = std::max(local[5], std::hypot(v.slip[0], v.slip[1]));
    }
  }
  double global[6], sums[2];
  long long totals[2];
  Teuchos::reduceAll<int, double>(*comm, Teuchos::REDUCE_MAX, 6, local, global);
  Teuchos::reduceAll<int, double>(*comm, Teuchos::REDUCE_SUM, 2, weights, sums);
  Teuchos::reduceAll<int, long long>(*comm, Teuchos::REDUCE_SUM, 2, counts, totals);
  const double pmax = global[0];
  out << d << "D, k = " << c.degree << ": max |σ_N| " << pmax << ", differences from σ_h: pressure "
      << global[1] / pmax << ", σ_T " << global[2] / pmax << " (relative); values − coefficients "
      << global[3] / pmax << "; Σ W " << sums[0] << ", Σ |F| " << sums[1] << "; " << totals[0]
      << " active, " << totals[1] << " stick points; |gap| on active points, −gap: " << global[4]
      << ", |slip| on stick points " << global[5] << "\n";
  TEST_COMPARE(totals[0], >, 0);
  TEST_COMPARE(pmax, >, 0.0);
  TEST_COMPARE(global[1], <=, 1e-11 * pmax);
  TEST_COMPARE(global[2], <=, 1e-11 * pmax);
  if (d == 3 && c.degree == 2) {
    TEST_COMPARE(global[3], >, 1e-3 * pmax);  // the evaluation is not the identity here
  } else {
    TEST_COMPARE(global[3], <=, 1e-14 * pmax);
  }
  TEST_FLOATING_EQUALITY(sums[0], sums[1], 1e-12);
  TEST_COMPARE(global[4], <=, 1e-9 * c.displacement);
  TEST_COMPARE(global[5], <=, 1e-9 * c.displacement);
}

}  // namespace

TEUCHOS_UNIT_TEST(ContactFields, PointValuesAreStressValues3D)
{
  for (int k : {1, 2})
    checkPointValues({3, k, 0.5, 0.1}, out, success);
}

TEUCHOS_UNIT_TEST(ContactFields, PointValuesAreStressValues2D)
{
  for (int k : {1, 2})
    checkPointValues({2, k, 0.2, 0.01}, out, success);
}
