// check_history: a run's history.csv against its summary.json (docs/output.md "history.csv").
//
//   check_history DIR [--perturb]
//
// history.csv must have a header and one row per cycle record of summary.json; every column must
// be one of the documented ones, with the value of its summary.json key, read back bit for bit
// (an empty cell where the key is null or missing); seconds is the sum of the record's timings
// without "checkpoint" (to 1e-12 relative). Every part of η in the records has its eta_<part>
// column, and the contact columns are there exactly when the records have contact quantities.
// --perturb moves the last row's eta by one unit in the last place before comparing: the check
// must then fail. Exit status: 0 all checks hold, 1 a check failed, 2 a file could not be read.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "CsvFields.hpp"

#include <nlohmann/json.hpp>

using nlohmann::json;

namespace {

using sc::testtools::splitCsvLine;

// The JSON pointer of a column, "" for seconds, "?" for an unknown column.
std::string pointerOf(const std::string& column)
{
  static const std::set<std::string> contactKeys{
      "half_width",   "radius", "max_pressure", "stick_half_width",
      "stick_radius", "area",   "stick_area",   "newton_iterations"};
  if (column == "step" || column == "time") return "/load_step/" + column;
  // reaction_<part>_<x|y|z> and prescribed_<part>_<component>
  if (column.size() > 11 && column.rfind("reaction_", 0) == 0 && column[column.size() - 2] == '_')
    return "/reactions/" + column.substr(9, column.size() - 11) + "/force/" +
           std::to_string(column.back() - 'x');
  if (column.rfind("prescribed_", 0) == 0 && column.find_last_of('_') > 11)
    return "/load_step/prescribed/" + column.substr(11, column.find_last_of('_') - 11) + "/" +
           column.substr(column.find_last_of('_') + 1);
  if (column == "cycle" || column == "elements" || column == "linear_solves") return "/" + column;
  if (column == "dofs") return "/dofs/total";
  if (column == "eta") return "/eta/total";
  if (column == "krylov_iterations") return "/linear_iterations/total";
  if (column.rfind("eta_", 0) == 0) return "/eta/" + column.substr(4);
  if (column.size() == 7 && column.rfind("force_", 0) == 0 && column[6] >= 'x' && column[6] <= 'z')
    return "/contact/force/" + std::to_string(column[6] - 'x');
  if (contactKeys.count(column)) return "/contact/" + column;
  if (column == "seconds") return "";
  return "?";
}

}  // namespace

int main(int argc, char** argv)
{
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s DIR [--perturb]\n", argv[0]);
    return 2;
  }
  const std::string dir = argv[1];
  const bool perturb = argc > 2 && std::string(argv[2]) == "--perturb";
  std::ifstream sin(dir + "/summary.json");
  std::ifstream hin(dir + "/history.csv");
  if (!sin || !hin) {
    std::fprintf(stderr, "cannot read %s/summary.json or %s/history.csv\n", dir.c_str(),
                 dir.c_str());
    return 2;
  }
  const json summary = json::parse(sin);
  const json& cycles = summary.at("cycles");
  std::string line;
  std::getline(hin, line);
  const auto header = splitCsvLine(line);
  std::vector<std::vector<std::string>> rows;
  while (std::getline(hin, line))
    rows.push_back(splitCsvLine(line));
  int failures = 0;
  auto fail = [&](const std::string& why) {
    std::printf("FAILED: %s\n", why.c_str());
    ++failures;
  };
  if (rows.size() != cycles.size())
    fail(std::to_string(rows.size()) + " rows, summary.json has " + std::to_string(cycles.size()) +
         " cycles");
  if (perturb && !rows.empty()) {
    for (std::size_t c = 0; c < header.size(); ++c)
      if (header[c] == "eta" && !rows.back()[c].empty()) {
        char buf[40];
        std::snprintf(buf, sizeof buf, "%.17g",
                      std::nextafter(std::strtod(rows.back()[c].c_str(), nullptr), INFINITY));
        rows.back()[c] = buf;
        std::printf("perturbed: the last row's eta is %s\n", buf);
      }
  }

  // The columns: known, every η part of the records, the contact columns with contact.
  static const std::set<std::string> notParts{
      "total",          "contact_normal_signed", "stress_energy_norm",
      "relative",       "stress_energy_error",   "efficiency_index",
      "marked_elements"};
  const std::set<std::string> columns(header.begin(), header.end());
  bool contact = false;
  for (const auto& c : cycles) {
    if (c.contains("eta") && c["eta"].is_object())
      for (const auto& [key, value] : c["eta"].items())
        if (!notParts.count(key) && value.is_number() && !columns.count("eta_" + key))
          fail("no column eta_" + key);
    contact =
        contact || (c.contains("contact") && c["contact"].is_object() && !c["contact"].empty());
  }
  if (contact != columns.count("max_pressure") > 0)
    fail(contact ? "the run has contact, but there are no contact columns"
                 : "contact columns without contact");
  for (const auto& required :
       {"cycle", "dofs", "eta", "linear_solves", "krylov_iterations", "seconds"})
    if (!columns.count(required)) fail(std::string("no column ") + required);
  if (header.empty() || header.back() != "seconds") fail("the last column is not seconds");

  std::size_t compared = 0;
  for (std::size_t r = 0; r < rows.size() && r < cycles.size(); ++r) {
    const json& c = cycles[r];
    if (rows[r].size() != header.size()) {
      fail("row " + std::to_string(r) + " has " + std::to_string(rows[r].size()) + " cells");
      continue;
    }
    for (std::size_t k = 0; k < header.size(); ++k) {
      const std::string pointer = pointerOf(header[k]);
      const std::string& cell = rows[r][k];
      const std::string where = "row " + std::to_string(r) + ", " + header[k] + " = '" + cell + "'";
      if (pointer == "?") {
        if (r == 0) fail("unknown column " + header[k]);
        continue;
      }
      if (pointer.empty()) {  // seconds
        double seconds = 0.0;
        bool any = false;
        if (c.contains("timings") && c["timings"].is_object())
          for (const auto& [phase, value] : c["timings"].items())
            if (phase != "checkpoint" && value.is_number())
              seconds += value.get<double>(), any = true;
        if (any != !cell.empty() ||
            (any && std::abs(std::strtod(cell.c_str(), nullptr) - seconds) > 1e-12 * seconds))
          fail(where + ": the timings add up to " + std::to_string(seconds));
        ++compared;
        continue;
      }
      const json::json_pointer p(pointer);
      const bool present = c.contains(p) && c[p].is_number();
      if (present != !cell.empty()) {
        fail(where +
             (present ? ": empty, summary.json has " + c[p].dump() : ": summary.json has none"));
        continue;
      }
      if (present && std::strtod(cell.c_str(), nullptr) != c[p].get<double>())
        fail(where + ": summary.json has " + c[p].dump());
      ++compared;
    }
  }
  std::printf("history.csv: %zu rows, %zu columns (%s), %zu cells compared with summary.json: %s\n",
              rows.size(), header.size(), contact ? "with contact" : "no contact", compared,
              failures ? "FAILED" : "all agree");
  return failures ? 1 : 0;
}
