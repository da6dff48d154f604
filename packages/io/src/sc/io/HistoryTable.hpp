#pragma once
// history.csv (docs/output.md "history.csv"): one row per cycle, the numbers a user follows over
// an adaptive run — size, η and its parts, the contact headline, iteration counts, seconds —
// taken from the cycle records of summary.json, so that the two never disagree and a restarted
// run's table holds the cycles its checkpoint restored.

#include <Teuchos_Comm.hpp>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace sc::io {

/// The table of the cycle records \p cycles (summary.json's "cycles"): a header line and one
/// line per record, empty cells for null or missing values. \p dim names the force components
/// and the zone sizes (half-width in 2D, radius in 3D); \p contact adds the contact columns.
/// The η parts are the keys of the records' "eta" that are parts of η (first-seen order).
std::string formatHistory(const nlohmann::ordered_json& cycles, int dim, bool contact);

/// The column names of formatHistory.
std::vector<std::string> historyColumns(const nlohmann::ordered_json& cycles, int dim,
                                        bool contact);

/// Collective: rank 0 writes <directory>/history.csv atomically; a failure throws on every rank.
void writeHistory(const Teuchos::Comm<int>& comm, const std::string& directory,
                  const nlohmann::ordered_json& cycles, int dim, bool contact);

}  // namespace sc::io
