// The "Contact" settings: the normal is normalised, friction rows only when they can be
// non-zero, and the one valid list of the package includes the "Newton" sublist of the
// ActiveSetSolver (a misspelt Newton key is an InputError naming it).
#include <algorithm>
#include <cmath>
#include <memory>
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
  const auto circle =
      sc::contact::createObstacle(sc::contact::ContactSettings::fromParameters(c, 2), 2);
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
  const auto sphere =
      sc::contact::createObstacle(sc::contact::ContactSettings::fromParameters(c, 3), 3);
  const double p3[3] = {0.3, 0.4, 0.0}, z[3] = {0.0, 0.0, 1.0};
  TEST_FLOATING_EQUALITY(sphere->height(p3), std::sqrt(0.25 + 0.99 * 0.99) - 1.0, 1e-12);
  TEST_FLOATING_EQUALITY(sphere->gap(p3, z, 99.0), 0.99 - std::sqrt(0.75), 1e-12);
  c.set("Obstacle", std::string("Cylinder"));
  c.set("Obstacle axis", Teuchos::Array<double>(Teuchos::tuple<double>(2.0, 0.0, 0.0)));
  const auto cylinder =
      sc::contact::createObstacle(sc::contact::ContactSettings::fromParameters(c, 3), 3);
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

// Height function obstacles (docs/contact.md "Height function") against the project's own Plane
// and Circle/Sphere obstacles (independent code paths: closed forms): a flat h reproduces the
// plane (the same formulas to rounding), the lower arc of a circle (cap of a sphere) the indenter
// at points below it, to the finite-difference slope's accuracy (~1e-12).
namespace {

Teuchos::Array<double> arr(std::initializer_list<double> v) { return Teuchos::Array<double>(v); }

std::unique_ptr<sc::contact::Obstacle> obstacleOf(ParameterList c, int dim)
{
  sc::core::validateParameters(c, *sc::contact::ContactSettings::getValidParameters(), "test");
  return sc::contact::createObstacle(sc::contact::ContactSettings::fromParameters(c, dim), dim);
}

}  // namespace

TEUCHOS_UNIT_TEST(ContactSettings, HeightFunctionFlatIsThePlane)
{
  for (int dim : {2, 3}) {
    ParameterList plane, graph;
    plane.set("Obstacle point", dim == 2 ? arr({0.0, 0.25}) : arr({0.0, 0.0, 0.25}));
    plane.set("Obstacle normal", dim == 2 ? arr({0.0, 1.0}) : arr({0.0, 0.0, 1.0}));
    graph.set("Obstacle", std::string("Height function"));
    graph.set("Obstacle height", Teuchos::Array<std::string>(1, "0.25"));
    graph.set("Obstacle normal", dim == 2 ? arr({0.0, 1.0}) : arr({0.0, 0.0, 1.0}));
    const auto p = obstacleOf(plane, dim), g = obstacleOf(graph, dim);
    const double points[4][3] = {
        {0.3, 0.7, 1.1}, {-2.0, 0.25, 0.4}, {1.5, 0.2, 0.249}, {0.1, 0.26, -0.3}};
    const double rays[4][3] = {
        {0.0, -1.0, -1.0}, {0.6, -0.8, 0.0}, {0.48, 0.6, -0.64}, {0.0, 1.0, 0.0}};
    for (const auto& x : points) {
      TEST_FLOATING_EQUALITY(g->height(x) + 1.0, p->height(x) + 1.0, 1e-15);
      const auto ng = g->contactNormal(x), np = p->contactNormal(x);
      for (int i = 0; i < dim; ++i)
        TEST_FLOATING_EQUALITY(ng[i] + 1.0, np[i] + 1.0, 1e-15);
      for (const auto& n : rays) {
        double u[3] = {n[0], n[1], n[2]}, len = 0.0;
        for (int i = 0; i < dim; ++i)
          len += u[i] * u[i];
        for (int i = 0; i < dim; ++i)
          u[i] /= std::sqrt(len);
        TEST_FLOATING_EQUALITY(g->gap(x, u, 99.0) + 1.0, p->gap(x, u, 99.0) + 1.0, 1e-14);
      }
    }
  }
}

