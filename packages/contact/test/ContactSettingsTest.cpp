// The "Contact" settings: the normal is normalised, friction rows only when they can be
// non-zero, and the one valid list of the package includes the "Newton" sublist of the
// ActiveSetSolver (a misspelt Newton key is an InputError naming it).
#include <cmath>
#include <string>

#include <Teuchos_UnitTestHarness.hpp>

#include <sc/contact/ActiveSetSolver.hpp>
#include <sc/contact/ContactSettings.hpp>
#include <sc/contact/Obstacle.hpp>
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

// Rigid indenters (docs/contact.md "Indenters"): height, contact normal and gap of a circle, a
// sphere and a cylinder against their closed forms (analytic geometry of a circle of radius R
// around c: a point at distance ρ from the centre (axis) has height ρ − R and normal towards the
// centre (axis); a ray x + s n meets the surface at the smaller root of |r + s n⊥|² = R²).
TEUCHOS_UNIT_TEST(ContactSettings, IndenterGeometry)
{
  ParameterList c;
  c.set("Obstacle", std::string("Circle"));
  c.set("Obstacle center", Teuchos::Array<double>(Teuchos::tuple<double>(0.0, 0.99)));
  c.set("Obstacle radius", 1.0);
  c.set("Obstacle normal", Teuchos::Array<double>(Teuchos::tuple<double>(0.0, -1.0)));
  sc::core::validateParameters(c, *sc::contact::ContactSettings::getValidParameters(), "test");
  const auto circle = sc::contact::createObstacle(sc::contact::ContactSettings::fromParameters(c, 2), 2);
  const double top[2] = {0.0, 0.0};  // the block's top below the centre: 0.01 inside the circle
  TEST_FLOATING_EQUALITY(circle->height(top), -0.01, 1e-12);
  const double up[2] = {0.0, 1.0};
  TEST_FLOATING_EQUALITY(circle->gap(top, up, 99.0), -0.01, 1e-12);  // overlap along +y
  const auto n = circle->contactNormal(top);
  TEST_FLOATING_EQUALITY(n[1], 1.0, 1e-15);
  // A point beside: x = (0.3, 0): ρ = sqrt(0.09 + 0.99²), height ρ − 1; along +y the ray meets the
  // circle where (0.3)² + (s − 0.99)² = 1: s = 0.99 − sqrt(1 − 0.09).
  const double side[2] = {0.3, 0.0};
  TEST_FLOATING_EQUALITY(circle->height(side), std::sqrt(0.09 + 0.99 * 0.99) - 1.0, 1e-12);
  TEST_FLOATING_EQUALITY(circle->gap(side, up, 99.0), 0.99 - std::sqrt(0.91), 1e-12);
  const double down[2] = {0.0, -1.0};
  TEST_EQUALITY(circle->gap(side, down, 99.0), 99.0);  // away from the indenter: a miss
  const double right[2] = {1.0, 0.0};
  TEST_EQUALITY(circle->gap(side, right, 99.0), 99.0);  // moving away sideways: a miss
  const auto ns = circle->contactNormal(side);
  const double rho = std::sqrt(0.09 + 0.99 * 0.99);
  TEST_FLOATING_EQUALITY(ns[0], -0.3 / rho, 1e-12);
  TEST_FLOATING_EQUALITY(ns[1], 0.99 / rho, 1e-12);

  // A sphere in 3D, and the same point against a cylinder along x (the distance across the axis
  // only: the point (5, 0.3, 0) is as far from the cylinder as (0.3, 0) from the circle).
  c.set("Obstacle", std::string("Sphere"));
  c.set("Obstacle center", Teuchos::Array<double>(Teuchos::tuple<double>(0.0, 0.0, 0.99)));
  c.set("Obstacle normal", Teuchos::Array<double>(Teuchos::tuple<double>(0.0, 0.0, -1.0)));
  const auto sphere = sc::contact::createObstacle(sc::contact::ContactSettings::fromParameters(c, 3), 3);
  const double p3[3] = {0.3, 0.4, 0.0}, z[3] = {0.0, 0.0, 1.0};
  TEST_FLOATING_EQUALITY(sphere->height(p3), std::sqrt(0.25 + 0.99 * 0.99) - 1.0, 1e-12);
  TEST_FLOATING_EQUALITY(sphere->gap(p3, z, 99.0), 0.99 - std::sqrt(0.75), 1e-12);
  c.set("Obstacle", std::string("Cylinder"));
  c.set("Obstacle axis", Teuchos::Array<double>(Teuchos::tuple<double>(2.0, 0.0, 0.0)));
  const auto cylinder = sc::contact::createObstacle(sc::contact::ContactSettings::fromParameters(c, 3), 3);
  const double q[3] = {5.0, 0.3, 0.0};
  TEST_FLOATING_EQUALITY(cylinder->height(q), std::sqrt(0.09 + 0.99 * 0.99) - 1.0, 1e-12);
  TEST_FLOATING_EQUALITY(cylinder->gap(q, z, 99.0), 0.99 - std::sqrt(0.91), 1e-12);
  const double alongAxis[3] = {1.0, 0.0, 0.0};
  TEST_EQUALITY(cylinder->gap(q, alongAxis, 99.0), 99.0);  // parallel to the axis: a miss
  const auto nc = cylinder->contactNormal(q);
  TEST_FLOATING_EQUALITY(nc[0] + 1.0, 1.0, 1e-15);  // no component along the axis

  // Bad input: a 3D indenter in 2D, no centre, a cylinder without an axis.
  c.set("Obstacle", std::string("Sphere"));
  TEST_THROW(sc::contact::ContactSettings::fromParameters(c, 2), sc::core::InputError);
  c.set("Obstacle", std::string("Circle"));
  c.set("Obstacle center", Teuchos::Array<double>());
  c.set("Obstacle normal", Teuchos::Array<double>(Teuchos::tuple<double>(0.0, -1.0)));
  TEST_THROW(sc::contact::ContactSettings::fromParameters(c, 2), sc::core::InputError);
  c.set("Obstacle", std::string("Cylinder"));
  c.set("Obstacle center", Teuchos::Array<double>(Teuchos::tuple<double>(0.0, 0.0, 0.99)));
  c.set("Obstacle normal", Teuchos::Array<double>(Teuchos::tuple<double>(0.0, 0.0, -1.0)));
  c.set("Obstacle axis", Teuchos::Array<double>());
  TEST_THROW(sc::contact::ContactSettings::fromParameters(c, 3), sc::core::InputError);
}
