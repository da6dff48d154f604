// toJson(ParameterList) and RunSummary (summary.json).
#include <sc/io/ParameterListJson.hpp>
#include <sc/io/RunSummary.hpp>

#include "TestDirectory.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_UnitTestHarness.hpp>

#include <fstream>
#include <sstream>

namespace {

using sc::io::test::freshDirectory;
using sc::io::test::temporaries;
using Json = nlohmann::ordered_json;

Teuchos::ParameterList sampleParameters()
{
  Teuchos::ParameterList pl("StressContact");
  pl.sublist("Problem").set("Dimension", 2);
  auto& mat = pl.sublist("Material");
  mat.set("Young modulus", 200.0e9);
  mat.set("Poisson ratio", 0.3);
  auto& bc = pl.sublist("Boundary Conditions").sublist("bottom");
  bc.set("Type", std::string("Contact"));
  bc.set("Value", Teuchos::Array<double>(std::vector<double>{0.0, -1.5e-3}));
  pl.sublist("Mesh").set("Project boundary", true);
  pl.sublist("Mesh").set("Uniform refinements", 0);
  pl.sublist("Mesh").set("Ids", Teuchos::Array<int>(std::vector<int>{3, 1, 2}));
  pl.sublist("Mesh").set("Names", Teuchos::Array<std::string>(std::vector<std::string>{"a", "b"}));
  pl.sublist("Mesh").set("Big", 12345678901LL);
  pl.sublist("Empty");
  return pl;
}

TEUCHOS_UNIT_TEST(ParameterListJson, TypesAndNestingPreserved)
{
  const Json j = sc::io::toJson(sampleParameters());
  TEST_ASSERT(j.is_object());
  TEST_ASSERT(j["Problem"]["Dimension"].is_number_integer());
  TEST_EQUALITY(j["Problem"]["Dimension"].get<int>(), 2);
  TEST_ASSERT(j["Material"]["Young modulus"].is_number_float());
  TEST_EQUALITY(j["Material"]["Young modulus"].get<double>(), 200.0e9);
  TEST_EQUALITY(j["Material"]["Poisson ratio"].get<double>(), 0.3);
  const Json& bc = j["Boundary Conditions"]["bottom"];
  TEST_ASSERT(bc["Type"].is_string());
  TEST_EQUALITY(bc["Type"].get<std::string>(), "Contact");
  TEST_ASSERT(bc["Value"].is_array());
  TEST_EQUALITY(bc["Value"].size(), 2u);
  TEST_EQUALITY(bc["Value"][1].get<double>(), -1.5e-3);
  TEST_ASSERT(j["Mesh"]["Project boundary"].is_boolean());
  TEST_EQUALITY(j["Mesh"]["Project boundary"].get<bool>(), true);
  TEST_ASSERT(j["Mesh"]["Ids"][0].is_number_integer());
  TEST_EQUALITY(j["Mesh"]["Ids"][0].get<int>(), 3);
  TEST_EQUALITY(j["Mesh"]["Names"][1].get<std::string>(), "b");
  TEST_EQUALITY(j["Mesh"]["Big"].get<long long>(), 12345678901LL);
  TEST_ASSERT(j["Empty"].is_object() && j["Empty"].empty());
  // Insertion order kept (ordered_json).
  std::vector<std::string> keys;
  for (auto it = j["Mesh"].begin(); it != j["Mesh"].end(); ++it)
    keys.push_back(it.key());
  TEST_COMPARE_ARRAYS(keys, (std::vector<std::string>{"Project boundary", "Uniform refinements",
                                                      "Ids", "Names", "Big"}));
}

TEUCHOS_UNIT_TEST(RunSummary, CycleEntryHasEverySchemaKey)
{
  const Json c = sc::io::RunSummary::makeCycleEntry(3);
  std::vector<std::string> keys;
  for (auto it = c.begin(); it != c.end(); ++it)
    keys.push_back(it.key());
  TEST_COMPARE_ARRAYS(keys, (std::vector<std::string>{
                                "cycle", "elements", "dofs", "mesh", "eta", "errors", "contact",
                                "reactions", "force_balance", "nonlinear_iterations",
                                "linear_solves", "linear_iterations", "timings", "memory"}));
  TEST_EQUALITY(c["cycle"].get<int>(), 3);
  for (const char* k : {"stress", "displacement", "rotation", "total"})
    TEST_ASSERT(c["dofs"].contains(k) && c["dofs"][k].is_null());
  for (const char* k : {"vertices", "elements", "measure", "min_angle_deg"})
    TEST_ASSERT(c["mesh"].contains(k) && c["mesh"][k].is_null());
  for (const char* k :
       {"eta", "errors", "contact", "reactions", "force_balance", "timings", "memory"})
    TEST_ASSERT(c[k].is_object() && c[k].empty());
}

TEUCHOS_UNIT_TEST(RunSummary, WrittenAfterEachCycleAndRoundTrips)
{
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string dir = freshDirectory(*comm, "summary");
  sc::io::RunSummary summary(comm, dir, "0.1.0", sampleParameters());
  auto read = [&] {
    std::ifstream in(summary.path());
    std::stringstream s;
    s << in.rdbuf();
    return Json::parse(s.str());
  };

  Json& c0 = summary.addCycle(0);
  c0["elements"] = 128;
  c0["dofs"]["total"] = 1000;
  c0["timings"]["assemble"] = 0.25;
  summary.write();
  comm->barrier();
  if (comm->getRank() == 0) {
    const Json j = read();
    std::vector<std::string> keys;
    for (auto it = j.begin(); it != j.end(); ++it)
      keys.push_back(it.key());
    TEST_COMPARE_ARRAYS(keys, (std::vector<std::string>{"code", "parameters", "ranks", "converged",
                                                        "cycles", "error"}));
    TEST_EQUALITY(j["code"]["name"].get<std::string>(), "StressContact");
    TEST_EQUALITY(j["code"]["version"].get<std::string>(), "0.1.0");
    TEST_EQUALITY(j["ranks"].get<int>(), comm->getSize());
    TEST_EQUALITY(j["converged"].get<bool>(), false);  // mid-run: not (yet) converged
    TEST_ASSERT(j["error"].is_null());
    TEST_EQUALITY(j["cycles"].size(), 1u);
    TEST_EQUALITY(j["cycles"][0]["elements"].get<int>(), 128);
    TEST_EQUALITY(j["cycles"][0]["timings"]["assemble"].get<double>(), 0.25);
    TEST_EQUALITY(j["parameters"]["Material"]["Poisson ratio"].get<double>(), 0.3);
  }

  summary.addCycle(1)["eta"]["total"] = 1.5e-3;
  summary.setConverged(true);
  summary.write();
  comm->barrier();
  if (comm->getRank() == 0) {
    const Json j = read();
    TEST_EQUALITY(j["converged"].get<bool>(), true);
    TEST_EQUALITY(j["cycles"].size(), 2u);
    TEST_EQUALITY(j["cycles"][1]["cycle"].get<int>(), 1);
    TEST_EQUALITY(j["cycles"][1]["eta"]["total"].get<double>(), 1.5e-3);
    TEST_EQUALITY(temporaries(dir).size(), 0u);
  }

  summary.setError("Linear solver failed: \xff bad byte");
  summary.writeLocal();
  comm->barrier();
  if (comm->getRank() == 0) {
    const Json j = read();
    TEST_EQUALITY(j["converged"].get<bool>(), false);
    TEST_ASSERT(j["error"].get<std::string>().rfind("Linear solver failed", 0) == 0);
  }
}

}  // namespace
