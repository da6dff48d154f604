// The "Contact" settings: the normal is normalised, friction rows only when they can be
// non-zero, and the one valid list of the package includes the "Newton" sublist of the
// ActiveSetSolver (a misspelt Newton key is an InputError naming it).
#include <string>

#include <Teuchos_UnitTestHarness.hpp>

#include <sc/contact/ActiveSetSolver.hpp>
#include <sc/contact/ContactSettings.hpp>
#include <sc/core/Error.hpp>
#include <sc/core/Parameters.hpp>

using Teuchos::ParameterList;

TEUCHOS_UNIT_TEST(ContactSettings, ContactNormalIsNormalised)
{
  ParameterList c;
  c.set("Obstacle normal", Teuchos::Array<double>(Teuchos::tuple<double>(0.0, 2.0)));
  c.set("Friction law", std::string("None"));
  c.set("Friction coefficient", 0.4);
  sc::core::validateParameters(c, *sc::contact::ContactSettings::getValidParameters(), "test");
  auto s = sc::contact::ContactSettings::fromParameters(c, 2);
  TEST_FLOATING_EQUALITY(s.obstacleNormal[1], 1.0, 1e-15);
  // Law None: no friction machinery whatever the coefficient.
  TEST_ASSERT(!s.needsFriction());
  c.set("Friction law", std::string("Coulomb"));
  TEST_ASSERT(sc::contact::ContactSettings::fromParameters(c, 2).needsFriction());
  c.set("Friction coefficient", 0.0);
  TEST_ASSERT(!sc::contact::ContactSettings::fromParameters(c, 2).needsFriction());
  // 2 components in a 3D problem.
  TEST_THROW(sc::contact::ContactSettings::fromParameters(c, 3), sc::core::InputError);
}

TEUCHOS_UNIT_TEST(ContactSettings, OneListWithTheNewtonSublist)
{
  const auto valid = sc::contact::ContactSettings::getValidParameters();
  TEST_ASSERT(valid->isSublist("Newton"));
  // The Newton keys are the ActiveSetSolver's, with their defaults.
  const auto& newton = valid->sublist("Newton");
  const auto& solverKeys = *sc::contact::ActiveSetSolver::getValidParameters();
  int keys = 0;
  for (auto it = solverKeys.begin(); it != solverKeys.end(); ++it, ++keys) {
    const std::string& name = solverKeys.name(it);
    TEST_ASSERT(newton.isParameter(name));
    TEST_ASSERT(newton.getEntry(name).getAny(false) == solverKeys.getEntry(name).getAny(false));
  }
  TEST_EQUALITY(static_cast<int>(newton.numParams()), keys);
  // Validation fills in the Newton defaults and rejects a misspelt Newton key.
  ParameterList c;
  sc::core::validateParameters(c, *valid, "test");
  TEST_EQUALITY(c.sublist("Newton").get<int>("Maximum iterations"), 50);
  ParameterList bad;
  bad.sublist("Newton").set("Maximum iteration", 10);
  try {
    sc::core::validateParameters(bad, *valid, "test");
    TEST_ASSERT(false);
  } catch (const sc::core::InputError& e) {
    TEST_ASSERT(std::string(e.what()).find("Maximum iteration") != std::string::npos);
  }
}
