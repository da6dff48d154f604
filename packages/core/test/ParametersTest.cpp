// Unit tests of the parameter conventions: unknown keys, wrong types, ranges, choices,
// template sublists, defaults and command-line overrides. Each test checks the error text names
// the key and the valid values, since that text is what a user reads.
#include <cstdio>
#include <fstream>

#include <Teuchos_UnitTestHarness.hpp>

#include <sc/core/Expression.hpp>

#include "sc/core/Error.hpp"
#include "sc/core/Parameters.hpp"
#include "sc/core/ValueText.hpp"

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
  sc::core::declareExpressionArray(bc, "Expression", "formulas", {0, 1, 2, 3});
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
  user.sublist("Boundary Conditions")
      .sublist("Top")
      .set("Value", Teuchos::Array<double>(Teuchos::tuple<double>(0.0, -0.01)));
  user.sublist("Boundary Conditions").sublist("Arc");
  sc::core::validateParameters(user, validList(), "deck.xml");
  TEST_EQUALITY(user.sublist("Boundary Conditions").sublist("Arc").get<std::string>("Type"),
                "Free");

  ParameterList bad;
  bad.sublist("Boundary Conditions").sublist("Top").set("Typ", std::string("Free"));
  TEST_ASSERT(contains(errorOf(bad), "unknown key 'Boundary Conditions/Top/Typ'"));

  ParameterList badLength;
  badLength.sublist("Boundary Conditions")
      .sublist("Top")
      .set("Value", Teuchos::Array<double>(Teuchos::tuple<double>(1.0)));
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
  // Formulas (Array(string)) as the XML reader reads them: split at commas, in braces.
  sc::core::applyOverride(user, valid, "Boundary Conditions/Top/Expression={0, -0.01*(1 + x^2)}");
  sc::core::validateParameters(user, valid, "--set");
  const auto formulas = user.sublist("Boundary Conditions")
                            .sublist("Top")
                            .get<Teuchos::Array<std::string>>("Expression");
  TEST_EQUALITY(formulas.size(), 2);
  TEST_EQUALITY(formulas[0], "0");
  TEST_EQUALITY(formulas[1], "-0.01*(1 + x^2)");
  TEST_THROW(sc::core::applyOverride(user, valid, "Boundary Conditions/Top/Expression=-0.01*x"),
             sc::core::InputError);
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

// A UTF-8 byte-order mark before the XML is skipped (Teuchos alone said "character data outside
// of an enclosing tag"); a UTF-16 deck is refused by name.
TEUCHOS_UNIT_TEST(Parameters, ByteOrderMarks)
{
  const std::string body =
      "<ParameterList name=\"StressContact\">\n  <ParameterList name=\"Material\">\n"
      "    <Parameter name=\"Poisson ratio\" type=\"double\" value=\"0.3\"/>\n"
      "  </ParameterList>\n</ParameterList>\n";
  const std::string path = "core_unit_tests_bom.xml";
  std::ofstream(path, std::ios::binary) << "\xEF\xBB\xBF" << body;
  const auto list = sc::core::readParameterFile(path);
  TEST_FLOATING_EQUALITY(list->sublist("Material").get<double>("Poisson ratio"), 0.3, 1e-15);
  std::ofstream(path, std::ios::binary | std::ios::trunc) << "\xFF\xFE<\0P\0";
  try {
    sc::core::readParameterFile(path);
    TEST_ASSERT(false);
  } catch (const sc::core::InputError& e) {
    out << e.what() << "\n";
    TEST_ASSERT(contains(e.what(), "is UTF-16 text"));
  }
  std::remove(path.c_str());
}

