#include "sc/contact/ContactSettings.hpp"

#include <cmath>

#include <sc/contact/ActiveSetSolver.hpp>
#include <sc/core/Error.hpp>
#include <sc/core/Expression.hpp>
#include <sc/core/Parameters.hpp>

namespace sc::contact {

Teuchos::RCP<const Teuchos::ParameterList> ContactSettings::getValidParameters()
{
  using namespace sc::core;
  static Teuchos::RCP<const Teuchos::ParameterList> valid = [] {
    auto pl = Teuchos::rcp(new Teuchos::ParameterList("Contact"));
    declareChoice(*pl, "Obstacle", "Plane",
                  {"Plane", "Circle", "Sphere", "Cylinder", "Height function"},
                  "Shape of the rigid obstacle: a Plane (the foundation), a rigid indenter: "
                  "Circle (2D: a cylinder in plane strain/stress), Sphere (3D) or Cylinder (3D, "
                  "with Obstacle axis), given by Obstacle center and Obstacle radius, the body "
                  "outside it (docs/contact.md 'Indenters'); or a Height function: the surface "
                  "y = h(x) (2D) or z = h(x, y) (3D) of Obstacle height, the obstacle below it "
                  "(Obstacle normal {0, 1} / {0, 0, 1}) or above it ({0, -1} / {0, 0, -1}) "
                  "(docs/contact.md 'Height function').");
    declareRealArray(*pl, "Obstacle point", Teuchos::tuple<double>(0.0, 0.0),
                     "Plane: a point of the obstacle plane (d components). A non-zero point is an "
                     "input error with indenters and Height function.",
                     {2, 3});
    declareRealArray(*pl, "Obstacle normal", Teuchos::tuple<double>(0.0, 1.0),
                     "Plane: its normal pointing towards the body (d components, normalised on "
                     "input; a normal pointing away from the body is an error). Height function: "
                     "{0, 1} / {0, 0, 1} for a body above the surface, {0, -1} / {0, 0, -1} for "
                     "one below it. Indenters: the "
                     "direction in which the indenter presses into the body, the axis along "
                     "which the contact summary reports the load and across which it measures "
                     "the contact half-width.",
                     {2, 3});
    declareRealArray(*pl, "Obstacle center", Teuchos::Array<double>(),
                     "Indenters: centre of the Circle/Sphere, a point of the Cylinder's axis "
                     "(d components; required for them; an input error with Plane and Height "
                     "function).",
                     {0, 2, 3});
    declareReal(*pl, "Obstacle radius", 1.0,
                "Indenters: radius (> 0); a value other than 1 with Plane or Height function "
                "is an input error.",
                0.0, true);
    declareRealArray(*pl, "Obstacle axis", Teuchos::Array<double>(),
                     "Cylinder (3D): direction of its axis (3 components, normalised on input; an "
                     "input error with the other obstacles).",
                     {0, 3});
    declareExpressionArray(*pl, "Obstacle height",
                           "Height function: the formula h of its surface, y = h(x) in 2D or "
                           "z = h(x, y) in 3D, e.g. {0.99 - sqrt(1 - x^2)}; it may use t (the "
                           "load step's time) but not the height's own coordinate (y in 2D, z in "
                           "3D), and must be finite, with its slope, over the body's span "
                           "(docs/contact.md 'Height function').",
                           {0, 1});
    declareChoice(*pl, "Frame", "Obstacle normal", {"Obstacle normal", "Body normal"},
                  "Contact frame of each contact point (docs/contact.md, 'Contact model'): "
                  "'Obstacle normal' measures the gap, the contact pressure and the slip along "
                  "the obstacle's normal and tangent plane (the exact non-penetration direction "
                  "for a rigid plane); 'Body normal' along the body's outward face normal (the "
                  "talk's literal linearisation: a narrower, more peaked zone at a ~1% (2D) to "
                  "~5% (3D) lower load).");
    declareChoice(*pl, "Friction law", "Coulomb", {"None", "Tresca", "Coulomb"},
                  "None: frictionless Signorini contact; Tresca: given slip bound; Coulomb: "
                  "|σ_T| ≤ μ_F|σ_N|.");
    declareReal(*pl, "Friction coefficient", 0.0, "Coulomb friction coefficient μ_F ≥ 0.", 0.0,
                false, kInfinity, false);
    declareReal(*pl, "Tresca bound", 0.0, "Slip bound s ≥ 0 of the Tresca law (stress units).", 0.0,
                false, kInfinity, false);
    pl->set("Newton", *ActiveSetSolver::getValidParameters(),
            "Semismooth Newton / active-set solver (docs/theory.md §\"Contact and friction\").");
    return pl;
  }();
  return valid;
}

ContactSettings ContactSettings::fromParameters(const Teuchos::ParameterList& pl, int dimension)
{
  auto toVector = [](const Teuchos::Array<double>& a) {
    return std::vector<double>(a.begin(), a.end());
  };
  ContactSettings c;
  c.obstacle = pl.get<std::string>("Obstacle");
  c.obstaclePoint = toVector(pl.get<Teuchos::Array<double>>("Obstacle point"));
  c.obstacleNormal = toVector(pl.get<Teuchos::Array<double>>("Obstacle normal"));
  for (const char* key : {"Obstacle point", "Obstacle normal"}) {
    if (std::string(key) == "Obstacle point" && c.obstacle != "Plane")
      continue;  // an indenter has a centre instead
    const auto& v = std::string(key) == "Obstacle point" ? c.obstaclePoint : c.obstacleNormal;
    SC_THROW_IF(static_cast<int>(v.size()) != dimension, core::InputError,
                "'Contact/" << key << "' has " << v.size()
                            << " components, but Problem/Dimension is " << dimension << ".");
  }
  double norm = 0.0;
  for (double x : c.obstacleNormal)
    norm += x * x;
  norm = std::sqrt(norm);
  SC_THROW_IF(norm == 0.0, core::InputError, "'Contact/Obstacle normal' is the zero vector.");
  for (double& x : c.obstacleNormal)
    x /= norm;
  c.obstacleCenter = toVector(pl.get<Teuchos::Array<double>>("Obstacle center"));
  c.obstacleRadius = pl.get<double>("Obstacle radius");
  c.obstacleAxis = toVector(pl.get<Teuchos::Array<double>>("Obstacle axis"));
  const auto& height = pl.get<Teuchos::Array<std::string>>("Obstacle height");
  SC_THROW_IF(!height.empty() && c.obstacle != "Height function", core::InputError,
              "'Contact/Obstacle height' is given, but 'Contact/Obstacle' = '"
                  << c.obstacle << "'; the height is for 'Contact/Obstacle' = 'Height function'.");
  if (c.obstacle == "Height function") {
    const char* graph = dimension == 2 ? "y = h(x)" : "z = h(x, y)";
    SC_THROW_IF(height.size() != 1, core::InputError,
                "'Contact/Obstacle' = 'Height function' needs 'Contact/Obstacle height', the "
                "formula h of the surface "
                    << graph << " (e.g. {0.1*x^2}).");
    c.obstacleHeight = height[0];
    const core::Expression h(c.obstacleHeight, "'Contact/Obstacle height'");
    const char* own = dimension == 2 ? "y" : "z";
    SC_THROW_IF(h.uses(own), core::InputError,
                "'Contact/Obstacle height' = '"
                    << c.obstacleHeight << "' uses " << own
                    << ", the height's own coordinate: the surface is " << graph
                    << ", a formula of " << (dimension == 2 ? "x" : "x and y") << " (and t).");
    bool alongAxis = true;
    for (int i = 0; i + 1 < dimension; ++i)
      alongAxis = alongAxis && std::abs(c.obstacleNormal[i]) <= 1e-12;
    SC_THROW_IF(!alongAxis, core::InputError,
                "'Contact/Obstacle normal' must be "
                    << (dimension == 2 ? "{0, 1} or {0, -1}" : "{0, 0, 1} or {0, 0, -1}")
                    << " for 'Contact/Obstacle' = 'Height function' (the body above or below the "
                       "surface "
                    << graph << "), but it is not along the " << own << " axis.");
    const double side = c.obstacleNormal[dimension - 1] > 0.0 ? 1.0 : -1.0;
    c.obstacleNormal.assign(dimension, 0.0);
    c.obstacleNormal[dimension - 1] = side;
  } else if (c.obstacle != "Plane") {
    const bool needs3D = c.obstacle != "Circle";
    SC_THROW_IF(needs3D != (dimension == 3), core::InputError,
                "'Contact/Obstacle' = '"
                    << c.obstacle << "' is a " << (needs3D ? "3D" : "2D")
                    << " indenter, but Problem/Dimension is " << dimension << "; valid: "
                    << (dimension == 2 ? "'Plane', 'Circle', 'Height function'"
                                       : "'Plane', 'Sphere', 'Cylinder', 'Height function'")
                    << ".");
    SC_THROW_IF(static_cast<int>(c.obstacleCenter.size()) != dimension, core::InputError,
                "'Contact/Obstacle' = '" << c.obstacle << "' needs 'Contact/Obstacle center' with "
                                         << dimension << " components (got "
                                         << c.obstacleCenter.size() << ").");
    if (c.obstacle == "Cylinder") {
      double a = 0.0;
      for (double x : c.obstacleAxis)
        a += x * x;
      a = std::sqrt(a);
      SC_THROW_IF(c.obstacleAxis.size() != 3, core::InputError,
                  "'Contact/Obstacle' = 'Cylinder' needs 'Contact/Obstacle axis', a non-zero "
                  "vector of 3 components (got "
                      << c.obstacleAxis.size() << " components).");
      SC_THROW_IF(!(a > 0.0) || !std::isfinite(a), core::InputError,
                  "'Contact/Obstacle' = 'Cylinder' needs 'Contact/Obstacle axis', a non-zero "
                  "vector of 3 components (got {"
                      << c.obstacleAxis[0] << ", " << c.obstacleAxis[1] << ", " << c.obstacleAxis[2]
                      << "}, of length " << a << ").");
      for (double& x : c.obstacleAxis)
        x /= a;
    }
  }
  // Keys of another obstacle are errors, not silently ignored: the centre and radius belong to
  // the indenters, the axis to the Cylinder. The radius has a default (1), so only another
  // value can be told from "not given".
  const bool indenter =
      c.obstacle == "Circle" || c.obstacle == "Sphere" || c.obstacle == "Cylinder";
  const char* uses = c.obstacle == "Plane" ? "a Plane takes 'Obstacle point' and 'Obstacle normal'"
                                           : "a Height function takes 'Obstacle height' and "
                                             "'Obstacle normal'";
  SC_THROW_IF(!indenter && !c.obstacleCenter.empty(), core::InputError,
              "'Contact/Obstacle center' is given, but 'Contact/Obstacle' = '"
                  << c.obstacle << "' has no centre (" << uses
                  << "); the centre is for 'Circle', 'Sphere' and 'Cylinder'. Remove the key.");
  SC_THROW_IF(!indenter && c.obstacleRadius != 1.0, core::InputError,
              "'Contact/Obstacle radius' = "
                  << c.obstacleRadius << " is given, but 'Contact/Obstacle' = '" << c.obstacle
                  << "' has no radius (" << uses
                  << "); the radius is for 'Circle', 'Sphere' and 'Cylinder'. Remove the key.");
  // 'Obstacle point' has a default ({0, 0}), so only a non-zero point can be told from "not
  // given": an indenter is placed by its centre, a height function by its formula.
  bool pointGiven = false;
  for (double x : c.obstaclePoint)
    pointGiven = pointGiven || x != 0.0;
  SC_THROW_IF(c.obstacle != "Plane" && pointGiven, core::InputError,
              "'Contact/Obstacle point' is given, but 'Contact/Obstacle' = '"
                  << c.obstacle << "' has no point ("
                  << (indenter ? "an indenter is placed by 'Obstacle center'"
                               : "a Height function is placed by its formula 'Obstacle height'")
                  << "); the point is for 'Plane' only. Remove the key.");
  SC_THROW_IF(c.obstacle != "Cylinder" && !c.obstacleAxis.empty(), core::InputError,
              "'Contact/Obstacle axis' is given, but 'Contact/Obstacle' = '"
                  << c.obstacle
                  << "' has no axis; the axis is for 'Cylinder' only. Remove the key.");
  c.frame = pl.get<std::string>("Frame") == "Body normal" ? ContactFrame::BodyNormal
                                                          : ContactFrame::ObstacleNormal;
  const std::string law = pl.get<std::string>("Friction law");
  c.frictionLaw = law == "Coulomb"  ? FrictionLaw::Coulomb
                  : law == "Tresca" ? FrictionLaw::Tresca
                                    : FrictionLaw::None;
  c.frictionCoefficient = pl.get<double>("Friction coefficient");
  c.trescaBound = pl.get<double>("Tresca bound");
  c.newton = NewtonSettings::fromParameters(pl.sublist("Newton"));
  return c;
}

NewtonSettings NewtonSettings::fromParameters(const Teuchos::ParameterList& nl)
{
  NewtonSettings s;
  s.maxIterations = nl.get<int>("Maximum iterations");
  s.penaltyFactor = nl.get<double>("Penalty factor");
  s.maxRemedies = nl.get<int>("Maximum remedies");
  s.hueberStadlerWohlmuth =
      nl.get<std::string>("3D slip linearisation") == "Hueber-Stadler-Wohlmuth";
  s.coulombMethod = nl.get<std::string>("Coulomb method");
  s.maxFixedPointIterations = nl.get<int>("Maximum fixed-point iterations");
  s.fixedPointTolerance = nl.get<double>("Fixed-point tolerance");
  return s;
}

NewtonSettings NewtonSettings::fromUncheckedParameters(const Teuchos::ParameterList& newtonList)
{
  Teuchos::ParameterList nl = newtonList;
  core::validateParameters(nl, *ActiveSetSolver::getValidParameters(), "Contact/Newton");
  return fromParameters(nl);
}

}  // namespace sc::contact
