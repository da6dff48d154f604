// Unit tests of the scene data: compliance coefficient c_d, Hertz modulus, boundary conditions
// against the problem dimension and the mesh's boundary names (the Contact settings are tested
// in the contact package).
#include <functional>

#include <Teuchos_UnitTestHarness.hpp>

#include "sc/core/Error.hpp"
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
  bcs.checkPressureDetermined({"Top", "Arc"}, nearly);             // well-posed below 0.5
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
  TEST_THROW(bcs.checkPressureDetermined({"Top"}, sc::core::Material{1.0, 0.5}), sc::core::InputError);
}