TEUCHOS_UNIT_TEST(ContactSettings, HeightFunctionArcIsTheIndenter)
{
  // 2D: the circle of radius 1 around (0, 0.99) and its lower arc y = 0.99 − sqrt(1 − x²) (the
  // body below it, normal {0, −1}), at points below the centre within |x| < 0.6, along the
  // contact normal and along tilted rays; the same shifted by an obstacle displacement.
  ParameterList circle, graph;
  circle.set("Obstacle", std::string("Circle"));
  circle.set("Obstacle center", arr({0.0, 0.99}));
  circle.set("Obstacle normal", arr({0.0, -1.0}));
  graph.set("Obstacle", std::string("Height function"));
  graph.set("Obstacle height", Teuchos::Array<std::string>(1, "0.99 - sqrt(1 - x^2)"));
  graph.set("Obstacle normal", arr({0.0, -1.0}));
  for (auto* list : {&circle, &graph})
    sc::core::validateParameters(*list, *sc::contact::ContactSettings::getValidParameters(),
                                 "test");
  for (double shift : {0.0, 0.15}) {
    auto cs = sc::contact::ContactSettings::fromParameters(circle, 2);
    cs.obstacleCenter[0] += shift, cs.obstacleCenter[1] -= shift / 10;
    auto gs = sc::contact::ContactSettings::fromParameters(graph, 2);
    gs.obstacleOffset = {shift, -shift / 10};
    gs.lengthScale = 4.0;
    const auto c = sc::contact::createObstacle(cs, 2), g = sc::contact::createObstacle(gs, 2);
    double worst = 0.0;
    for (double x0 : {-0.5, -0.2, 0.0, 0.07, 0.3, 0.55})
      for (double y0 : {-0.5, -0.05, -0.0123, 0.0, 0.004}) {
        const double x[2] = {x0 + shift, y0};
        worst = std::max(worst, std::abs(g->height(x) - c->height(x)));
        const auto ng = g->contactNormal(x), nc = c->contactNormal(x);
        worst = std::max({worst, std::abs(ng[0] - nc[0]), std::abs(ng[1] - nc[1])});
        for (double angle : {0.0, 0.2, -0.35}) {
          const double n[2] = {nc[0] * std::cos(angle) - nc[1] * std::sin(angle),
                               nc[0] * std::sin(angle) + nc[1] * std::cos(angle)};
          worst = std::max(worst, std::abs(g->gap(x, n, 99.0) - c->gap(x, n, 99.0)));
        }
        const double away[2] = {-nc[0], -nc[1]};
        TEST_EQUALITY(g->gap(x, away, 99.0), 99.0);  // leaving the surface: a miss
      }
    out << "shift " << shift << ": largest difference from the circle " << worst << "\n";
    TEST_COMPARE(worst, <, 1e-11);
  }

  // 3D: the sphere of radius 1 around (0.5, 0.5, 1.995) and its lower cap.
  ParameterList sphere, cap;
  sphere.set("Obstacle", std::string("Sphere"));
  sphere.set("Obstacle center", arr({0.5, 0.5, 1.995}));
  sphere.set("Obstacle normal", arr({0.0, 0.0, -1.0}));
  cap.set("Obstacle", std::string("Height function"));
  cap.set("Obstacle height",
          Teuchos::Array<std::string>(1, "1.995 - sqrt(1 - (x - 0.5)^2 - (y - 0.5)^2)"));
  cap.set("Obstacle normal", arr({0.0, 0.0, -1.0}));
  const auto s = obstacleOf(sphere, 3), g = obstacleOf(cap, 3);
  double worst = 0.0;
  for (double x0 : {0.0, 0.3, 0.5, 0.62})
    for (double y0 : {0.1, 0.5, 0.77})
      for (double z0 : {0.5, 0.99, 1.0}) {
        const double x[3] = {x0, y0, z0};
        worst = std::max(worst, std::abs(g->height(x) - s->height(x)));
        const auto ng = g->contactNormal(x), ns = s->contactNormal(x);
        for (int i = 0; i < 3; ++i)
          worst = std::max(worst, std::abs(ng[i] - ns[i]));
        const double tilted[3] = {0.3, -0.2, std::sqrt(1 - 0.13)};
        worst = std::max({worst, std::abs(g->gap(x, ns.data(), 99.0) - s->gap(x, ns.data(), 99.0)),
                          std::abs(g->gap(x, tilted, 99.0) - s->gap(x, tilted, 99.0))});
      }
  out << "3D: largest difference from the sphere " << worst << "\n";
  TEST_COMPARE(worst, <, 1e-11);
}

TEUCHOS_UNIT_TEST(ContactSettings, HeightFunctionBadInput)
{
  auto error = [](ParameterList c, int dim) {
    try {
      sc::core::validateParameters(c, *sc::contact::ContactSettings::getValidParameters(), "test");
      sc::contact::ContactSettings::fromParameters(c, dim);
    } catch (const sc::core::InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  ParameterList c;
  c.set("Obstacle", std::string("Height function"));
  c.set("Obstacle normal", arr({0.0, -1.0}));
  std::string e = error(c, 2);
  out << e << "\n";
  TEST_ASSERT(e.find("needs 'Contact/Obstacle height'") != std::string::npos);
  c.set("Obstacle height", Teuchos::Array<std::string>(1, "0.1*y"));
  e = error(c, 2);
  out << e << "\n";
  TEST_ASSERT(e.find("'Contact/Obstacle height' = '0.1*y' uses y, the height's own coordinate") !=
              std::string::npos);
  c.set("Obstacle height", Teuchos::Array<std::string>(1, "0.1*x"));
  c.set("Obstacle normal", arr({0.6, -0.8}));
  e = error(c, 2);
  out << e << "\n";
  TEST_ASSERT(e.find("'Contact/Obstacle normal' must be {0, 1} or {0, -1}") != std::string::npos);
  c.set("Obstacle", std::string("Plane"));
  e = error(c, 2);
  TEST_ASSERT(e.find("'Contact/Obstacle height' is given, but 'Contact/Obstacle' = 'Plane'") !=
              std::string::npos);
  c.set("Obstacle", std::string("Height function"));
  c.set("Obstacle normal", arr({0.0, -1.0}));
  c.set("Obstacle height", Teuchos::Array<std::string>(1, "0.1*x + (1"));
  e = error(c, 2);
  out << e << "\n";
  TEST_ASSERT(
      e.find(
          "Obstacle height' entry 1 = '0.1*x + (1' is not a valid formula: Missing parenthesis") !=
      std::string::npos);
}
