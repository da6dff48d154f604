// sc::adapt::AdaptiveLoop driving a problem that is not this code base's finite elements: the
// L² projection of f(x) = s·x + J·H(x − a) onto piecewise constants on a 1D mesh of [0, 1],
// refined by bisecting the marked intervals, with the exact local error η_T² = ∫_T (f − f_T)²
// as the indicator (f_T the mean of f on T). It shows what another application implements
// (adapt::AdaptiveProblem) and checks the loop's order, stop criteria and restart entry, at
// 1, 2 and 4 ranks (interval e is owned by rank e mod size; the mesh is replicated).
//
// Sources of the expected numbers (analytic):
// - A linear f on an interval of length h: ∫ (f − f_T)² = s² h³ / 12, so on a uniform mesh
//   η = |s| h / √12 and, with ‖f‖ = |s| / √3 on [0, 1], η / ‖f‖ = h / 2.
// - A jump J at a point dividing T in the fractions ϑ and 1 − ϑ: f_T = J(1 − ϑ), and
//   ∫ (f − f_T)² = J² h ϑ(1 − ϑ); the other intervals have f constant and η_T = 0. For a = 1/3
//   (binary 0.0101…) the interval of a dyadic mesh containing a has ϑ = 1/3 or 2/3 at every level,
//   so η² = (2/9) J² h with h the length of that interval. Dörfler marking (θ = 0.5) then marks
//   exactly that interval each cycle: one more DOF per cycle and η² halves, while uniform
//   refinement doubles the DOFs for the same halving.
// A piecewise-constant approximation converges at the optimal rate for a function with a kink
// (f ∈ W^{1,∞}); a jump is the feature that needs adaptivity at degree 0, hence the jump here.
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_UnitTestHarness.hpp>

#include <sc/adapt/AdaptiveLoop.hpp>
#include <sc/adapt/AdaptiveProblem.hpp>
#include <sc/adapt/AdaptivitySettings.hpp>
#include <sc/adapt/QuantityError.hpp>
#include <sc/core/Error.hpp>

namespace {

using sc::adapt::CycleEstimate;
using sc::adapt::Marking;

/// f(x) = slope·x + jump·H(x − a), H(0) = 1.
struct StepFunction {
  double slope = 0.0;
  double jump = 1.0;
  double a = 1.0 / 3.0;

  double valueOn(double x, bool rightOfJump) const
  {
    return slope * x + (rightOfJump ? jump : 0.0);
  }
};

/// ∫_p^q g² for g linear with g(p) = u, g(q) = v (exact).
double squareIntegral(double p, double q, double u, double v)
{
  return (q - p) * (u * u + u * v + v * v) / 3.0;
}

/// What the problem saw in one cycle.
struct CycleRecord {
  int elements = 0;
  long long dofs = 0;
  double eta = 0.0;
  double norm = 0.0;
  std::vector<double> vertices;
  Marking marking;
  std::string stopReason;
};

class PiecewiseConstantProblem : public sc::adapt::AdaptiveProblem {
public:
  PiecewiseConstantProblem(StepFunction f, std::vector<double> vertices)
      : f_(f), x_(std::move(vertices)), comm_(Teuchos::DefaultComm<int>::getComm())
  {
  }
  /// `n` equal intervals of [0, 1].
  static std::vector<double> uniformMesh(int n)
  {
    std::vector<double> x(n + 1);
    for (int i = 0; i <= n; ++i)
      x[i] = static_cast<double>(i) / n;
    return x;
  }

  void refine(const Marking& marking) override
  {
    trace.push_back(std::string("refine ") +
                    (marking.uniform ? "uniform" : std::to_string(marking.elements.size())));
    std::vector<bool> bisect(numElements(), marking.uniform);
    for (int e : marking.elements)
      bisect.at(e) = true;
    std::vector<double> x{x_.front()};
    for (int e = 0; e < numElements(); ++e) {
      if (bisect[e]) x.push_back(0.5 * (x_[e] + x_[e + 1]));
      x.push_back(x_[e + 1]);
    }
    x_ = std::move(x);
  }

  void solve(int cycle) override
  {
    trace.push_back("solve " + std::to_string(cycle));
    // The L² projection onto piecewise constants: the mean on each interval.
    mean_.assign(numElements(), 0.0);
    for (int e = 0; e < numElements(); ++e) {
      const double l = x_[e], r = x_[e + 1];
      const double right = std::max(0.0, r - std::max(l, f_.a));  // |T ∩ [a, ∞)|
      mean_[e] = (f_.slope * 0.5 * (r * r - l * l) + f_.jump * right) / (r - l);
    }
  }

