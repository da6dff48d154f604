// sc::adapt::estimateQuantityError (QuantityError.hpp): the error bar of a quantity from its
// history and η's, on synthetic histories whose limit is known (analytic sources below).
#include <cmath>
#include <vector>

#include <Teuchos_UnitTestHarness.hpp>

#include <sc/adapt/QuantityError.hpp>

namespace {

using sc::adapt::QuantitySample;

/// q = q∞ + C·η^p with η = η₀·ρ^c for cycles c = 0..n−1 (DOFs 1000·2^c).
std::vector<QuantitySample> modelHistory(int n, double p, double C, double rho)
{
  std::vector<QuantitySample> h;
  for (int c = 0; c < n; ++c) {
    const double eta = 0.2 * std::pow(rho, c);
    h.push_back({1000.0 * std::ldexp(1.0, c), eta, 106.8 + C * std::pow(eta, p)});
  }
  return h;
}

}  // namespace

// q − q∞ = C·η exactly (the model of the estimate): with safety factor 1 the estimate is the
// true error |C|·η_n, from any earlier cycle in the window (analytic).
TEUCHOS_UNIT_TEST(QuantityError, ExactForTheModel)
{
  const sc::adapt::QuantityErrorSettings plain{3, 1.0};
  for (double rho : {0.5, 0.8, 0.97}) {
    const auto h = modelHistory(6, 1.0, -40.0, rho);
    const double trueError = 40.0 * h.back().eta;
    TEST_FLOATING_EQUALITY(sc::adapt::estimateQuantityError(h, 0.0, plain), trueError, 1e-9);
    // The default settings: 1.5 times it.
    TEST_FLOATING_EQUALITY(sc::adapt::estimateQuantityError(h), 1.5 * trueError, 1e-9);
  }
}

// A quantity converging like η² (a functional): the estimate over-estimates by 1 + η_j/η_n
// for the pair (j, n) that gives the largest value (the oldest in the window): with ρ = 0.8
// and window 3, 1 + 0.8^{−3} = 2.953 (analytic); never below the true error.
TEUCHOS_UNIT_TEST(QuantityError, FasterConvergenceIsOverEstimated)
{
  const sc::adapt::QuantityErrorSettings plain{3, 1.0};
  const auto h = modelHistory(8, 2.0, 500.0, 0.8);
  const double trueError = 500.0 * h.back().eta * h.back().eta;
  TEST_FLOATING_EQUALITY(sc::adapt::estimateQuantityError(h, 0.0, plain) / trueError,
                         1.0 + std::pow(0.8, -3.0), 1e-9);
  // With the rate β = 2 of the model the estimate is exact again.
  TEST_FLOATING_EQUALITY(sc::adapt::estimateQuantityError(h, 0.0, {3, 1.0, 2.0}), trueError, 1e-9);
}

// β = 0 (a quantity that moves in steps): the largest change over the window, no extrapolation.
TEUCHOS_UNIT_TEST(QuantityError, StepsWithoutExtrapolation)
{
  std::vector<QuantitySample> h = {
      {100, 0.2, 0.05}, {200, 0.1, 0.06}, {300, 0.08, 0.07}, {400, 0.06, 0.07}};
  // The window (3 earlier cycles) reaches back to 0.05: |0.05 − 0.07|; with window 1, 0.
  TEST_FLOATING_EQUALITY(sc::adapt::estimateQuantityError(h, 0.0, {3, 1.0, 0.0}), 0.02, 1e-12);
  TEST_FLOATING_EQUALITY(sc::adapt::estimateQuantityError(h, 0.0, {3, 2.0, 0.0}), 0.04, 1e-12);
  TEST_EQUALITY(sc::adapt::estimateQuantityError(h, 0.0, {1, 1.0, 0.0}), 0.0);
}

// No estimate: one sample; η not decreasing over the window. A staircase (the quantity did not
// move) gives 0, raised to the floor.
TEUCHOS_UNIT_TEST(QuantityError, NoneOrFloor)
{
  std::vector<QuantitySample> h = {{100, 0.1, 5.0}};
  TEST_ASSERT(sc::adapt::estimateQuantityError(h) < 0.0);
  h.push_back({200, 0.12, 5.1});
  TEST_ASSERT(sc::adapt::estimateQuantityError(h) < 0.0);
  h.push_back(
      {300, 0.05, 5.1});  // η 0.1 → 0.05: |5.0 − 5.1|·0.05/0.05 = 0.1, the 0.12 cycle gives 0
  TEST_FLOATING_EQUALITY(sc::adapt::estimateQuantityError(h), 1.5 * 0.1, 1e-12);
  std::vector<QuantitySample> flat = {{100, 0.1, 2.0}, {200, 0.08, 2.0}, {300, 0.06, 2.0}};
  TEST_EQUALITY(sc::adapt::estimateQuantityError(flat), 0.0);
  TEST_EQUALITY(sc::adapt::estimateQuantityError(flat, 0.01), 0.01);
  // Only the window counts: a jump four cycles back is forgotten with window 3.
  std::vector<QuantitySample> old = {
      {100, 0.2, 1.0}, {200, 0.1, 2.0}, {300, 0.08, 2.0}, {400, 0.06, 2.0}, {500, 0.05, 2.0}};
  TEST_EQUALITY(sc::adapt::estimateQuantityError(old), 0.0);
  TEST_FLOATING_EQUALITY(sc::adapt::estimateQuantityError(old, 0.0, {4, 1.0}), 1.0 * 0.05 / 0.15,
                         1e-12);
}
