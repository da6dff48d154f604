// Unit tests of the load-step data (docs/theory.md §"Load steps"): the times, the per-step
// tables of the boundary parts, the body force and the obstacle, and the time t in formulas.
#include <string>

#include <Teuchos_UnitTestHarness.hpp>

#include "sc/core/Error.hpp"
#include "sc/core/Expression.hpp"
#include "sc/core/LoadSteps.hpp"
#include "sc/core/Parameters.hpp"
#include "sc/core/ProblemData.hpp"

using Teuchos::ParameterList;

namespace {

template <class F>
std::string inputError(F&& f)
{
  try {
    f();
  } catch (const sc::core::InputError& e) {
    return e.what();
  }
  return "";
}

sc::core::LoadSteps steps(const Teuchos::Array<double>& times,
                          const Teuchos::Array<double>& obstacle = {}, int dim = 2)
{
  ParameterList pl;
  pl.set("Times", times);
  if (!obstacle.empty()) pl.set("Obstacle displacement", obstacle);
  sc::core::validateParameters(pl, *sc::core::LoadSteps::getValidParameters(), "test");
  return sc::core::LoadSteps::fromParameters(pl, dim);
}

}  // namespace

TEUCHOS_UNIT_TEST(LoadSteps, DefaultIsOneStepAtTimeOne)
{
  const auto s = steps(Teuchos::Array<double>());
  TEST_EQUALITY(s.numSteps(), 1);
  TEST_EQUALITY(s.times[0], 1.0);
  TEST_ASSERT(!s.given);
  TEST_EQUALITY(s.cyclesPerLaterStep, 0);
  TEST_EQUALITY(s.obstacleDisplacementAt(0, 2)[1], 0.0);
}

TEUCHOS_UNIT_TEST(LoadSteps, TimesMustIncrease)
{
  const auto s = steps(Teuchos::tuple<double>(0.5, 1.0, 2.0),
                       Teuchos::tuple<double>(0, 0, 0, -0.1, 0.2, -0.1));
  TEST_EQUALITY(s.numSteps(), 3);
  TEST_EQUALITY(s.obstacleDisplacementAt(2, 2)[0], 0.2);
  std::string m = inputError([] { steps(Teuchos::tuple<double>(1.0, 1.0)); });
  out << m << "\n";
  TEST_ASSERT(m.find("'Load steps/Times' entry 2 (1) does not follow entry 1 (1)") !=
              std::string::npos);
  m = inputError([] { steps(Teuchos::tuple<double>(0.0, 1.0)); });
  TEST_ASSERT(m.find("must be positive") != std::string::npos);
  m = inputError([] { steps(Teuchos::tuple<double>(1.0, 2.0), Teuchos::tuple<double>(0, 0, 0)); });
  out << m << "\n";
  TEST_ASSERT(m.find("'Load steps/Obstacle displacement' has 3 numbers") != std::string::npos);
}

TEUCHOS_UNIT_TEST(LoadSteps, BoundaryAndBodyForceTables)
{
  ParameterList bc;
  bc.sublist("Top").set("Type", std::string("Displacement"));
  bc.sublist("Top").set("Values per step",
                        Teuchos::Array<double>(Teuchos::tuple<double>(0, -0.01, 0.004, -0.01)));
  bc.sublist("Side").set("Type", std::string("Pressure"));
  bc.sublist("Side").set("Values per step",
                         Teuchos::Array<double>(Teuchos::tuple<double>(1.0, 3.0)));
  sc::core::validateParameters(bc, *sc::core::BoundaryConditions::getValidParameters(), "test");
  const auto bcs = sc::core::BoundaryConditions::fromParameters(bc, 2);
  bcs.checkStepTables(2, 2);
  const auto second = bcs.atStep(1, 2);
  TEST_EQUALITY(second.find("Top")->value[0], 0.004);
  TEST_EQUALITY(second.find("Top")->value[1], -0.01);
  TEST_EQUALITY(second.find("Side")->value[0], 3.0);
  TEST_EQUALITY(bcs.atStep(0, 2).find("Side")->value[0], 1.0);
  std::string m = inputError([&] { bcs.checkStepTables(3, 2); });
  out << m << "\n";
  TEST_ASSERT(m.find("'Boundary Conditions/Top/Values per step' has 2 rows of 2, but 'Load "
                     "steps/Times' has 3 entries") != std::string::npos);
  // A table beside Value; a table that is not whole rows.
  ParameterList both = bc;
  both.sublist("Top").set("Value", Teuchos::Array<double>(Teuchos::tuple<double>(0, 0)));
  m = inputError([&] { sc::core::BoundaryConditions::fromParameters(both, 2); });
  TEST_ASSERT(
      m.find("'Boundary Conditions/Top/Values per step' and 'Boundary Conditions/Top/Value' "
             "are both given") != std::string::npos);
  ParameterList odd = bc;
  odd.sublist("Top").set("Values per step",
                         Teuchos::Array<double>(Teuchos::tuple<double>(0, -0.01, 0.004)));
  m = inputError([&] { sc::core::BoundaryConditions::fromParameters(odd, 2); });
  TEST_ASSERT(m.find("not a whole number of rows of 2") != std::string::npos);

  ParameterList f;
  f.set("Values per step", Teuchos::Array<double>(Teuchos::tuple<double>(0, -1, 0, -2)));
  sc::core::validateParameters(f, *sc::core::BodyForce::getValidParameters(), "test");
  sc::core::ProblemSettings problem;
  problem.dimension = 2;
  problem.exactSolution = "None";
  const auto force = sc::core::BodyForce::fromParameters(f, problem);
  force.checkStepTable(2, 2);
  double value[2];
  const double x[2] = {0.3, 0.4};
  force.atStep(1, 2).evaluate(x, 2, value);
  TEST_EQUALITY(value[1], -2.0);
  m = inputError([&] { force.checkStepTable(1, 2); });
  TEST_ASSERT(
      m.find("'Body Force/Values per step' has 2 rows of 2, but 'Load steps/Times' has 1") !=
      std::string::npos);
}

// Formulas see the step's time t (analytic values).
TEUCHOS_UNIT_TEST(LoadSteps, FormulasOfTime)
{
  const sc::core::Expression e("-0.01*t*(1 + x)", "test");
  const double x[2] = {1.0, 0.0};
  TEST_FLOATING_EQUALITY(e(x, 2), -0.02, 1e-15);  // t = 1 without load steps
  sc::core::Expression::setLoadTime(0.25);
  TEST_FLOATING_EQUALITY(e(x, 2), -0.005, 1e-15);
  sc::core::Expression::setLoadTime(1.0);
}