namespace {

// The error readParameterFile gives for a one-list deck with the given <Parameter>s ("" if none).
std::string deckError(const std::string& body)
{
  const std::string path = "core_unit_tests_strict.xml";
  {
    std::ofstream f(path);
    f << "<ParameterList name=\"StressContact\">\n  <ParameterList name=\"Material\">\n"
      << body << "\n  </ParameterList>\n</ParameterList>\n";
  }
  std::string error;
  try {
    sc::core::readParameterFile(path);
  } catch (const sc::core::InputError& e) {
    error = e.what();
  }
  std::remove(path.c_str());
  return error;
}

std::string param(const std::string& name, const std::string& type, const std::string& value)
{
  return "<Parameter name=\"" + name + "\" type=\"" + type + "\" value=\"" + value + "\"/>";
}

}  // namespace

TEUCHOS_UNIT_TEST(Parameters, XmlNumbersAreParsedStrictly)
{
  // Teuchos alone reads these as 0, 20, 20600, 1, {0, 0} and -1 (docs/reliability.md).
  const std::string e1 = deckError(param("Poisson ratio", "double", "abc"));
  out << e1 << "\n";
  TEST_ASSERT(contains(e1, "'Material/Poisson ratio' = 'abc' is not a double (not a number)"));
  TEST_ASSERT(contains(e1, "core_unit_tests_strict.xml"));
  TEST_ASSERT(
      contains(deckError(param("Young modulus", "double", "20,600")),
               "'Material/Young modulus' = '20,600' is not a double (trailing characters ',600')"));
  TEST_ASSERT(contains(deckError(param("Young modulus", "double", "20600abc")),
                       "trailing characters 'abc'"));
  TEST_ASSERT(
      contains(deckError(param("Young modulus", "double", "")), "is not a double (empty value)"));
  TEST_ASSERT(contains(deckError(param("Young modulus", "double", "nan")), "not a finite number"));
  TEST_ASSERT(
      contains(deckError(param("Young modulus", "double", "1e999")), "out of the range of double"));
  TEST_ASSERT(contains(deckError(param("Cycles", "int", "1.5")),
                       "'Material/Cycles' = '1.5' is not an int (trailing characters '.5')"));
  TEST_ASSERT(contains(deckError(param("Cycles", "int", "99999999999999999999")),
                       "is not an int (out of the range of int"));
  TEST_ASSERT(contains(deckError(param("Cycles", "int", "3000000000")), "out of the range of int"));
  const std::string e2 = deckError(param("Value", "Array(double)", "{0, abc}"));
  out << e2 << "\n";
  TEST_ASSERT(contains(
      e2, "'Material/Value' = '{0, abc}' is not an Array(double) (entry 2 'abc': not a number)"));
  TEST_ASSERT(contains(deckError(param("Value", "Array(double)", "{0, nan}")),
                       "entry 2 'nan': not a finite number"));
  TEST_ASSERT(
      contains(deckError(param("Value", "Array(double)", "{0, }")), "entry 2 '': empty value"));
  TEST_ASSERT(contains(deckError(param("Value", "Array(double)", "0, 1")), "braces"));
  TEST_ASSERT(contains(deckError(param("Flag", "bool", "maybe")),
                       "is not a bool (expected true or false)"));
  // Valid texts pass: blanks around the value, exponents, signs, empty arrays, bool spellings.
  TEST_EQUALITY(deckError(param("A", "double", " 2.06e4 ") + param("B", "int", "-3") +
                          param("C", "Array(double)", "{ 0, -0.01 }") +
                          param("D", "Array(double)", "{}") + param("E", "bool", "true") +
                          param("F", "bool", "FALSE") + param("G", "string", "anything, 1.5abc")),
                "");
}

TEUCHOS_UNIT_TEST(Parameters, DuplicateKeysInXmlAreErrors)
{
  const std::string e =
      deckError(param("Poisson ratio", "double", "0.3") + param("Young modulus", "double", "1") +
                param("Poisson ratio", "double", "0.4"));
  out << e << "\n";
  TEST_ASSERT(contains(e, "'Material/Poisson ratio' is given twice in 'Material'"));
  TEST_ASSERT(contains(deckError("<ParameterList name=\"X\"/><ParameterList name=\"X\"/>"),
                       "'Material/X' is given twice"));
}

