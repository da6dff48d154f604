#pragma once
// The error bars of a cycle's headline quantities (docs/output.md "Error bars"): the contact
// force |F|, the contact half-width (2D) / radius (3D) and its equivalent from the area, the peak
// pressure, the stick zone's width, and the force of each reaction, each with its estimated error
// in the quantity's units from the history of the run's earlier cycles of the same load step
// (adapt::estimateQuantityError: Richardson-type in η_CF). The history is read from the cycle
// records of summary.json, so that a restarted run continues it.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include <sc/adapt/AdaptiveProblem.hpp>

namespace sc::app {

struct CycleResults;

struct EstimatedErrors {
  /// summary.json contact key (half_width or radius, ...) → estimated error; nullopt: none yet.
  std::vector<std::pair<std::string, std::optional<double>>> contact;
  /// reaction part → estimated error of |force|.
  std::vector<std::pair<std::string, std::optional<double>>> reactions;
  /// The quantities with accuracy targets (adapt::StopCriteria's names), for the stop criteria.
  std::vector<adapt::QuantityEstimate> targets;
};

/// The estimates for the cycle `results` (solved, estimated), from `cycles` (summary.json's
/// records of the earlier cycles); `loadStep` (1-based, 0 without load steps) selects the
/// earlier cycles of the same step. `friction`: the stick zone is estimated too.
EstimatedErrors estimateErrors(const nlohmann::ordered_json& cycles, const CycleResults& results,
                               int dim, bool friction, int loadStep);

}  // namespace sc::app
