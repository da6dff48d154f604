// The Output sublist: defaults, documentation, validation.
#include <sc/io/OutputSettings.hpp>

#include <sc/core/Error.hpp>

#include <Teuchos_UnitTestHarness.hpp>

namespace {

TEUCHOS_UNIT_TEST(OutputSettings, EveryEntryHasDefaultAndDocumentation)
{
  const auto valid = sc::io::OutputSettings::getValidParameters();
  std::vector<std::string> keys;
  for (auto it = valid->begin(); it != valid->end(); ++it) {
    keys.push_back(valid->name(it));
    TEST_ASSERT(!valid->entry(it).docString().empty());
  }
  TEST_COMPARE_ARRAYS(keys, (std::vector<std::string>{"Directory", "Base name", "Write XDMF",
                                                      "Write contact CSV", "Moment point"}));
  const sc::io::OutputSettings defaults;
  TEST_EQUALITY(defaults.directory, "output");
  TEST_EQUALITY(defaults.baseName, "solution");
  TEST_EQUALITY(defaults.writeXdmf, true);
  TEST_EQUALITY(defaults.writeContactCsv, true);
  TEST_EQUALITY(defaults.momentPoint[0], 0.0);
  TEST_EQUALITY(defaults.momentPoint[1], 0.0);
  TEST_EQUALITY(defaults.momentPoint[2], 0.0);
}

TEUCHOS_UNIT_TEST(OutputSettings, ReadsValuesAndRejectsBadOnes)
{
  Teuchos::ParameterList pl("Output");
  pl.set("Directory", std::string("results/run1"));
  pl.set("Write XDMF", false);
  const sc::io::OutputSettings s(pl);
  TEST_EQUALITY(s.directory, "results/run1");
  TEST_EQUALITY(s.writeXdmf, false);
  TEST_EQUALITY(s.baseName, "solution");

  Teuchos::ParameterList typo("Output");
  typo.set("Directroy", std::string("x"));
  try {
    sc::io::OutputSettings bad(typo);
    TEST_ASSERT(false);
  } catch (const sc::core::InputError& e) {
    TEST_ASSERT(std::string(e.what()).find("Directroy") != std::string::npos);
  }
  Teuchos::ParameterList wrongType("Output");
  wrongType.set("Write XDMF", 1);
  TEST_THROW(sc::io::OutputSettings{wrongType}, sc::core::InputError);
  Teuchos::ParameterList slash("Output");
  slash.set("Base name", std::string("a/b"));
  TEST_THROW(sc::io::OutputSettings{slash}, sc::core::InputError);
}

TEUCHOS_UNIT_TEST(OutputSettings, MomentPointHasThreeComponents)
{
  Teuchos::ParameterList pl("Output");
  pl.set("Moment point", Teuchos::Array<double>(Teuchos::tuple<double>(1.0, -2.0, 0.5)));
  const sc::io::OutputSettings s(pl);
  TEST_EQUALITY(s.momentPoint[0], 1.0);
  TEST_EQUALITY(s.momentPoint[1], -2.0);
  TEST_EQUALITY(s.momentPoint[2], 0.5);
  Teuchos::ParameterList two("Output");
  two.set("Moment point", Teuchos::Array<double>(Teuchos::tuple<double>(1.0, 2.0)));
  try {
    sc::io::OutputSettings bad(two);
    TEST_ASSERT(false);
  } catch (const sc::core::InputError& e) {
    out << e.what() << "\n";
    TEST_ASSERT(std::string(e.what()).find("Moment point") != std::string::npos);
    TEST_ASSERT(std::string(e.what()).find("must have 3") != std::string::npos);
  }
}

}  // namespace
