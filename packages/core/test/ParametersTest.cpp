// Unit tests of the parameter conventions: unknown keys, wrong types, ranges, choices,
// template sublists, defaults and command-line overrides. Each test checks the error text names
// the key and the valid values, since that text is what a user reads.
#include <cstdio>
#include <fstream>

#include <Teuchos_UnitTestHarness.hpp>

#include "sc/core/Error.hpp"
#include "sc/core/Parameters.hpp"

using Teuchos::ParameterList;

namespace {

ParameterList validList()
{
  ParameterList valid;
  ParameterList& m = valid.sublist("Material");
  sc::core::declareReal(m, "Young modulus", 1.0, "E", 0.0, true, sc::core::kInfinity, false);
  sc::core::declareReal(m, "Poisson ratio", 0.3, "nu", 0.0, false, 0.5, false);
  ParameterList& a = valid.sublist("Adaptivity");
  sc::core::declareInt(a, "Cycles", 0, "cycles", 0, 100);
  sc::core::declareChoice(a, "Marking", "Dorfler", {"Dorfler", "Maximum", "Uniform"}, "marking");
  ParameterList& bc = valid.sublist("Boundary Conditions").sublist(sc::core::kTemplateSublist);
  sc::core::declareChoice(bc, "Type", "Free", {"Displacement", "Free"}, "type");
  sc::core::declareRealArray(bc, "Value", Teuchos::Array<double>(), "value", {0, 2, 3});
  return valid;
}

std::string errorOf(ParameterList user)
{
  try {
    sc::core::validateParameters(user, validList(), "deck.xml");
  } catch (const sc::core::InputError& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}

}  // namespace

TEUCHOS_UNIT_TEST(Parameters, DefaultsAreFilledIn)
{
  ParameterList user;
  user.sublist("Material").set("Young modulus", 20600.0);
  sc::core::validateParameters(user, validList(), "deck.xml");
  TEST_FLOATING_EQUALITY(user.sublist("Material").get<double>("Young modulus"), 20600.0, 1e-15);
  TEST_FLOATING_EQUALITY(user.sublist("Material").get<double>("Poisson ratio"), 0.3, 1e-15);
  TEST_EQUALITY(user.sublist("Adaptivity").get<std::string>("Marking"), "Dorfler");
}

TEUCHOS_UNIT_TEST(Parameters, MisspeltKeyIsNamedWithSuggestion)
{
  ParameterList user;
  user.sublist("Material").set("Poison ratio", 0.3);
  const std::string e = errorOf(user);
  TEST_ASSERT(contains(e, "deck.xml"));
  TEST_ASSERT(contains(e, "unknown key 'Material/Poison ratio'"));
  TEST_ASSERT(contains(e, "did you mean 'Poisson ratio'"));
  TEST_ASSERT(contains(e, "'Young modulus', 'Poisson ratio'"));
}

TEUCHOS_UNIT_TEST(Parameters, OutOfRangeValuesNameRange)
{
  ParameterList user;
  user.sublist("Material").set("Young modulus", 0.0);
  std::string e = errorOf(user);
  TEST_ASSERT(contains(e, "Young modulus"));
  TEST_ASSERT(contains(e, "(0, inf)"));

  ParameterList user2;
  user2.sublist("Material").set("Poisson ratio", 0.51);
  e = errorOf(user2);
  TEST_ASSERT(contains(e, "Poisson ratio' = 0.51"));
  TEST_ASSERT(contains(e, "[0, 0.5]"));

  // ν = 0.5 exactly is valid (incompressible).
  ParameterList user3;
  user3.sublist("Material").set("Poisson ratio", 0.5);
  TEST_EQUALITY(errorOf(user3), "");
}

TEUCHOS_UNIT_TEST(Parameters, WrongTypeAndIntToDouble)
{
  ParameterList user;
  user.sublist("Material").set("Young modulus", std::string("big"));
  const std::string e = errorOf(user);
  TEST_ASSERT(contains(e, "has type string"));
  TEST_ASSERT(contains(e, "must be of type double"));

  ParameterList user2;
  user2.sublist("Material").set("Young modulus", 7);
  sc::core::validateParameters(user2, validList(), "deck.xml");
  TEST_FLOATING_EQUALITY(user2.sublist("Material").get<double>("Young modulus"), 7.0, 1e-15);
}

TEUCHOS_UNIT_TEST(Parameters, ChoicesAreListed)
{
  ParameterList user;
  user.sublist("Adaptivity").set("Marking", std::string("Dorfer"));
  const std::string e = errorOf(user);
  TEST_ASSERT(contains(e, "'Dorfer' is not valid"));
  TEST_ASSERT(contains(e, "did you mean 'Dorfler'"));
  TEST_ASSERT(contains(e, "'Dorfler', 'Maximum', 'Uniform'"));
}

TEUCHOS_UNIT_TEST(Parameters, TemplateSublistsAreCheckedAndFilled)
{
  ParameterList user;
  user.sublist("Boundary Conditions").sublist("Top").set("Type", std::string("Displacement"));
  user.sublist("Boundary Conditions").sublist("Top").set("Value", Teuchos::Array<double>(Teuchos::tuple<double>(0.0, -0.01)));
  user.sublist("Boundary Conditions").sublist("Arc");
  sc::core::validateParameters(user, validList(), "deck.xml");
  TEST_EQUALITY(user.sublist("Boundary Conditions").sublist("Arc").get<std::string>("Type"),
                "Free");

  ParameterList bad;
  bad.sublist("Boundary Conditions").sublist("Top").set("Typ", std::string("Free"));
  TEST_ASSERT(contains(errorOf(bad), "unknown key 'Boundary Conditions/Top/Typ'"));

  ParameterList badLength;
  badLength.sublist("Boundary Conditions").sublist("Top").set("Value", Teuchos::Array<double>(Teuchos::tuple<double>(1.0)));
  TEST_ASSERT(contains(errorOf(badLength), "has 1 entries; it must have 0 or 2 or 3"));
}

TEUCHOS_UNIT_TEST(Parameters, Overrides)
{
  const ParameterList valid = validList();
  ParameterList user;
  sc::core::applyOverride(user, valid, "Material/Poisson ratio=0.4999");
  sc::core::applyOverride(user, valid, "Adaptivity/Cycles=3");
  sc::core::applyOverride(user, valid, "Boundary Conditions/Top/Value={0, -0.02}");
  sc::core::validateParameters(user, valid, "--set");
  TEST_FLOATING_EQUALITY(user.sublist("Material").get<double>("Poisson ratio"), 0.4999, 1e-15);
  TEST_EQUALITY(user.sublist("Adaptivity").get<int>("Cycles"), 3);
  TEST_FLOATING_EQUALITY(
      user.sublist("Boundary Conditions").sublist("Top").get<Teuchos::Array<double>>("Value")[1],
      -0.02, 1e-15);
  TEST_THROW(sc::core::applyOverride(user, valid, "Material/Poison ratio=0.3"),
             sc::core::InputError);
  TEST_THROW(sc::core::applyOverride(user, valid, "Adaptivity/Cycles=two"), sc::core::InputError);
  TEST_THROW(sc::core::applyOverride(user, valid, "Material/Poisson ratio"), sc::core::InputError);
}

TEUCHOS_UNIT_TEST(Parameters, ClosestMatch)
{
  TEST_EQUALITY(sc::core::closestMatch("Poison ratio", {"Young modulus", "Poisson ratio"}),
                "Poisson ratio");
  TEST_EQUALITY(sc::core::closestMatch("Colour", {"Young modulus", "Poisson ratio"}), "");
}

TEUCHOS_UNIT_TEST(Parameters, MissingAndMalformedFiles)
{
  TEST_THROW(sc::core::readParameterFile("/nonexistent/deck.xml"), sc::core::InputError);
  const std::string path = "core_unit_tests_malformed.xml";
  {
    std::ofstream f(path);
    f << "<ParameterList name=\"x\">\n  <Parameter name=\"a\" type=\"double\" value=\"1\"\n";
  }
  try {
    sc::core::readParameterFile(path);
    TEST_ASSERT(false);
  } catch (const sc::core::InputError& e) {
    TEST_ASSERT(contains(e.what(), path));
  }
  std::remove(path.c_str());
}
