// Unit tests of the scene data: compliance coefficient c_d, Hertz modulus, boundary conditions
// against the problem dimension and the mesh's boundary names (the Contact settings are tested
// in the contact package).
#include <functional>

#include <Teuchos_UnitTestHarness.hpp>

#include "sc/core/Error.hpp"
#include "sc/core/ExactSolution.hpp"
#include "sc/core/Parameters.hpp"
#include "sc/core/ProblemData.hpp"

using Teuchos::ParameterList;

TEUCHOS_UNIT_TEST(ProblemData, ComplianceCoefficient)
{
  // Analytic: c_d = λ/(dλ + 2μ) with λ = Eν/((1+ν)(1−2ν)), μ = E/(2(1+ν)) equals ν/(1+(d−2)ν).
  sc::core::Material m{20600.0, 0.28};
  const double E = m.youngModulus, nu = m.poissonRatio;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  TEST_FLOATING_EQUALITY(m.complianceCoefficient(2), lambda / (2 * lambda + 2 * mu), 1e-14);
  TEST_FLOATING_EQUALITY(m.complianceCoefficient(3), lambda / (3 * lambda + 2 * mu), 1e-14);
  TEST_FLOATING_EQUALITY(m.shearModulus(), mu, 1e-14);
  // Incompressible limit (λ → ∞): c_d → 1/d, finite.
  sc::core::Material inc{1.0, 0.5};
  TEST_FLOATING_EQUALITY(inc.complianceCoefficient(2), 0.5, 1e-15);
  TEST_FLOATING_EQUALITY(inc.complianceCoefficient(3), 1.0 / 3.0, 1e-15);
}

TEUCHOS_UNIT_TEST(ProblemData, BoundaryConditions)
{
  ParameterList bc;
  bc.sublist("Top").set("Type", std::string("Displacement"));
  bc.sublist("Top").set("Value", Teuchos::Array<double>(Teuchos::tuple<double>(0.0, -0.01)));
  bc.sublist("Arc").set("Type", std::string("Contact"));
  ParameterList valid = *sc::core::BoundaryConditions::getValidParameters();
  sc::core::validateParameters(bc, valid, "test");
  auto bcs = sc::core::BoundaryConditions::fromParameters(bc, 2);
  TEST_ASSERT(bcs.hasContact());
  TEST_EQUALITY(bcs.find("Top")->value.size(), 2u);
  TEST_FLOATING_EQUALITY(bcs.find("Top")->value[1], -0.01, 1e-15);
  bcs.checkBoundaryNames({"Top", "Arc"}, "Half disc");
  try {
    bcs.checkBoundaryNames({"Top", "Cap"}, "Half ball");
    TEST_ASSERT(false);
  } catch (const sc::core::InputError& e) {
    const std::string msg = e.what();
    TEST_ASSERT(msg.find("no boundary part named 'Arc'") != std::string::npos);
    TEST_ASSERT(msg.find("'Top', 'Cap'") != std::string::npos);
  }
  // 2 components in a 3D problem.
  TEST_THROW(sc::core::BoundaryConditions::fromParameters(bc, 3), sc::core::InputError);
}

// ν = 0.5: A I = 0 (analytic: c_d = 1/d, so A I = (I − c_d d I)/2μ = 0), so a boundary held by
// Displacement everywhere leaves the mean pressure free; any traction part fixes it.
TEUCHOS_UNIT_TEST(ProblemData, IncompressiblePureDisplacementIsAnInputError)
{
  ParameterList bc;
  for (const char* name : {"Top", "Arc"}) {
    bc.sublist(name).set("Type", std::string("Displacement"));
    bc.sublist(name).set("Value", Teuchos::Array<double>(Teuchos::tuple<double>(0.0, 0.0)));
  }
  ParameterList valid = *sc::core::BoundaryConditions::getValidParameters();
  sc::core::validateParameters(bc, valid, "test");
  auto bcs = sc::core::BoundaryConditions::fromParameters(bc, 2);
  const sc::core::Material incompressible{1.0, 0.5}, nearly{1.0, 0.4999};
  TEST_THROW(bcs.checkPressureDetermined({"Top", "Arc"}, incompressible), sc::core::InputError);
  bcs.checkPressureDetermined({"Top", "Arc"}, nearly);                  // well-posed below 0.5
  bcs.checkPressureDetermined({"Top", "Arc", "Side"}, incompressible);  // "Side": traction free
  bcs.conditions[1].type = sc::core::BoundaryType::Contact;
  bcs.checkPressureDetermined({"Top", "Arc"}, incompressible);
}

