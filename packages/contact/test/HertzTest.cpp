// Hertz contact (issue #5 acceptance; DESIGN §3, §9), at 1, 2 and 4 ranks. References:
// plane-strain Hertz (Johnson 1985): E* = E/(1−ν²), a = √(4PR/(πE*)), p0 = 2P/(πa),
// p(x) = p0 √(1 − x²/a²), with P the computed resultant (the half disc is finite).
#include <cmath>

#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_UnitTestHarness.hpp>

#include <sc/assembly/MixedElasticityAssembler.hpp>
#include <sc/contact/ActiveSetSolver.hpp>
#include <sc/contact/ContactSummary.hpp>
#include <sc/disc/MixedElasticitySpace.hpp>
#include <sc/mesh/BisectionRefiner.hpp>
#include <sc/mesh/MeshFactory.hpp>
#include <sc/mesh/Partitioning.hpp>
#include <sc/mesh/SimplexMesh.hpp>
#include <sc/solvers/DirectSolver.hpp>
#include <sc/solvers/LinearSolverFactory.hpp>
#include <Tpetra_MultiVector.hpp>

namespace {

struct HertzCase {
  int dim = 2;
  double E = 20600.0, nu = 0.28, displacement = 0.01;
  sc::core::FrictionLaw law = sc::core::FrictionLaw::None;
  double mu = 0.0;
  double meshSize = 0.1;
  int localRefinements = 6;  ///< bisection sweeps of the elements near the contact zone
  double refineRadius = 0.25;
  std::string solver = "MUMPS";
};

struct HertzResult {
  sc::contact::ContactSummary summary;
  std::vector<sc::contact::ContactPoint> points;  // local points
  sc::contact::ContactStatistics stats;
  std::vector<double> x;  // local solution copy
};

HertzResult solveHertz(const HertzCase& h)
{
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const int d = h.dim;
  Teuchos::ParameterList meshList;
  meshList.set("Source", std::string(d == 2 ? "Half disc" : "Half ball"));
  meshList.set("Initial mesh size", h.meshSize);
  auto refiner = sc::mesh::MeshFactory::build(meshList, d, *comm);
  for (int r = 0; r < h.localRefinements; ++r) {
    auto m = refiner->mesh();
    std::vector<int> marked;
    for (int e = 0; e < m->numElements(); ++e) {
      double c[3] = {0, 0, 0};
      for (int i = 0; i <= d; ++i)
        for (int j = 0; j < d; ++j)
          c[j] += m->vertex(m->elementVertices(e)[i])[j] / (d + 1);
      if (std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) < h.refineRadius)
        marked.push_back(e);
    }
    refiner->refine(marked);
  }
  auto m = refiner->mesh();
  auto owner = sc::mesh::partitionElements(*m, *comm);
  auto space = Teuchos::rcp(new sc::disc::MixedElasticitySpace(m, 1, owner, comm->getRank()));
  sc::assembly::MixedElasticityAssembler assembler(space, comm);
  sc::core::BoundaryConditions bcs;
  std::vector<double> uD(d, 0.0);
  uD[d - 1] = -h.displacement;
  bcs.conditions.push_back({"Top", sc::core::BoundaryType::Displacement, uD, false});
  const std::string contactName = d == 2 ? "Arc" : "Cap";
  bcs.conditions.push_back({contactName, sc::core::BoundaryType::Contact, {}, false});
  sc::core::Material material{h.E, h.nu};
  assembler.assemble({material, bcs, nullptr});
  sc::core::ContactSettings cs;
  cs.obstaclePoint.assign(d, 0.0);
  cs.obstacleNormal.assign(d, 0.0);
  cs.obstacleNormal[d - 1] = 1.0;
  cs.frictionLaw = h.law;
  cs.frictionCoefficient = h.mu;
  Teuchos::ParameterList newton;
  sc::contact::ActiveSetSolver contact(*space, cs, material, {contactName}, newton, comm);
  Teuchos::ParameterList solverList;
  solverList.set("Type", h.solver);
  auto solver = sc::solvers::createDirectSolver(solverList);
  auto x = assembler.createVector();
  contact.solve(*assembler.matrix(), *assembler.rhs(), *solver, *x);
  HertzResult r;
  r.summary = sc::contact::summarizeContact(contact.points(), d, cs.obstacleNormal, *comm);
  r.points = contact.points();
  r.stats = contact.statistics();
  auto xv = x->getData(0);
  r.x.assign(xv.begin(), xv.end());
  return r;
}

