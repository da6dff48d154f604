// Displacement reconstruction and estimator: exactness and partition independence at 1,
// 2 and 4 ranks (docs/verification.md "Estimator and reconstruction"). Source of the expected
// numbers: analytic. For the linear patch solution (σ linear and symmetric, u quadratic, θ linear)
// the mixed method reproduces σ and θ exactly and u_h is the L² projection of u, so z_h = ∇u, u° =
// u on every element, the averages and the Dirichlet values are u: u^R = u and every part of η is
// zero up to round-off (docs/theory.md §"Estimator": prototype 1e-14).
#include <algorithm>
#include <cmath>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_UnitTestHarness.hpp>

#include <sc/assembly/ElementSolution.hpp>
#include <sc/disc/ElementValues.hpp>
#include <sc/estimator/ErrorEstimator.hpp>

#include <sc/testing/ElasticityTestProblem.hpp>

namespace {

using sc::test::VerificationSetup;

sc::estimator::EstimatorSettings settingsKPlusOne()
{
  sc::estimator::EstimatorSettings s;
  s.reconstructionDegreeKPlusOne = true;
  return s;
}

void exactness(int dim, int degree, Teuchos::FancyOStream& out, bool& success)
{
  auto comm = Teuchos::DefaultComm<int>::getComm();
  VerificationSetup s;
  s.source = dim == 2 ? "Unit square" : "Unit cube";
  s.dim = dim;
  s.meshSize = 0.5;
  s.levels = dim == 2 ? 2 : 1;
  s.initialRefinements = 1;
  s.degree = degree;
  s.exact = "Linear patch";
  s.nu = 0.3;
  s.solver = "MUMPS";
  sc::test::solveVerification(
      s, comm,
      [&](int level, const sc::assembly::MixedElasticityAssembler& A,
          const Tpetra::MultiVector<>& x, const sc::assembly::ElasticityData& data) {
        sc::estimator::ErrorEstimator estimator(A, settingsKPlusOne(), comm);
        const auto est = estimator.estimate(x, data);
        const auto& rec = estimator.reconstruction();
        // u^R − u at the vertices and at the centroid of every owned element.
        const auto& S = A.space();
        const auto& m = S.mesh();
        double localErr = 0.0, localMax = 0.0;
        for (int e : S.ownedElements()) {
          const int* v = m.elementVertices(e);
          double centroid[3] = {0, 0, 0};
          for (int i = 0; i <= dim; ++i)
            for (int c = 0; c < dim; ++c)
              centroid[c] += m.vertex(v[i])[c] / (dim + 1);
          for (int i = 0; i <= dim + 1; ++i) {
            const double* x = i <= dim ? m.vertex(v[i]) : centroid;
            double uR[3], u[3];
            if (i <= dim)
              rec.vertexValue(v[i], uR);
            else
              rec.valueAt(e, x, uR);
            data.exactSolution->displacement(x, u);
            for (int c = 0; c < dim; ++c) {
              localErr = std::max(localErr, std::abs(uR[c] - u[c]));
              localMax = std::max(localMax, std::abs(u[c]));
            }
          }
        }
        double err = 0.0, umax = 0.0;
        Teuchos::reduceAll<int, double>(*comm, Teuchos::REDUCE_MAX, 1, &localErr, &err);
        Teuchos::reduceAll<int, double>(*comm, Teuchos::REDUCE_MAX, 1, &localMax, &umax);
        const double norm2 = std::pow(est.stressEnergyNorm, 2);
        out << dim << "D k=" << degree << " level " << level << ": nodes " << rec.numGlobalNodes()
            << ", max|u^R - u| / max|u| = " << err / umax << ", eta^2 / |A^1/2 sigma_h|^2: volume "
            << est.squared("volume") / norm2 << ", asymmetry " << est.squared("asymmetry") / norm2
            << ", oscillation " << est.squared("oscillation") / norm2 << "\n";
        TEST_COMPARE(err / umax, <, 1e-11);
        TEST_COMPARE(est.squared("volume") / norm2, <, 1e-22);
        TEST_COMPARE(est.squared("asymmetry") / norm2, <, 1e-22);
        TEST_COMPARE(est.squared("oscillation") / norm2, <, 1e-22);
        TEST_COMPARE(est.total() / est.stressEnergyNorm, <, 1e-11);
      });
}

// The estimate of the METIS partition equals the estimate with every element on rank 0, element
// by element (the averaging at shared nodes sums the same values in another order only).
void partitionIndependence(int dim, Teuchos::FancyOStream& out, bool& success)
{
  auto comm = Teuchos::DefaultComm<int>::getComm();
  std::vector<std::vector<double>> indicators;
  std::vector<std::vector<double>> parts;
  for (bool serial : {true, false}) {
    VerificationSetup s;
    s.source = dim == 2 ? "Unit square" : "Unit cube";
    s.dim = dim;
    s.meshSize = 0.5;
    s.levels = 1;
    s.initialRefinements = dim == 2 ? 2 : 1;
    s.nu = 0.4;
    s.solver = "MUMPS";
    s.allOnRankZero = serial;
    sc::test::solveVerification(
        s, comm,
        [&](int, const sc::assembly::MixedElasticityAssembler& A, const Tpetra::MultiVector<>& x,
            const sc::assembly::ElasticityData& data) {
          sc::estimator::ErrorEstimator estimator(A, settingsKPlusOne(), comm);
          const auto est = estimator.estimate(x, data);
          const auto& S = A.space();
          const int ne = S.mesh().numElements();
          std::vector<double> local(ne, 0.0), all(ne, 0.0);
          for (std::size_t i = 0; i < S.ownedElements().size(); ++i)
            local[S.ownedElements()[i]] = est.indicators[i];
          Teuchos::reduceAll<int, double>(*comm, Teuchos::REDUCE_SUM, ne, local.data(), all.data());
          indicators.push_back(all);
          parts.push_back(
              {est.squared("volume"), est.squared("asymmetry"), est.squared("oscillation")});
        });
  }
  double maxRel = 0.0, maxEta = 0.0;
  for (double v : indicators[0])
    maxEta = std::max(maxEta, v);
  for (std::size_t e = 0; e < indicators[0].size(); ++e)
    maxRel = std::max(maxRel, std::abs(indicators[0][e] - indicators[1][e]) / maxEta);
  out << dim << "D, " << comm->getSize()
      << " rank(s): max |eta_T^2(all on rank 0) - eta_T^2(METIS)| / max eta_T^2 = " << maxRel
      << "; volume " << parts[0][0] << " vs " << parts[1][0] << "\n";
  TEST_COMPARE(maxRel, <, 1e-10);
  for (int i = 0; i < 3; ++i)
    TEST_FLOATING_EQUALITY(parts[0][i], parts[1][i], 1e-10);
}

}  // namespace

TEUCHOS_UNIT_TEST(Reconstruction, ExactQuadratic2DDegree1) { exactness(2, 1, out, success); }
TEUCHOS_UNIT_TEST(Reconstruction, ExactQuadratic2DDegree2) { exactness(2, 2, out, success); }
TEUCHOS_UNIT_TEST(Reconstruction, ExactQuadratic3DDegree1) { exactness(3, 1, out, success); }
TEUCHOS_UNIT_TEST(Reconstruction, PartitionIndependent2D)
{
  partitionIndependence(2, out, success);
}
TEUCHOS_UNIT_TEST(Reconstruction, PartitionIndependent3D)
{
  partitionIndependence(3, out, success);
}
