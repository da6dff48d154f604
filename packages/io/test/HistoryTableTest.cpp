// history.csv (docs/output.md "history.csv"): the table of summary.json's cycle records, checked
// text for text on hand-made records.
#include <sc/io/HistoryTable.hpp>
#include <sc/io/RunSummary.hpp>

#include "TestDirectory.hpp"

#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_UnitTestHarness.hpp>

#include <fstream>
#include <sstream>

namespace {

using Json = nlohmann::ordered_json;

// Two cycles of a 2D contact run as the application records them: cycle 0 estimated, with a
// Krylov solver and the checkpoint's time (left out of the seconds); cycle 1 not yet solved
// (nulls and empty objects).
Json contactCycles()
{
  Json c0 = sc::io::RunSummary::makeCycleEntry(0);
  c0["elements"] = 390;
  c0["dofs"]["total"] = 6566;
  c0["eta"] = {{"total", 0.5},
               {"volume", 0.25},
               {"asymmetry", 0.125},
               {"oscillation", 0.0},
               {"friction", 0.375},
               {"contact_normal_signed", -1e-3},
               {"stress_energy_norm", 10.0},
               {"relative", 0.05},
               {"marked_elements", 17}};
  c0["contact"] = {{"force", {1.5, 108.25}},      {"half_width", 0.0625}, {"max_pressure", 900.5},
                   {"stick_half_width", 0.03125}, {"area", 0.125},        {"stick_area", 0.0625},
                   {"newton_iterations", 4}};
  c0["reactions"] = {{"Top", {{"type", "Displacement"}, {"force", {-1.5, -108.25}}}}};
  c0["nonlinear_iterations"] = 4;
  c0["linear_solves"] = 4;
  c0["linear_iterations"] = {{"per_solve", {10, 11, 12, 13}}, {"total", 46}};
  c0["timings"] = {{"mesh", 0.25}, {"solve", 1.5}, {"output", 0.125}, {"checkpoint", 100.0}};
  Json c1 = sc::io::RunSummary::makeCycleEntry(1);
  c1["elements"] = 700;
  return Json::array({c0, c1});
}

TEUCHOS_UNIT_TEST(HistoryTable, ContactRunColumnsAndValues)
{
  const std::string text = sc::io::formatHistory(contactCycles(), 2, true);
  const std::string expected =
      "cycle,elements,dofs,eta,eta_relative,eta_volume,eta_asymmetry,eta_oscillation,eta_friction,"
      "force_x,force_y,half_width,max_pressure,stick_half_width,area,stick_area,newton_iterations,"
      "reaction_Top_x,reaction_Top_y,linear_solves,krylov_iterations,seconds\n"
      "0,390,6566,0.5,0.050000000000000003,0.25,0.125,0,0.375,1.5,108.25,0.0625,900.5,0.03125,"
      "0.125,0.0625,4,-1.5,-108.25,4,46,1.875\n"
      "1,700,,,,,,,,,,,,,,,,,,,,\n";
  out << text;
  TEST_EQUALITY(text, expected);
}

// Load steps (docs/output.md "history.csv"): the step, its time and the prescribed values of the
// tables come after the cycle.
TEUCHOS_UNIT_TEST(HistoryTable, LoadStepColumns)
{
  Json cycles = contactCycles();
  cycles[0]["load_step"] = {{"step", 1}, {"time", 1.0}, {"prescribed", {{"Top", {0.0, -0.01}}}}};
  cycles[1]["load_step"] = {{"step", 2}, {"time", 2.5}, {"prescribed", {{"Top", {0.004, -0.01}}}}};
  const std::string text = sc::io::formatHistory(cycles, 2, true);
  out << text;
  TEST_ASSERT(text.rfind("cycle,step,time,prescribed_Top_0,prescribed_Top_1,elements,", 0) == 0);
  TEST_ASSERT(text.find("\n0,1,1,0,-0.01,390,") != std::string::npos);
  TEST_ASSERT(text.find("\n1,2,2.5,0.0040000000000000001,-0.01,700,") != std::string::npos);
}

TEUCHOS_UNIT_TEST(HistoryTable, ElasticityRun3DHasNoContactColumns)
{
  Json c = sc::io::RunSummary::makeCycleEntry(0);
  c["elements"] = 48;
  c["dofs"]["total"] = 4452;
  c["eta"] = {
      {"total", 2.0}, {"volume", 1.0}, {"stress_energy_error", 1.5}, {"efficiency_index", 1.25}};
  c["linear_solves"] = 1;
  c["timings"] = {{"solve", 0.5}};
  const std::string text = sc::io::formatHistory(Json::array({c}), 3, false);
  out << text;
  TEST_EQUALITY(text, std::string("cycle,elements,dofs,eta,eta_relative,eta_volume,linear_solves,"
                                  "krylov_iterations,seconds\n"
                                  "0,48,4452,2,,1,1,,0.5\n"));
  // A 3D contact run names the third force component and the radii.
  const auto columns = sc::io::historyColumns(Json::array({c}), 3, true);
  TEST_EQUALITY(columns[6], std::string("force_x"));
  TEST_EQUALITY(columns[8], std::string("force_z"));
  TEST_EQUALITY(columns[9], std::string("radius"));
  TEST_EQUALITY(columns[11], std::string("stick_radius"));
}

TEUCHOS_UNIT_TEST(HistoryTable, WrittenAtomicallyByRankZero)
{
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string dir = sc::io::test::freshDirectory(*comm, "history");
  sc::io::writeHistory(*comm, dir, contactCycles(), 2, true);
  comm->barrier();
  if (comm->getRank() != 0) return;
  std::ifstream in(dir + "/history.csv");
  std::stringstream s;
  s << in.rdbuf();
  TEST_EQUALITY(s.str(), sc::io::formatHistory(contactCycles(), 2, true));
  TEST_EQUALITY(sc::io::test::temporaries(dir).size(), 0u);
}

}  // namespace