  CycleEstimate estimate(int cycle) override
  {
    trace.push_back("estimate " + std::to_string(cycle));
    CycleEstimate est;
    est.dofs = numElements();
    est.numElements = numElements();
    if (!provideEstimate) return est;
    double local = 0.0;
    for (int e = comm_->getRank(); e < numElements(); e += comm_->getSize()) {
      est.ownedElements.push_back(e);
      est.indicators.push_back(localErrorSquared(e));
      local += est.indicators.back();
    }
    double global = 0.0;
    Teuchos::reduceAll<int, double>(*comm_, Teuchos::REDUCE_SUM, local, Teuchos::outArg(global));
    est.available = true;
    est.eta = std::sqrt(global);
    // ‖f‖ on [0, 1], exact: the two linear pieces left and right of the jump.
    const auto piece = [&](double p, double q, bool right) {
      return squareIntegral(p, q, f_.valueOn(p, right), f_.valueOn(q, right));
    };
    est.norm = std::sqrt(piece(0.0, f_.a, false) + piece(f_.a, 1.0, true));
    // A quantity with an accuracy target: ‖f_h‖² = Σ_T |T| f_T², with its estimated error from
    // the history of the cycles (QuantityError.hpp), under the target name "force".
    double q = 0.0;
    for (int e = 0; e < numElements(); ++e)
      q += (x_[e + 1] - x_[e]) * mean_[e] * mean_[e];
    history.push_back({static_cast<double>(est.dofs), est.eta, q});
    est.quantities.push_back({"force", q, sc::adapt::estimateQuantityError(history)});
    last_ = est;
    return est;
  }

  sc::adapt::NextMeshForecast forecastNextMesh(const Marking& marking) const override
  {
    trace.push_back("forecast");
    sc::adapt::NextMeshForecast next;
    if (bytesPerDof > 0.0) {
      next.dofs = marking.uniform ? 2.0 * numElements()
                                  : numElements() + static_cast<double>(marking.elements.size());
      next.bytes = bytesPerDof * next.dofs;
      next.limitBytes = limitBytes;
      next.limitSource = "the test";
    }
    return next;
  }

  void output(int cycle, const Marking& marking, const std::string& stopReason) override
  {
    trace.push_back("output " + std::to_string(cycle) + (stopReason.empty() ? "" : " stop"));
    CycleRecord& r = records[cycle];
    r.elements = numElements();
    r.dofs = last_.dofs;
    r.eta = last_.eta;
    r.norm = last_.norm;
    r.vertices = x_;
    r.marking = marking;
    r.stopReason = stopReason;
  }

  void checkpoint(int cycle, const Marking& marking) override
  {
    trace.push_back("checkpoint " + std::to_string(cycle));
    checkpoints[cycle] = {x_, marking.elements};
  }

  int numElements() const { return static_cast<int>(x_.size()) - 1; }

  // What the test reads or sets.
  mutable std::vector<std::string> trace;
  std::map<int, CycleRecord> records;
  std::map<int, std::pair<std::vector<double>, std::vector<int>>> checkpoints;
  bool provideEstimate = true;
  std::vector<sc::adapt::QuantitySample> history;  ///< of ‖f_h‖²
  double bytesPerDof = 0.0;  ///< > 0: forecast the next mesh against limitBytes
  double limitBytes = 0.0;

private:
  /// ∫_T (f − f_T)², split at the jump if it lies inside T.
  double localErrorSquared(int e) const
  {
    const double l = x_[e], r = x_[e + 1], m = mean_[e];
    const auto piece = [&](double p, double q, bool right) {
      return squareIntegral(p, q, f_.valueOn(p, right) - m, f_.valueOn(q, right) - m);
    };
    if (l < f_.a && f_.a < r) return piece(l, f_.a, false) + piece(f_.a, r, true);
    return piece(l, r, l >= f_.a);
  }

  StepFunction f_;
  std::vector<double> x_;
  std::vector<double> mean_;
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  CycleEstimate last_;
};

sc::adapt::AdaptivitySettings settings(const std::string& marking, int cycles,
                                       long long maxDofs = 1000000, double targetError = 0.0)
{
  sc::adapt::AdaptivitySettings s;
  s.cycles = cycles;
  s.marking = marking;
  s.bulkParameter = 0.5;
  s.maxDofs = maxDofs;
  s.targetError = targetError;
  return s;
}

Teuchos::RCP<const Teuchos::Comm<int>> comm() { return Teuchos::DefaultComm<int>::getComm(); }

/// η after refinement to intervals of length h at the jump at 1/3 (J = 1): (2/9 · h)^{1/2}.
double jumpEta(double h) { return std::sqrt(2.0 / 9.0 * h); }

}  // namespace