namespace {
ParameterList validated(ParameterList bc)
{
  ParameterList valid = *sc::core::BoundaryConditions::getValidParameters();
  sc::core::validateParameters(bc, valid, "test");
  return bc;
}

std::string inputErrorOf(const std::function<void()>& f)
{
  try {
    f();
  } catch (const sc::core::InputError& e) {
    return e.what();
  }
  return "";
}

Teuchos::Array<std::string> formulas(std::initializer_list<const char*> list)
{
  Teuchos::Array<std::string> a;
  for (const char* f : list)
    a.push_back(f);
  return a;
}
}  // namespace

// Plane stress: Aσ = ((1+ν)σ − ν tr(σ) I)/E (analytic, σ_zz = 0) is c_d = ν/(1+ν); 3D rejects it.
TEUCHOS_UNIT_TEST(ProblemData, PlaneStress)
{
  ParameterList material;
  material.set("Young modulus", 2.0);
  material.set("Poisson ratio", 0.25);
  material.set("Plane", std::string("Stress"));
  ParameterList valid = *sc::core::Material::getValidParameters();
  sc::core::validateParameters(material, valid, "test");
  const auto m = sc::core::Material::fromParameters(material, 2);
  TEST_ASSERT(m.planeStress);
  // A applied to σ = diag(1, 0): ε_xx = 1/E, ε_yy = −ν/E.
  const double cd = m.complianceCoefficient(2), twoMu = 2 * m.shearModulus();
  TEST_FLOATING_EQUALITY((1.0 - cd) / twoMu, 1.0 / 2.0, 1e-15);
  TEST_FLOATING_EQUALITY(-cd / twoMu, -0.25 / 2.0, 1e-15);
  // Plane strain (the default): ε_xx = (1 − ν²)/E.
  const sc::core::Material strain{2.0, 0.25};
  TEST_FLOATING_EQUALITY((1.0 - strain.complianceCoefficient(2)) / (2 * strain.shearModulus()),
                         (1 - 0.25 * 0.25) / 2.0, 1e-15);
  const std::string msg = inputErrorOf([&] { sc::core::Material::fromParameters(material, 3); });
  TEST_ASSERT(msg.find("'Material/Plane' = 'Stress' is a 2D model") != std::string::npos);
  // ν = 0.5 in plane stress keeps A I ≠ 0: no pressure check.
  const sc::core::Material stress05{1.0, 0.5, true};
  auto bcs = sc::core::BoundaryConditions::fromParameters(
      validated([] {
        ParameterList bc;
        bc.sublist("Top").set("Type", std::string("Displacement"));
        bc.sublist("Top").set("Value", Teuchos::Array<double>(2, 0.0));
        return bc;
      }()),
      2);
  bcs.checkPressureDetermined({"Top"}, stress05);
  TEST_THROW(bcs.checkPressureDetermined({"Top"}, sc::core::Material{1.0, 0.5}),
             sc::core::InputError);
}

// The data of Displacement / Traction / Pressure: exactly one of Value, Expression and Data =
// Exact solution; the counts; Symmetry takes none. Each error names the keys.
TEUCHOS_UNIT_TEST(ProblemData, BoundaryDataKeys)
{
  auto make = [](const std::string& type, const Teuchos::Array<double>& value,
                 const Teuchos::Array<std::string>& expression) {
    ParameterList bc;
    bc.sublist("Top").set("Type", type);
    if (!value.empty()) bc.sublist("Top").set("Value", value);
    if (!expression.empty()) bc.sublist("Top").set("Expression", expression);
    return validated(bc);
  };
  const Teuchos::Array<double> none, two(2, 1.0), one(1, 3.0);
  auto error = [&](const std::string& type, const Teuchos::Array<double>& v,
                   const Teuchos::Array<std::string>& e) {
    return inputErrorOf([&] { sc::core::BoundaryConditions::fromParameters(make(type, v, e), 2); });
  };
  TEST_ASSERT(
      error("Traction", two, formulas({"0", "y"}))
          .find("'Boundary Conditions/Top/Value' and 'Boundary Conditions/Top/Expression' are "
                "both given") != std::string::npos);
  TEST_ASSERT(error("Displacement", none, {})
                  .find("'Boundary Conditions/Top' (Type Displacement) has no data: give "
                        "'Boundary Conditions/Top/Value'") != std::string::npos);
  TEST_ASSERT(error("Pressure", two, {}).find("Type Pressure takes one") != std::string::npos);
  TEST_ASSERT(
      error("Traction", none, formulas({"x"}))
          .find(
              "'Boundary Conditions/Top/Expression' has 1 formulas, but Problem/Dimension is 2") !=
      std::string::npos);
  TEST_ASSERT(error("Symmetry", one, {})
                  .find("'Boundary Conditions/Top/Value' is given, but "
                        "Type 'Symmetry' takes no data") != std::string::npos);
  TEST_ASSERT(error("Free", none, formulas({"x"})).find("Type 'Free' takes no data") !=
              std::string::npos);
  {
    ParameterList bc;
    bc.sublist("Top").set("Type", std::string("Pressure"));
    bc.sublist("Top").set("Data", std::string("Exact solution"));
    TEST_ASSERT(
        inputErrorOf([&] { sc::core::BoundaryConditions::fromParameters(validated(bc), 2); })
            .find("'Boundary Conditions/Top/Data' = 'Exact solution' is for Type "
                  "Displacement, Traction or Components") != std::string::npos);
  }
  // A formula that does not compile fails at validation, naming the key and the entry.
  {
    ParameterList deck, valid;
    ParameterList& bc = deck.sublist("Boundary Conditions");
    bc.sublist("Top").set("Type", std::string("Traction"));
    bc.sublist("Top").set("Expression", formulas({"0", "2*(y+"}));
    valid.set("Boundary Conditions", *sc::core::BoundaryConditions::getValidParameters());
    const std::string msg =
        inputErrorOf([&] { sc::core::validateParameters(deck, valid, "deck.xml"); });
    TEST_ASSERT(msg.find("deck.xml: 'Boundary Conditions/Top/Expression' entry 2 = '2*(y+' is "
                         "not a valid formula: Unexpected end of expression at position 6") !=
                std::string::npos);
  }
}