TEUCHOS_UNIT_TEST(Parameters, OverridesAreParsedStrictly)
{
  const ParameterList valid = validList();
  auto overrideError = [&](const std::string& assignment) {
    ParameterList user;
    try {
      sc::core::applyOverride(user, valid, assignment);
    } catch (const sc::core::InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  TEST_ASSERT(
      contains(overrideError("Material/Poisson ratio=0.3abc"), "trailing characters 'abc'"));
  TEST_ASSERT(contains(overrideError("Material/Poisson ratio="), "empty value"));
  TEST_ASSERT(contains(overrideError("Adaptivity/Cycles=1.5"), "trailing characters '.5'"));
  TEST_ASSERT(
      contains(overrideError("Adaptivity/Cycles=99999999999999999999"), "out of the range of int"));
  TEST_ASSERT(contains(overrideError("Boundary Conditions/Top/Value={0, abc}"),
                       "entry 2 'abc': not a number"));
  TEST_ASSERT(
      contains(overrideError("Boundary Conditions/Top/Value={0, nan}"), "not a finite number"));
  const std::string sub = overrideError("Material=1");
  out << sub << "\n";
  TEST_ASSERT(contains(sub, "'Material' is a sublist, not a key"));
  TEST_ASSERT(contains(sub, "'Young modulus', 'Poisson ratio'"));
  TEST_ASSERT(contains(overrideError("Boundary Conditions/Top=1"),
                       "'Boundary Conditions/Top' is a sublist"));
  TEST_EQUALITY(overrideError("Material/Poisson ratio= 0.25 "), "");
}

TEUCHOS_UNIT_TEST(Parameters, DirectoryAsDeck)
{
  try {
    sc::core::readParameterFile(".");
    TEST_ASSERT(false);
  } catch (const sc::core::InputError& e) {
    out << e.what() << "\n";
    TEST_ASSERT(contains(e.what(), "is a directory"));
  }
}

TEUCHOS_UNIT_TEST(Parameters, DeckNestingDepthIsLimited)
{
  // Lists nested `levels` deep inside the deck's list, one parameter in the innermost one:
  // levels + 2 elements deep. A comment, a CDATA section and a quoted '>' do not count.
  auto deckOfDepth = [](int levels) {
    std::string text = "<?xml version=\"1.0\"?>\n<!-- <ParameterList name=\"not counted\"> -->\n"
                       "<ParameterList name=\"StressContact\">\n";
    for (int i = 0; i < levels; ++i)
      text += "<ParameterList name=\"L" + std::to_string(i) + "\">";
    text += "<Parameter name=\"Note\" type=\"string\" value=\"a > b\"/>";
    for (int i = 0; i < levels; ++i)
      text += "</ParameterList>";
    return text + "\n</ParameterList>\n";
  };
  const std::string path = "core_unit_tests_deep.xml";
  auto readError = [&](int levels) {
    {
      std::ofstream f(path);
      f << deckOfDepth(levels);
    }
    std::string error;
    try {
      sc::core::readParameterFile(path);
    } catch (const sc::core::InputError& e) {
      error = e.what();
    }
    std::remove(path.c_str());
    return error;
  };
  const int limit = sc::core::kMaxDeckNestingDepth;
  TEST_EQUALITY(readError(limit - 2), "");
  const std::string e = readError(limit - 1);
  out << e << "\n";
  TEST_ASSERT(contains(e,
                       "the input deck 'core_unit_tests_deep.xml' nests its XML elements 65 levels "
                       "deep; at most 64 levels are accepted"));
  // Far beyond the depth at which Teuchos' conversion overflowed the stack: an error, no crash.
  TEST_ASSERT(contains(readError(100000), "nests its XML elements 100002 levels deep"));
}