// The documented order of the steps (AdaptiveLoop.hpp): no refinement in cycle 0, no forecast
// and no checkpoint in the cycle that stops.
TEUCHOS_UNIT_TEST(AdaptiveLoop, StepsInTheirOrder)
{
  PiecewiseConstantProblem problem({}, PiecewiseConstantProblem::uniformMesh(8));
  sc::adapt::AdaptiveLoop loop(settings("Dorfler", 2), comm());
  // run() once, into a variable: Teuchos' TEST_EQUALITY evaluates its arguments twice.
  const std::string reason = loop.run(problem);
  TEST_EQUALITY(reason, "Cycles = 2 reached");
  const std::vector<std::string> expected = {
      "solve 0",      "estimate 0", "forecast",   "output 0",   "checkpoint 0",
      "refine 1",     "solve 1",    "estimate 1", "forecast",   "output 1",
      "checkpoint 1", "refine 1",   "solve 2",    "estimate 2", "output 2 stop"};
  TEST_COMPARE_ARRAYS(problem.trace, expected);
}

// Dörfler marks only the interval holding the jump: 8 + n intervals after n cycles, all the new
// ones inside the initial interval [1/4, 3/8] that holds a = 1/3, and η_n = (2/9 · 2^{−3−n})^{1/2}.
TEUCHOS_UNIT_TEST(AdaptiveLoop, DorflerRefinesOnlyAtTheJump)
{
  PiecewiseConstantProblem problem({}, PiecewiseConstantProblem::uniformMesh(8));
  sc::adapt::AdaptiveLoop loop(settings("Dorfler", 10), comm());
  const std::string reason = loop.run(problem);
  TEST_EQUALITY(reason, "Cycles = 10 reached");
  TEST_EQUALITY(static_cast<int>(problem.records.size()), 11);
  for (const auto& [cycle, r] : problem.records) {
    TEST_EQUALITY(r.elements, 8 + cycle);
    TEST_FLOATING_EQUALITY(r.eta, jumpEta(std::ldexp(1.0, -3 - cycle)), 1e-12);
    TEST_EQUALITY(r.marking.uniform, false);
    TEST_EQUALITY(r.marking.elements.size(), cycle < 10 ? 1u : 0u);
  }
  const auto& x = problem.records.at(10).vertices;
  int inside = 0;
  for (std::size_t e = 0; e + 1 < x.size(); ++e) {
    const double h = x[e + 1] - x[e];
    if (x[e] >= 0.25 && x[e + 1] <= 0.375) {
      ++inside;
    } else {
      TEST_EQUALITY(h, 0.125);  // untouched initial interval
    }
    if (x[e] < 1.0 / 3.0 && 1.0 / 3.0 < x[e + 1]) TEST_EQUALITY(h, std::ldexp(1.0, -13));
  }
  TEST_EQUALITY(inside, 11);  // [1/4, 3/8] bisected 10 times, once per cycle
}

// Uniform marking refines every interval (Marking::uniform, no indicators needed) and stops by
// Max DOFs: 2^c DOFs from one interval, the first ≥ 100 is 128 at cycle 7. Its η equals that of
// 7 Dörfler cycles, which have 8 DOFs.
TEUCHOS_UNIT_TEST(AdaptiveLoop, MaxDofsStopsUniformRefinement)
{
  PiecewiseConstantProblem uniform({}, PiecewiseConstantProblem::uniformMesh(1));
  sc::adapt::AdaptiveLoop loop(settings("Uniform", 20, 100), comm());
  const std::string uniformReason = loop.run(uniform);
  TEST_EQUALITY(uniformReason, "128 DOFs >= Max DOFs = 100");
  TEST_EQUALITY(uniform.records.rbegin()->first, 7);
  TEST_EQUALITY(uniform.trace.at(5), "refine uniform");
  for (const auto& [cycle, r] : uniform.records) {
    TEST_EQUALITY(r.dofs, 1LL << cycle);
    TEST_EQUALITY(r.marking.uniform, true);
    TEST_FLOATING_EQUALITY(r.eta, jumpEta(std::ldexp(1.0, -cycle)), 1e-12);
  }

  PiecewiseConstantProblem adaptive({}, PiecewiseConstantProblem::uniformMesh(1));
  sc::adapt::AdaptiveLoop dorfler(settings("Dorfler", 7, 100), comm());
  const std::string dorflerReason = dorfler.run(adaptive);
  TEST_EQUALITY(dorflerReason, "Cycles = 7 reached");
  TEST_EQUALITY(adaptive.records.at(7).dofs, 8);
  TEST_FLOATING_EQUALITY(adaptive.records.at(7).eta, uniform.records.at(7).eta, 1e-12);
}

