// Formulas of x, y, z in the deck (core/Expression.hpp, muparser): values against hand-computed
// numbers, and the messages of malformed formulas, unknown names and non-finite values, which
// must name the key, the formula and the position or point.
#include <cmath>
#include <string>

#include <Teuchos_UnitTestHarness.hpp>

#include "sc/core/Error.hpp"
#include "sc/core/Expression.hpp"
#include "sc/core/Parameters.hpp"

namespace {

std::string compileError(const std::string& formula)
{
  try {
    sc::core::Expression e(formula, "'Body Force/Expression' entry 2");
  } catch (const sc::core::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEUCHOS_UNIT_TEST(Expression, Values)
{
  const double p2[2] = {0.25, 2.0}, p3[3] = {0.25, 2.0, -1.5};
  // Analytic values at the points above.
  TEST_FLOATING_EQUALITY(sc::core::Expression("-9.81*(2 - y) + x", "k")(p2, 2), 0.25, 1e-15);
  TEST_FLOATING_EQUALITY(sc::core::Expression("sin(pi*x)^2", "k")(p2, 2), 0.5, 1e-15);
  TEST_FLOATING_EQUALITY(sc::core::Expression("sqrt(x) * exp(0) / y", "k")(p2, 2), 0.25, 1e-15);
  TEST_FLOATING_EQUALITY(sc::core::Expression("x < y ? 1e3 : -1", "k")(p2, 2), 1e3, 1e-15);
  // z is 0 in 2D and the third coordinate in 3D.
  TEST_EQUALITY(sc::core::Expression("z", "k")(p2, 2), 0.0);
  TEST_EQUALITY(sc::core::Expression("z", "k")(p3, 3), -1.5);
  // Copies share the compiled formula and evaluate at their own points.
  const sc::core::Expression a("x*y", "k");
  const sc::core::Expression b = a;
  TEST_FLOATING_EQUALITY(b(p2, 2), 0.5, 1e-15);
  const double q[2] = {3.0, 4.0};
  TEST_FLOATING_EQUALITY(a(q, 2), 12.0, 1e-15);
}

TEUCHOS_UNIT_TEST(Expression, MalformedFormulaNamesKeyFormulaAndPosition)
{
  const std::string msg = compileError("2*(x+");
  TEST_ASSERT(msg.find("'Body Force/Expression' entry 2 = '2*(x+' is not a valid formula: "
                       "Unexpected end of expression at position 6") != std::string::npos);
  TEST_ASSERT(msg.find("variables x, y, z") != std::string::npos);
  TEST_ASSERT(compileError("3 +* 4").find("Unexpected operator \"*\" found at position 3") !=
              std::string::npos);
  TEST_ASSERT(compileError("").find("is not a valid formula") != std::string::npos);
  // muparser's "Missing parenthesis" has no position of its own: the unclosed '(' is named.
  TEST_ASSERT(compileError("sin(x").find("Missing parenthesis at position 3: the '(' there is "
                                         "not closed") != std::string::npos);
  TEST_ASSERT(compileError("((x)").find("Missing parenthesis at position 0") != std::string::npos);
}

TEUCHOS_UNIT_TEST(Expression, UnknownVariableIsAnInputError)
{
  const std::string msg = compileError("-9.81*rho");
  TEST_ASSERT(msg.find("'-9.81*rho' is not a valid formula: Unexpected token \"rho\" found at "
                       "position 6") != std::string::npos);
  TEST_ASSERT(msg.find("'rho' is not a variable, constant or function") != std::string::npos);
  // muparser's own constants are not part of the syntax: pi is, _pi is not.
  TEST_ASSERT(!compileError("_pi").empty());
  TEST_ASSERT(compileError("pi").empty());
  // t is the load step's time (LoadStepsTest); other single letters are not variables.
  TEST_ASSERT(compileError("t").empty());
  TEST_ASSERT(!compileError("s").empty());
}

TEUCHOS_UNIT_TEST(Expression, NonFiniteValueNamesThePoint)
{
  const sc::core::Expression e("sqrt(x - 2)", "'Boundary Conditions/Top/Expression' entry 1");
  const double inside[2] = {3.0, 0.0}, outside[2] = {1.0, 0.5};
  TEST_FLOATING_EQUALITY(e(inside, 2), 1.0, 1e-15);
  try {
    e(outside, 2);
    TEST_ASSERT(false);
  } catch (const sc::core::InputError& err) {
    const std::string msg = err.what();
    TEST_ASSERT(msg.find("'Boundary Conditions/Top/Expression' entry 1 = 'sqrt(x - 2)' evaluates "
                         "to NaN at the point (1, 0.5)") != std::string::npos);
  }
  const sc::core::Expression inv("1/x", "k");
  const double origin[2] = {0.0, 0.0};
  TEST_THROW(inv(origin, 2), sc::core::InputError);
}

// The validator behind every Expression key: it compiles at validation (--check) and checks the
// number of formulas.
TEUCHOS_UNIT_TEST(Expression, ValidatorCompilesAndCounts)
{
  Teuchos::ParameterList valid;
  sc::core::declareExpressionArray(valid.sublist("Body Force"), "Expression", "doc", {0, 2, 3});
  auto check = [&](const Teuchos::Array<std::string>& formulas) -> std::string {
    Teuchos::ParameterList deck;
    deck.sublist("Body Force").set("Expression", formulas);
    try {
      sc::core::validateParameters(deck, valid, "deck.xml");
    } catch (const sc::core::InputError& e) {
      return e.what();
    }
    return "";
  };
  TEST_EQUALITY(check(Teuchos::tuple<std::string>("0", "-9.81")), "");
  TEST_ASSERT(check(Teuchos::tuple<std::string>("min(x", "y)", "0", "1"))
                  .find("'Body Force/Expression' = {min(x, y), 0, 1} has 4 formulas; it must have "
                        "0 or 2 or 3 (a formula cannot contain a comma") != std::string::npos);
  TEST_ASSERT(
      check(Teuchos::tuple<std::string>("0", "y^"))
          .find("deck.xml: 'Body Force/Expression' entry 2 = 'y^' is not a valid formula") !=
      std::string::npos);
}
