#pragma once
// Load steps (docs/theory.md §"Load steps"): a run as a sequence of quasi-static steps at the
// pseudo-times t_1 < ... < t_n, each solved from the state of the step before (friction on the
// slip increment). The data of each step: the boundary parts' and the body force's
// "Values per step" rows, formulas of t, and the obstacle's displacement. Without the section
// a run is one step at t = 1 (the static problem).
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

namespace sc::core {

struct LoadSteps {
  std::vector<double> times{1.0};  ///< t_1 < ... < t_n
  bool given = false;              ///< the deck has a Load steps section with Times
  /// Adaptive cycles of every step after the first (the first runs Adaptivity/Cycles).
  int cyclesPerLaterStep = 0;
  /// Rigid displacement of the obstacle at each step (d values per step), or empty.
  std::vector<double> obstacleDisplacement;

  int numSteps() const { return static_cast<int>(times.size()); }
  /// The obstacle's displacement at step `step` (0-based; zeros without a table).
  std::vector<double> obstacleDisplacementAt(int step, int dimension) const;

  static Teuchos::RCP<const Teuchos::ParameterList> getValidParameters();
  /// Throws InputError naming the key for times that do not increase, a first time ≤ 0, or an
  /// obstacle table whose rows do not match the times.
  static LoadSteps fromParameters(const Teuchos::ParameterList& list, int dimension);
};

}  // namespace sc::core