// Target error on f(x) = x: η/‖f‖ = h/2 on uniform meshes of h = 2^{−c} (Maximum marking with
// equal indicators marks every interval), first ≤ 0.01 at c = 6 (1/128; c = 5 gives 1/64).
TEUCHOS_UNIT_TEST(AdaptiveLoop, TargetErrorOnALinearFunction)
{
  PiecewiseConstantProblem problem({1.0, 0.0, 1.0 / 3.0}, PiecewiseConstantProblem::uniformMesh(1));
  sc::adapt::AdaptiveLoop loop(settings("Maximum", 20, 1000000, 0.01), comm());
  const std::string reason = loop.run(problem);
  out << reason << "\n";
  TEST_ASSERT(reason.rfind("eta = ", 0) == 0 &&
              reason.find("Target error 0.01") != std::string::npos);
  TEST_EQUALITY(problem.records.rbegin()->first, 6);
  for (const auto& [cycle, r] : problem.records) {
    const double h = std::ldexp(1.0, -cycle);
    TEST_EQUALITY(r.dofs, 1LL << cycle);
    TEST_FLOATING_EQUALITY(r.eta, h / std::sqrt(12.0), 1e-10);
    TEST_FLOATING_EQUALITY(r.norm, 1.0 / std::sqrt(3.0), 1e-14);
  }
}

// Restart: a loop started at cycle 4 from the checkpoint of cycle 3 (its mesh and marking)
// repeats cycles 4–6 of the uninterrupted run exactly.
TEUCHOS_UNIT_TEST(AdaptiveLoop, RestartFromACheckpointRepeatsTheRun)
{
  PiecewiseConstantProblem whole({}, PiecewiseConstantProblem::uniformMesh(8));
  sc::adapt::AdaptiveLoop loop(settings("Dorfler", 6), comm());
  loop.run(whole);
  TEST_EQUALITY(static_cast<int>(whole.checkpoints.size()), 6);  // cycles 0–5, not the last
  const auto& [mesh3, marked3] = whole.checkpoints.at(3);
  TEST_EQUALITY(marked3.size(), 1u);

  PiecewiseConstantProblem restarted({}, mesh3);
  const std::string reason = loop.run(restarted, 4, marked3);
  TEST_EQUALITY(reason, "Cycles = 6 reached");
  TEST_EQUALITY(restarted.trace.front(), "refine 1");
  TEST_EQUALITY(static_cast<int>(restarted.records.size()), 3);
  for (int cycle = 4; cycle <= 6; ++cycle) {
    TEST_EQUALITY(restarted.records.at(cycle).eta, whole.records.at(cycle).eta);
    TEST_COMPARE_ARRAYS(restarted.records.at(cycle).vertices, whole.records.at(cycle).vertices);
  }
}

// The next-mesh forecast stops the run before it refines: 1000 bytes per DOF against 12,500
// bytes; after cycle c the next mesh has 9 + c intervals, above the limit first at c = 4. That
// cycle is output with the reason and not checkpointed.
TEUCHOS_UNIT_TEST(AdaptiveLoop, NextMeshForecastStopsTheRun)
{
  PiecewiseConstantProblem problem({}, PiecewiseConstantProblem::uniformMesh(8));
  problem.bytesPerDof = 1000.0;
  problem.limitBytes = 12500.0;
  sc::adapt::AdaptiveLoop loop(settings("Dorfler", 10), comm());
  const std::string reason = loop.run(problem);
  out << reason << "\n";
  TEST_ASSERT(reason.rfind("memory: the next mesh would have about 13 DOFs", 0) == 0);
  TEST_EQUALITY(problem.records.rbegin()->first, 4);
  TEST_EQUALITY(problem.records.at(4).stopReason, reason);
  TEST_EQUALITY(problem.records.at(4).marking.elements.size(), 0u);
  TEST_EQUALITY(problem.checkpoints.count(4), 0u);
  TEST_EQUALITY(problem.checkpoints.count(3), 1u);
}