// Type Components (docs/theory.md §"Loads and supports"): component i of the data is Value[i],
// or u_i or (σn)_i of the exact solution as the entry of 'Components' says (analytic: the exact
// solution's own values); blanks around the entries are ignored; the key is refused with
// another Type and needs d entries.
TEUCHOS_UNIT_TEST(ProblemData, ComponentsData)
{
  using sc::core::ComponentCondition;
  const Teuchos::Array<std::string> dt(Teuchos::tuple<std::string>("Displacement", " Traction"));
  ParameterList bc;
  bc.sublist("Left").set("Type", std::string("Components"));
  bc.sublist("Left").set("Components", dt);
  bc.sublist("Left").set("Data", std::string("Exact solution"));
  bc.sublist("Top").set("Type", std::string("Components"));
  bc.sublist("Top").set("Components", Teuchos::Array<std::string>(
                                          Teuchos::tuple<std::string>("Traction", "Displacement")));
  bc.sublist("Top").set("Value", Teuchos::Array<double>(Teuchos::tuple<double>(2.0, -0.5)));
  const auto bcs = sc::core::BoundaryConditions::fromParameters(validated(bc), 2);
  const auto* left = bcs.find("Left");
  TEST_ASSERT(left->components == std::vector<ComponentCondition>({ComponentCondition::Displacement,
                                                                   ComponentCondition::Traction}));
  TEST_ASSERT(left->hasDisplacementComponent() && left->displacementComponent(0) &&
              !left->displacementComponent(1));
  const auto exact =
      sc::core::createExactSolution("Manufactured smooth", 2, sc::core::Material{1.0, 0.3}, M_PI);
  const double x[2] = {0.0, 0.3}, n[2] = {-1.0, 0.0};
  double data[3], u[2], t[2];
  left->evaluate(x, n, 2, exact.get(), data);
  exact->displacement(x, u);
  exact->traction(x, n, t);
  TEST_EQUALITY(data[0], u[0]);
  TEST_EQUALITY(data[1], t[1]);
  TEST_ASSERT(u[0] != t[0] && u[1] != t[1]);  // the components are told apart
  bcs.find("Top")->evaluate(x, n, 2, nullptr, data);
  TEST_EQUALITY(data[0], 2.0);
  TEST_EQUALITY(data[1], -0.5);
  {
    ParameterList wrong;
    wrong.sublist("Left").set("Type", std::string("Symmetry"));
    wrong.sublist("Left").set("Components", dt);
    TEST_ASSERT(inputErrorOf([&] {
                  sc::core::BoundaryConditions::fromParameters(validated(wrong), 2);
                }).find("'Boundary Conditions/Left/Components' is given, but Type is 'Symmetry'") !=
                std::string::npos);
  }
  {
    ParameterList three;
    three.sublist("Left").set("Type", std::string("Components"));
    three.sublist("Left").set("Components", dt);
    three.sublist("Left").set("Value", Teuchos::Array<double>(2, 0.0));
    TEST_ASSERT(
        inputErrorOf([&] { sc::core::BoundaryConditions::fromParameters(validated(three), 3); })
            .find("needs 'Boundary Conditions/Left/Components' with one entry per space "
                  "dimension (Problem/Dimension is 3)") != std::string::npos);
  }
  {
    ParameterList typo;
    typo.sublist("Left").set("Type", std::string("Components"));
    typo.sublist("Left").set("Components", Teuchos::Array<std::string>(
                                               Teuchos::tuple<std::string>("Displacement", "u")));
    TEST_ASSERT(inputErrorOf([&] { validated(typo); })
                    .find("'Left/Components' entry 2 = 'u' is not valid. Valid values: "
                          "'Displacement', 'Traction'") != std::string::npos);
  }
}

