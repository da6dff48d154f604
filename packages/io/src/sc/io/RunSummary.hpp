#pragma once
// summary.json: the machine-readable record of a run (schema: docs/output.md, "summary.json").
// It is rewritten atomically after every cycle with "converged": false, so that a run that dies
// leaves the last complete summary behind, and once more at the end with the final flag.

#include <Teuchos_Comm.hpp>
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include <nlohmann/json.hpp>

#include <string>

namespace sc::io {

class RunSummary {
public:
  /// \p directory: where summary.json goes (must exist: see createOutputDirectory).
  /// \p version: the code's version string, e.g. "0.1.0". \p parameters: the full validated
  /// parameter list of the run (converted with toJson). ranks = comm->getSize().
  RunSummary(Teuchos::RCP<const Teuchos::Comm<int>> comm, const std::string& directory,
             const std::string& version, const Teuchos::ParameterList& parameters);

  /// A cycle entry with every key of the schema present: counts and scalars null, phase
  /// objects ({} for eta, errors, contact, timings) empty, to be filled by the driver.
  static nlohmann::ordered_json makeCycleEntry(int cycle);

  /// Append makeCycleEntry(cycle) and return it for filling. The reference is invalidated by the
  /// next addCycle.
  nlohmann::ordered_json& addCycle(int cycle);

  /// The last cycle added (InternalError if none).
  nlohmann::ordered_json& currentCycle();

  void setConverged(bool converged);
  /// Record why the run failed (also sets converged to false).
  void setError(const std::string& message);

  /// Collective: rank 0 writes summary.json atomically; a failure throws on every rank.
  void write() const;
  /// Not collective (for error handlers that may run on some ranks only): rank 0 writes, other
  /// ranks return at once; a failure throws on rank 0 only.
  void writeLocal() const;

  const nlohmann::ordered_json& json() const { return json_; }
  nlohmann::ordered_json& json() { return json_; }
  /// <directory>/summary.json
  const std::string& path() const { return path_; }

private:
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  std::string path_;
  nlohmann::ordered_json json_;
};

}  // namespace sc::io