// An accuracy target on a quantity: f(x) = x, uniform meshes of h = 2^{−c}, q = ‖f_h‖² =
// 1/3 − h²/12 (exact: the means are the midpoint values) and η = h/√12, so q_{c−1} − q_c =
// (8² − 1)h²/12 for the oldest cycle of the window, c − 3, with η_{c−3} − η_c = 7η_c: the
// estimate is 1.5 · 9h²/12 (QuantityError.hpp, window 3, safety factor 1.5; 1 + 2³ times the
// true error h²/12 from that pair, as for any quantity converging like η² under uniform
// refinement), relative 3.375 h² / (1 − h²/4) to q. Target 1e-3: first met at c = 6 (8.24e-4;
// c = 5 gives 3.3e-3); after cycle 3 (window of 3 cycles: 0, 1, 2) 3.375/64/(1 − 1/256).
TEUCHOS_UNIT_TEST(AdaptiveLoop, AccuracyTargetOnAQuantity)
{
  PiecewiseConstantProblem problem({1.0, 0.0, 1.0 / 3.0}, PiecewiseConstantProblem::uniformMesh(1));
  auto s = settings("Maximum", 20);
  s.targetForceError = 1e-3;
  sc::adapt::AdaptiveLoop loop(s, comm());
  const std::string reason = loop.run(problem);
  out << reason << "\n";
  TEST_ASSERT(
      reason.rfind("accuracy targets met (estimated relative errors): force 8.24e-04 <= 0.001",
                   0) == 0);
  TEST_EQUALITY(problem.records.rbegin()->first, 6);
  const double h2 = std::ldexp(1.0, -12);
  TEST_FLOATING_EQUALITY(problem.history.back().value, 1.0 / 3.0 - h2 / 12.0, 1e-12);
  // Stopped by Cycles first: the unmet target is named.
  PiecewiseConstantProblem early({1.0, 0.0, 1.0 / 3.0}, PiecewiseConstantProblem::uniformMesh(1));
  s.cycles = 3;
  sc::adapt::AdaptiveLoop short3(s, comm());
  const std::string r3 = short3.run(early);
  out << r3 << "\n";
  TEST_ASSERT(r3.rfind("Cycles = 3 reached; accuracy targets not met (estimated relative errors): "
                       "force 5.29e-02 > 0.001",
                       0) == 0);
}

// A time budget that no cycle fits: the run stops after cycle 0 (the best within the budget),
// saying why; no checkpoint is written for it.
TEUCHOS_UNIT_TEST(AdaptiveLoop, TimeBudgetStopsBeforeTheNextCycle)
{
  PiecewiseConstantProblem problem({}, PiecewiseConstantProblem::uniformMesh(8));
  auto s = settings("Dorfler", 10);
  s.timeBudget = 1e-12;
  sc::adapt::AdaptiveLoop loop(s, comm());
  const std::string reason = loop.run(problem);
  out << reason << "\n";
  TEST_ASSERT(reason.rfind("time budget: the next cycle would end at about ", 0) == 0);
  TEST_ASSERT(
      reason.find("beyond Time budget = 1e-12 s; this cycle is the best within the budget") !=
      std::string::npos);
  TEST_EQUALITY(problem.records.rbegin()->first, 0);
  TEST_EQUALITY(problem.checkpoints.size(), 0u);
}

// A problem without an estimate: Uniform marking runs (no indicators needed; Target error is
// ignored), Dörfler marking is refused.
TEUCHOS_UNIT_TEST(AdaptiveLoop, NoEstimate)
{
  PiecewiseConstantProblem uniform({}, PiecewiseConstantProblem::uniformMesh(1));
  uniform.provideEstimate = false;
  sc::adapt::AdaptiveLoop loop(settings("Uniform", 3, 1000000, 0.5), comm());
  const std::string reason = loop.run(uniform);
  TEST_EQUALITY(reason, "Cycles = 3 reached");
  TEST_EQUALITY(uniform.records.at(3).elements, 8);

  PiecewiseConstantProblem dorfler({}, PiecewiseConstantProblem::uniformMesh(1));
  dorfler.provideEstimate = false;
  sc::adapt::AdaptiveLoop marking(settings("Dorfler", 3), comm());
  TEST_THROW(marking.run(dorfler), sc::core::InternalError);
}

// Bad settings fail when the loop is built, before any step.
TEUCHOS_UNIT_TEST(AdaptiveLoop, BadSettingsFailWhenBuilt)
{
  auto s = settings("Dorfler", 3);
  s.bulkParameter = 1.5;
  TEST_THROW(sc::adapt::AdaptiveLoop bad(s, comm()), sc::core::InputError);
  s = settings("Dorfler", 3, 0);
  TEST_THROW(sc::adapt::AdaptiveLoop bad(s, comm()), sc::core::InputError);
}