// Values of the data at a point (analytic): pressure −p n, formulas of x, y; Symmetry zero.
TEUCHOS_UNIT_TEST(ProblemData, BoundaryDataValues)
{
  ParameterList bc;
  bc.sublist("Arc").set("Type", std::string("Pressure"));
  bc.sublist("Arc").set("Expression", formulas({"2 + x*y"}));
  bc.sublist("Top").set("Type", std::string("Displacement"));
  bc.sublist("Top").set("Expression", formulas({"sin(pi*x)", "-0.01*y^2"}));
  bc.sublist("Left").set("Type", std::string("Symmetry"));
  bc.sublist("Right").set("Type", std::string("Traction"));
  bc.sublist("Right").set("Value", Teuchos::Array<double>(Teuchos::tuple<double>(1.5, 0.0)));
  const auto bcs = sc::core::BoundaryConditions::fromParameters(validated(bc), 2);
  const double x[2] = {0.5, 3.0}, n[2] = {0.6, -0.8};
  double v[2];
  bcs.find("Arc")->evaluate(x, n, 2, nullptr, v);
  TEST_FLOATING_EQUALITY(v[0], -3.5 * 0.6, 1e-15);
  TEST_FLOATING_EQUALITY(v[1], 3.5 * 0.8, 1e-15);
  bcs.find("Top")->evaluate(x, n, 2, nullptr, v);
  TEST_FLOATING_EQUALITY(v[0], 1.0, 1e-15);
  TEST_FLOATING_EQUALITY(v[1], -0.09, 1e-14);
  bcs.find("Left")->evaluate(x, n, 2, nullptr, v);
  TEST_EQUALITY(v[0], 0.0);
  TEST_EQUALITY(v[1], 0.0);
  bcs.find("Right")->evaluate(x, n, 2, nullptr, v);
  TEST_EQUALITY(v[0], 1.5);
  TEST_ASSERT(!bcs.find("Right")->isZero());
  TEST_ASSERT(bcs.find("Left")->isZero());
  TEST_ASSERT(!bcs.find("Top")->isZero());
}

// Body Force: constants or formulas, one of them, d components, not beside an exact solution.
TEUCHOS_UNIT_TEST(ProblemData, BodyForce)
{
  auto read = [](ParameterList list, const std::string& exact) {
    ParameterList valid = *sc::core::BodyForce::getValidParameters();
    sc::core::validateParameters(list, valid, "test");
    sc::core::ProblemSettings problem;
    problem.dimension = 2;
    problem.exactSolution = exact;
    return sc::core::BodyForce::fromParameters(list, problem);
  };
  TEST_ASSERT(read(ParameterList(), "None").isZero());
  ParameterList gravity;
  gravity.set("Value", Teuchos::Array<double>(Teuchos::tuple<double>(0.0, -9.81)));
  const auto g = read(gravity, "None");
  const double x[2] = {0.3, 0.7};
  double f[2];
  g.evaluate(x, 2, f);
  TEST_EQUALITY(f[0], 0.0);
  TEST_EQUALITY(f[1], -9.81);
  ParameterList formula;
  formula.set("Expression", formulas({"x", "-9.81*(2 - y)"}));
  read(formula, "None").evaluate(x, 2, f);
  TEST_FLOATING_EQUALITY(f[0], 0.3, 1e-15);
  TEST_FLOATING_EQUALITY(f[1], -9.81 * 1.3, 1e-14);
  TEST_ASSERT(inputErrorOf([&] { read(gravity, "Manufactured smooth"); })
                  .find("'Body Force/Value' is given, but 'Problem/Exact solution' = 'Manufactured "
                        "smooth' defines the body force") != std::string::npos);
  ParameterList both = gravity;
  both.set("Expression", formulas({"0", "-1"}));
  TEST_ASSERT(inputErrorOf([&] {
                read(both, "None");
              }).find("'Body Force/Value' and 'Body Force/Expression' are both given") !=
              std::string::npos);
}
