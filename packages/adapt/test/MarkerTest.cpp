// Marking, stop criteria and settings of the adaptive loop, at 1, 2 and 4 ranks; the unit
// robustness of the estimate (E × 10⁶). Sources of the expected numbers: hand-computed selections
// for the small indicator arrays; for the scaling, the discrete problem driven by u_D is linear
// in E on σ_h (A scales as 1/E, the data do not), with u_h, θ_h and u^R unchanged, so every part
// of η² (each an energy) scales by exactly 10⁶ (docs/theory.md §"Estimator" prototype).
#include <cmath>

#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_UnitTestHarness.hpp>

#include <sc/adapt/AdaptivitySettings.hpp>
#include <sc/adapt/Marker.hpp>
#include <sc/adapt/StopCriteria.hpp>
#include <sc/core/Error.hpp>
#include <sc/core/Parameters.hpp>
#include <sc/estimator/ErrorEstimator.hpp>

#include <sc/testing/ElasticityTestProblem.hpp>

namespace {

// η_T² of `all` distributed round-robin over the ranks (element e on rank e mod size).
std::vector<int> markDistributed(const sc::adapt::Marker& marker, const std::vector<double>& all)
{
  auto comm = Teuchos::DefaultComm<int>::getComm();
  std::vector<int> owned;
  std::vector<double> eta2;
  for (std::size_t e = 0; e < all.size(); ++e)
    if (static_cast<int>(e) % comm->getSize() == comm->getRank()) {
      owned.push_back(static_cast<int>(e));
      eta2.push_back(all[e]);
    }
  return marker.mark(static_cast<int>(all.size()), owned, eta2, *comm);
}

std::string messageOf(const std::function<void()>& f)
{
  try {
    f();
  } catch (const sc::core::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEUCHOS_UNIT_TEST(Marker, DorflerSelectsTheFewestLargest)
{
  // Σ = 10; θ = 0.5: 4 (< 5) then 3 (7 ≥ 5) → elements {0, 2}; θ = 0.75: 4, 3, 2 (9 ≥ 7.5).
  const std::vector<double> eta2 = {4.0, 0.5, 3.0, 2.0, 0.5};
  TEST_COMPARE_ARRAYS(markDistributed(sc::adapt::DorflerMarker(0.5), eta2),
                      std::vector<int>({0, 2}));
  TEST_COMPARE_ARRAYS(markDistributed(sc::adapt::DorflerMarker(0.75), eta2),
                      std::vector<int>({0, 2, 3}));
  TEST_COMPARE_ARRAYS(markDistributed(sc::adapt::DorflerMarker(1.0), eta2),
                      std::vector<int>({0, 1, 2, 3, 4}));
  // Ties broken by element index: the lower index first (Σ = 6, θ = 0.3: one element of 2).
  TEST_COMPARE_ARRAYS(markDistributed(sc::adapt::DorflerMarker(0.3), {1.0, 2.0, 2.0, 1.0}),
                      std::vector<int>({1}));
  // η = 0: nothing to refine.
  TEST_EQUALITY(markDistributed(sc::adapt::DorflerMarker(0.5), {0.0, 0.0}).size(), 0u);
}

TEUCHOS_UNIT_TEST(Marker, MaximumAndUniform)
{
  // η_T ≥ 0.5 max η_T ⇔ η_T² ≥ 0.25 · 4 = 1.
  const std::vector<double> eta2 = {4.0, 0.5, 3.0, 1.0, 0.99};
  TEST_COMPARE_ARRAYS(markDistributed(sc::adapt::MaximumMarker(0.5), eta2),
                      std::vector<int>({0, 2, 3}));
  TEST_COMPARE_ARRAYS(markDistributed(sc::adapt::UniformMarker(), eta2),
                      std::vector<int>({0, 1, 2, 3, 4}));
}

TEUCHOS_UNIT_TEST(Marker, BadValuesNameTheKeyAndRange)
{
  auto valid = sc::adapt::AdaptivitySettings::getValidParameters();
  for (double theta : {0.0, -0.1, 1.5}) {
    Teuchos::ParameterList user;
    user.set("Bulk parameter", theta);
    const std::string msg =
        messageOf([&] { sc::core::validateParameters(user, *valid, "deck.xml"); });
    out << msg << "\n";
    TEST_ASSERT(msg.find("Bulk parameter") != std::string::npos);
    TEST_ASSERT(msg.find("(0, 1]") != std::string::npos);
    const std::string direct = messageOf([&] { sc::adapt::DorflerMarker m(theta); });
    TEST_ASSERT(direct.find("Bulk parameter") != std::string::npos);
  }
  {
    Teuchos::ParameterList user;
    user.set("Target error", -1e-3);
    const std::string msg =
        messageOf([&] { sc::core::validateParameters(user, *valid, "deck.xml"); });
    out << msg << "\n";
    TEST_ASSERT(msg.find("Target error") != std::string::npos);
  }
  {
    Teuchos::ParameterList user;
    user.set("Reconstruction degree", std::string("k+2"));
    const std::string msg = messageOf([&] {
      sc::core::validateParameters(user, *sc::estimator::EstimatorSettings::getValidParameters(),
                                   "deck.xml");
    });
    out << msg << "\n";
    TEST_ASSERT(msg.find("Reconstruction degree") != std::string::npos);
    TEST_ASSERT(msg.find("k+1") != std::string::npos);
  }
}

TEUCHOS_UNIT_TEST(StopCriteria, CyclesDofsTarget)
{
  sc::adapt::AdaptivitySettings s;
  s.cycles = 5;
  s.maxDofs = 10000;
  s.targetError = 0.01;
  sc::adapt::StopCriteria stop(s);
  TEST_EQUALITY(stop.reason(0, 100, 1.0, 10.0), "");
  TEST_INEQUALITY(stop.reason(5, 100, 1.0, 10.0), "");    // Cycles
  TEST_INEQUALITY(stop.reason(1, 10000, 1.0, 10.0), "");  // Max DOFs
  TEST_INEQUALITY(stop.reason(1, 100, 0.099, 10.0), "");  // η ≤ 0.01 · 10
  TEST_EQUALITY(stop.reason(1, 100, 0.101, 10.0), "");
  TEST_EQUALITY(stop.reason(1, 100, -1.0, -1.0), "");  // no estimate: ignored
  s.targetError = -1.0;
  TEST_THROW(sc::adapt::StopCriteria bad(s), sc::core::InputError);
}

// Accuracy targets (docs/adaptivity.md "Accuracy targets and a time budget"): all given targets
// must be met by estimated relative errors; a quantity without an estimate does not meet its
// target; out-of-range values name the key.
TEUCHOS_UNIT_TEST(StopCriteria, AccuracyTargetsAndTimeBudget)
{
  // The settings have no defaults of their own (the deck's are in getValidParameters).
  const auto valid = [] {
    sc::adapt::AdaptivitySettings v;
    v.cycles = 50;
    v.maxDofs = 1000000;
    return v;
  };
  auto s = valid();
  s.targetForceError = 1e-3;
  s.targetWidthError = 1e-2;
  sc::adapt::StopCriteria stop(s);
  using Q = sc::adapt::QuantityEstimate;
  // force 0.05/100 = 5e-4 ≤ 1e-3, width 0.002/0.1 = 2e-2 > 1e-2.
  std::vector<Q> q = {{"force", -100.0, 0.05}, {"width", 0.1, 0.002}, {"pressure", 900.0, 100.0}};
  auto status = stop.targets(q);
  TEST_EQUALITY(status.size(), 2u);
  TEST_ASSERT(status[0].met && !status[1].met);
  TEST_FLOATING_EQUALITY(status[0].relativeError, 5e-4, 1e-14);
  TEST_EQUALITY(status[1].key, "Adaptivity/Target width error");
  TEST_EQUALITY(stop.targetsReason(q), "");
  TEST_EQUALITY(stop.unmetTargets(q),
                "; accuracy targets not met (estimated relative errors): width 2.00e-02 > 0.01");
  q[1].error = 0.0009;
  TEST_EQUALITY(stop.targetsReason(q), "accuracy targets met (estimated relative errors): force "
                                       "5.00e-04 <= 0.001, width 9.00e-03 <= 0.01");
  q[0].error = -1.0;  // no estimate yet
  TEST_EQUALITY(stop.targetsReason(q), "");
  TEST_EQUALITY(stop.unmetTargets(q),
                "; accuracy targets not met (estimated relative errors): force not estimated yet");
  // Time budget: 10 s; 7 s elapsed, next cycle forecast 2.9 s: fits; 3.1 s: stops.
  s.timeBudget = 10.0;
  sc::adapt::StopCriteria budget(s);
  TEST_EQUALITY(budget.budgetReason(7.0, 2.9, q), "");
  const std::string r = budget.budgetReason(7.0, 3.1, q);
  out << r << "\n";
  TEST_ASSERT(r.rfind("time budget: the next cycle would end at about 10.1 s", 0) == 0);
  TEST_ASSERT(r.find("force not estimated yet") != std::string::npos);
  // No targets, no budget: nothing to say.
  sc::adapt::StopCriteria none(valid());
  TEST_EQUALITY(none.targetsReason(q), "");
  TEST_EQUALITY(none.unmetTargets(q), "");
  TEST_EQUALITY(none.budgetReason(1e9, 1e9, q), "");
  // Out of range: the key and the valid range.
  for (double bad : {-0.1, 1.5}) {
    auto b = valid();
    b.targetPressureError = bad;
    try {
      sc::adapt::StopCriteria x(b);
      TEST_ASSERT(false);
    } catch (const sc::core::InputError& e) {
      TEST_ASSERT(std::string(e.what()).find("'Adaptivity/Target pressure error'") !=
                  std::string::npos);
    }
  }
  auto b = valid();
  b.timeBudget = -1.0;
  TEST_THROW(sc::adapt::StopCriteria x(b), sc::core::InputError);
}

// A step whose next mesh would exceed the memory limit stops the run (docs/mesh.md "Resource
// limits").
TEUCHOS_UNIT_TEST(StopCriteria, NextMeshAboveTheMemoryLimit)
{
  sc::adapt::AdaptivitySettings s;
  s.cycles = 5;
  s.maxDofs = 10000;
  sc::adapt::StopCriteria stop(s);
  TEST_EQUALITY(stop.memoryReason(5000, 0.9e9, 1e9, "test"), "");
  TEST_EQUALITY(stop.memoryReason(5000, 1e9, 1e9, "test"), "");
  const std::string r = stop.memoryReason(2.5e6, 5.5e9, 1e9, "MemAvailable in /proc/meminfo");
  out << r << "\n";
  TEST_ASSERT(r.find("memory: the next mesh would have about 2.5e+06 DOFs needing about 5.5 GB, "
                     "above the memory limit of 1 GB (MemAvailable in /proc/meminfo)") == 0);
}

// E × 10⁶ on a displacement-driven scene (unit square: Left clamped, Right pulled by u_D, the
// rest free; corner singularities make the indicators far from uniform).
TEUCHOS_UNIT_TEST(Estimator, YoungModulusScalesEveryPartAndKeepsTheMarking)
{
  auto comm = Teuchos::DefaultComm<int>::getComm();
  std::vector<sc::estimator::ErrorEstimate> estimates;
  std::vector<std::vector<int>> marked;
  for (double E : {1.0, 1e6}) {
    sc::test::VerificationSetup s;
    s.meshSize = 0.25;
    s.initialRefinements = 1;
    s.levels = 1;
    s.E = E;
    s.nu = 0.4;
    s.exact = "None";
    s.solver = "KLU2";  // MUMPS' default workspace is too small for this small pivoting case
    s.boundaryConditions = {{"Left", sc::core::BoundaryType::Displacement, {0.0, 0.0}, false},
                            {"Right", sc::core::BoundaryType::Displacement, {0.01, 0.005}, false}};
    sc::test::solveVerification(
        s, comm,
        [&](int, const sc::assembly::MixedElasticityAssembler& A, const Tpetra::MultiVector<>& x,
            const sc::assembly::ElasticityData& data) {
          sc::estimator::ErrorEstimator estimator(A, sc::estimator::EstimatorSettings{true}, comm);
          estimates.push_back(estimator.estimate(x, data));
          sc::adapt::DorflerMarker dorfler(0.5);
          marked.push_back(dorfler.mark(A.space().mesh().numElements(), A.space().ownedElements(),
                                        estimates.back().indicators, *comm));
        });
  }
  for (std::size_t i = 0; i < estimates[0].parts.size(); ++i) {
    out << estimates[0].parts[i].first << ": " << estimates[0].parts[i].second << " -> "
        << estimates[1].parts[i].second << "\n";
    // Parts at round-off (here the u_D oscillation: constant u_D is interpolated exactly) have no
    // scaling to check.
    if (estimates[0].parts[i].second > 1e-12 * std::pow(estimates[0].total(), 2))
      TEST_FLOATING_EQUALITY(estimates[1].parts[i].second / estimates[0].parts[i].second, 1e6,
                             1e-8);
  }
  TEST_FLOATING_EQUALITY(estimates[1].total() / estimates[0].total(), 1e3, 1e-8);
  out << marked[0].size() << " of the elements marked\n";
  TEST_COMPARE(marked[0].size(), >, 0u);
  TEST_COMPARE_ARRAYS(marked[0], marked[1]);
}
