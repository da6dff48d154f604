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
                                                      "Write contact CSV"}));
  const sc::io::OutputSettings defaults;
  TEST_EQUALITY(defaults.directory, "output");
  TEST_EQUALITY(defaults.baseName, "solution");
  TEST_EQUALITY(defaults.writeXdmf, true);
  TEST_EQUALITY(defaults.writeContactCsv, true);
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

}  // namespace