double hertzHalfWidth(double P, double E, double nu)
{
  return std::sqrt(4.0 * P * 1.0 / (M_PI * E / (1.0 - nu * nu)));
}

}  // namespace

TEUCHOS_UNIT_TEST(Hertz, Frictionless2D)
{
  HertzCase h;
  const auto r = solveHertz(h);
  const double P = r.summary.force[1];  // the foundation pushes the body up
  const double a = hertzHalfWidth(P, h.E, h.nu), p0 = 2.0 * P / (M_PI * a);
  out << "P = " << P << ", a = " << r.summary.zoneSize << " (Hertz " << a << "), p0 = "
      << r.summary.maxPressure << " (Hertz " << p0 << "), Newton steps " << r.stats.newtonIterations
      << ", centre " << r.summary.center[0] << "\n";
  TEST_ASSERT(r.stats.converged);
  TEST_COMPARE(P, >, 0.0);
  TEST_COMPARE(std::abs(r.summary.zoneSize - a), <=, 0.03 * a);
  TEST_COMPARE(std::abs(r.summary.maxPressure - p0), <=, 0.03 * p0);
  // Symmetry about x = 0: no horizontal resultant, zone centred.
  TEST_COMPARE(std::abs(r.summary.force[0]), <=, 1e-3 * P);
  TEST_COMPARE(std::abs(r.summary.center[0]), <=, 0.01 * a);
  // Profile in the inner 80% of the zone.
  double worst = 0.0;
  for (const auto& p : r.points)
    if (std::abs(p.x[0]) < 0.8 * a)
      worst = std::max(worst, std::abs(-p.sigmaN - p0 * std::sqrt(1.0 - p.x[0] * p.x[0] / (a * a))));
  out << "worst profile deviation " << worst / p0 * 100 << "% of p0\n";
  TEST_COMPARE(worst, <=, 0.05 * p0);
}

TEUCHOS_UNIT_TEST(Hertz, Coulomb2D)
{
  HertzCase h;
  h.law = sc::core::FrictionLaw::Coulomb;
  h.mu = 0.4;
  const auto r = solveHertz(h);
  out << "stick half-width " << r.summary.stickZoneSize << " of " << r.summary.zoneSize
      << ", points free/stick/slip " << r.summary.numFree << "/" << r.summary.numStick << "/"
      << r.summary.numSlip << ", Newton steps " << r.stats.newtonIterations << "\n";
  TEST_ASSERT(r.stats.converged);
  TEST_COMPARE(r.summary.numStick, >, 0);
  TEST_COMPARE(r.summary.numSlip, >, 0);
  TEST_COMPARE(r.summary.stickZoneSize, <, r.summary.zoneSize);
  // Coulomb on slip points: |σ_T| = μ|σ_N| to round-off; stick points inside the cone.
  for (const auto& p : r.points) {
    if (p.status == sc::contact::PointStatus::Slip)
      TEST_COMPARE(std::abs(std::abs(p.sigmaT[0]) - h.mu * std::abs(p.sigmaN)), <=,
                   1e-9 * std::abs(p.sigmaN));
    if (p.status == sc::contact::PointStatus::Stick)
      TEST_COMPARE(std::abs(p.sigmaT[0]), <=, h.mu * std::abs(p.sigmaN) * (1 + 1e-9));
  }
}
