#pragma once
// Teuchos::ParameterList -> JSON, for summary.json: the record of exactly which parameters a run
// used, readable by any script without a Teuchos XML parser.

#include <Teuchos_ParameterList.hpp>

#include <nlohmann/json.hpp>

namespace sc::io {

/// Convert \p list keeping order and types: sublists -> objects; bool, int, long long, double,
/// float, string -> the JSON type; Teuchos::Array of int / long long / double / string -> arrays;
/// Teuchos::TwoDArray -> array of rows. Any other type becomes its string form (as in XML).
/// Non-finite doubles become null (JSON has no NaN/Inf). Does not mark parameters as used.
nlohmann::ordered_json toJson(const Teuchos::ParameterList& list);

}  // namespace sc::io
