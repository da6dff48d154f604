#include <sc/io/HistoryTable.hpp>

#include <sc/io/AtomicFile.hpp>
#include <sc/core/Collective.hpp>
#include <sc/io/CsvWriter.hpp>

#include <algorithm>
#include <filesystem>
#include <set>
#include <sstream>

namespace sc::io {

namespace {

// Entries of a record's "eta" that are not parts of η (docs/output.md "summary.json").
const std::set<std::string>& notParts()
{
  static const std::set<std::string> keys{
      "total",          "contact_normal_signed", "stress_energy_norm",
      "relative",       "stress_energy_error",   "efficiency_index",
      "marked_elements"};
  return keys;
}

std::vector<std::string> etaParts(const nlohmann::ordered_json& cycles)
{
  std::vector<std::string> parts;
  for (const auto& c : cycles) {
    if (!c.contains("eta") || !c["eta"].is_object()) continue;
    for (const auto& [key, value] : c["eta"].items())
      if (!notParts().count(key) && value.is_number() &&
          std::find(parts.begin(), parts.end(), key) == parts.end())
        parts.push_back(key);
  }
  return parts;
}

// The value at a path of keys (and array indices), or null.
const nlohmann::ordered_json& at(const nlohmann::ordered_json& record,
                                 std::initializer_list<const char*> keys, int index = -1)
{
  static const nlohmann::ordered_json null;
  const nlohmann::ordered_json* node = &record;
  for (const char* k : keys) {
    if (!node->is_object() || !node->contains(k)) return null;
    node = &(*node)[k];
  }
  if (index >= 0) {
    if (!node->is_array() || node->size() <= static_cast<std::size_t>(index)) return null;
    node = &(*node)[static_cast<std::size_t>(index)];
  }
  return *node;
}

CsvWriter::Value cell(const nlohmann::ordered_json& v)
{
  if (v.is_number()) return v.get<double>();
  return std::string();
}

}  // namespace

namespace {

bool hasLoadSteps(const nlohmann::ordered_json& cycles)
{
  for (const auto& c : cycles)
    if (c.contains("load_step")) return true;
  return false;
}

// The names under `key` (an object of objects) of the records, in order of first appearance:
// the parts with reactions, or the parts with prescribed values per load step.
std::vector<std::string> namesUnder(const nlohmann::ordered_json& cycles,
                                    std::initializer_list<const char*> keys)
{
  std::vector<std::string> names;
  for (const auto& c : cycles) {
    const auto& node = at(c, keys);
    if (!node.is_object()) continue;
    for (const auto& [name, value] : node.items())
      if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  }
  return names;
}

}  // namespace

std::vector<std::string> historyColumns(const nlohmann::ordered_json& cycles, int dim, bool contact)
{
  std::vector<std::string> columns{"cycle"};
  if (hasLoadSteps(cycles)) {
    columns.insert(columns.end(), {"step", "time"});
    for (const auto& part : namesUnder(cycles, {"load_step", "prescribed"}))
      for (std::size_t i = 0;
           i < at(cycles.back(), {"load_step", "prescribed", part.c_str()}).size(); ++i)
        columns.push_back("prescribed_" + part + "_" + std::to_string(i));
  }
  columns.insert(columns.end(), {"elements", "dofs", "eta", "eta_relative"});
  for (const auto& part : etaParts(cycles))
    columns.push_back("eta_" + part);
  if (contact) {
    for (int i = 0; i < dim; ++i)
      columns.push_back(std::string("force_") + "xyz"[i]);
    const std::string zone = dim == 2 ? "half_width" : "radius";
    columns.insert(columns.end(), {zone, "max_pressure", "stick_" + zone, "area", "stick_area",
                                   "newton_iterations"});
  }
  for (const auto& part : namesUnder(cycles, {"reactions"}))
    for (int i = 0; i < dim; ++i)
      columns.push_back("reaction_" + part + "_" + "xyz"[i]);
  columns.insert(columns.end(), {"linear_solves", "krylov_iterations", "seconds"});
  return columns;
}

std::string formatHistory(const nlohmann::ordered_json& cycles, int dim, bool contact)
{
  CsvWriter table(historyColumns(cycles, dim, contact));
  const auto parts = etaParts(cycles);
  const std::string zone = dim == 2 ? "half_width" : "radius";
  for (const auto& c : cycles) {
    // Filled by index, not push_back: GCC 12 warns (-Wmaybe-uninitialized, a false positive)
    // about moving std::variant<double, std::string> when a vector of them grows.
    CsvWriter::Row row(table.header().size());
    std::size_t i = 0;
    row[i++] = cell(at(c, {"cycle"}));
    if (hasLoadSteps(cycles)) {
      row[i++] = cell(at(c, {"load_step", "step"}));
      row[i++] = cell(at(c, {"load_step", "time"}));
      for (const auto& part : namesUnder(cycles, {"load_step", "prescribed"}))
        for (std::size_t k = 0;
             k < at(cycles.back(), {"load_step", "prescribed", part.c_str()}).size(); ++k)
          row[i++] = cell(at(c, {"load_step", "prescribed", part.c_str()}, static_cast<int>(k)));
    }
    row[i++] = cell(at(c, {"elements"}));
    row[i++] = cell(at(c, {"dofs", "total"}));
    row[i++] = cell(at(c, {"eta", "total"}));
    row[i++] = cell(at(c, {"eta", "relative"}));
    for (const auto& part : parts)
      row[i++] = cell(at(c, {"eta", part.c_str()}));
    if (contact) {
      for (int k = 0; k < dim; ++k)
        row[i++] = cell(at(c, {"contact", "force"}, k));
      row[i++] = cell(at(c, {"contact", zone.c_str()}));
      row[i++] = cell(at(c, {"contact", "max_pressure"}));
      row[i++] = cell(at(c, {"contact", ("stick_" + zone).c_str()}));
      row[i++] = cell(at(c, {"contact", "area"}));
      row[i++] = cell(at(c, {"contact", "stick_area"}));
      row[i++] = cell(at(c, {"contact", "newton_iterations"}));
    }
    for (const auto& part : namesUnder(cycles, {"reactions"}))
      for (int k = 0; k < dim; ++k)
        row[i++] = cell(at(c, {"reactions", part.c_str(), "force"}, k));
    row[i++] = cell(at(c, {"linear_solves"}));
    row[i++] = cell(at(c, {"linear_iterations", "total"}));
    // The cycle's phases as its progress line adds them: writing the checkpoint comes after the
    // record (and a restarted run's copy of the record lacks it).
    const auto& timings = at(c, {"timings"});
    if (timings.is_object() && !timings.empty()) {
      double seconds = 0.0;
      for (const auto& [phase, value] : timings.items())
        if (phase != "checkpoint" && value.is_number()) seconds += value.get<double>();
      row[i++] = seconds;
    } else {
      row[i++] = std::string();
    }
    table.addRow(std::move(row));
  }
  return table.format();
}

void writeHistory(const Teuchos::Comm<int>& comm, const std::string& directory,
                  const nlohmann::ordered_json& cycles, int dim, bool contact)
{
  core::runOnRoot(comm, [&] {
    writeFileAtomically((std::filesystem::path(directory) / "history.csv").string(),
                        formatHistory(cycles, dim, contact));
  });
}

}  // namespace sc::io
