#pragma once
// What the adaptive loop (AdaptiveLoop.hpp) asks of a problem: one named step each for the
// deal.II tutorial cycle solve → estimate → mark → refine (docs/architecture.md "The adaptive
// loop"). The loop owns the cycle count, the marking and the stop criteria; the problem owns
// its mesh, its discretization, its solution and its output. StressContact's application
// (apps/stresscontact/Simulation) is one implementation; packages/adapt/test/AdaptiveLoopTest.cpp
// is another, a piecewise-constant approximation on a 1D mesh.
//
// Parallel: every step is collective. The loop calls the same steps in the same order on every
// rank; `Marker::mark` (the only communication of the loop itself) sums the indicators of each
// rank's owned elements, so the mesh must be the same on every rank (replicated), with each
// element owned by exactly one rank.
#include <limits>
#include <string>
#include <vector>

namespace sc::adapt {

/// The elements to refine for the next cycle, chosen by the loop's Marker.
struct Marking {
  /// Refine every element by the problem's own uniform refinement (`Adaptivity/Marking` =
  /// Uniform, no indicators needed; StressContact: d bisections of every element). `elements`
  /// is then empty.
  bool uniform = false;
  /// Otherwise: the elements to refine (sorted, the same on every rank), indices into the mesh
  /// that was estimated. Empty once the loop stops.
  std::vector<int> elements;
};

/// A quantity users read and its estimated error (QuantityError.hpp), for the accuracy targets
/// of StopCriteria.
struct QuantityEstimate {
  std::string name;  ///< one of StopCriteria's target names: force, width, pressure, stick width
  double value = 0.0;
  double error = -1.0;  ///< same units as value; negative: no estimate this cycle
};

/// What the loop needs from a cycle's estimate.
struct CycleEstimate {
  long long dofs = 0;      ///< unknowns of the solved cycle (for Max DOFs); 0 if nothing was solved
  int numElements = 0;     ///< elements of the (replicated) mesh that was solved
  bool available = false;  ///< false: no estimate this cycle (η, norm and indicators are unused)
  double eta = 0.0;        ///< global η = (Σ_T η_T²)^{1/2}, over all ranks
  double norm = 0.0;  ///< the norm `Target error` is relative to (StressContact: ‖A^{1/2}σ_h‖)
  std::vector<int> ownedElements;  ///< this rank's elements (each element has one owner)
  std::vector<double> indicators;  ///< η_T² of ownedElements[i] (not η_T)
  /// The quantities with targets (empty without): the same on every rank.
  std::vector<QuantityEstimate> quantities;
};

/// The size of the next mesh, forecast before it is built, for the memory stop criterion
/// (StopCriteria::memoryReason). The default forecast has no limit.
struct NextMeshForecast {
  double dofs = 0.0;
  double bytes = 0.0;
  double limitBytes = std::numeric_limits<double>::infinity();  ///< no limit
  std::string limitSource;  ///< where the limit comes from, for the message
};

class AdaptiveProblem {
public:
  virtual ~AdaptiveProblem() = default;

  /// Refine the mesh by `marking` (the previous cycle's) and carry over to the new mesh what the
  /// next solve starts from (StressContact: the contact state, through the refinement history,
  /// which is then forgotten). Called at the start of every cycle but cycle 0.
  virtual void refine(const Marking& marking) = 0;
  /// Set up the discrete problem on the current mesh (partition, spaces, assembly) and solve it.
  virtual void solve(int cycle) = 0;
  /// Estimate the error of the cycle's solution (or report none: `available` = false).
  virtual CycleEstimate estimate(int cycle) = 0;
  /// The forecast of the mesh that `marking` would give, checked before the cycle is output.
  /// A problem that knows no memory limit need not override it.
  virtual NextMeshForecast forecastNextMesh(const Marking& /*marking*/) const { return {}; }
  /// Write the cycle's results. `marking` is what the next cycle will refine and `stopReason`
  /// is "" or why this is the last cycle.
  virtual void output(int cycle, const Marking& marking, const std::string& stopReason) = 0;
  /// After output, if the run goes on: save what a restart needs to continue with cycle + 1
  /// (the mesh of `cycle`, `marking`, the state the next solve starts from). The default saves
  /// nothing.
  virtual void checkpoint(int /*cycle*/, const Marking& /*marking*/) {}
};

}  // namespace sc::adapt
