#pragma once
// What one cycle produced, handed by the solve and estimate steps to the output step: the
// recorder (RunRecorder: summary.json, history.csv, the contact CSV, the progress lines) and the
// field writer (CycleFields: the XDMF/HDF5 grids) read this value only, never the solvers
// (docs/output.md for what each file holds).
#include <optional>
#include <string>
#include <vector>

#include <sc/assembly/MixedElasticityAssembler.hpp>
#include <sc/contact/ContactPoint.hpp>
#include <sc/contact/ContactSummary.hpp>
#include <sc/contact/Hertz.hpp>
#include <sc/estimator/ErrorEstimate.hpp>
#include <sc/io/GridPiece.hpp>
#include <sc/mesh/Partitioning.hpp>
#include <sc/solvers/SolveStatistics.hpp>

#include <sc/adapt/StopCriteria.hpp>

#include "EstimatedErrors.hpp"
#include "ForceBalance.hpp"

namespace sc::app {

/// The cycle's unknowns.
struct DofCounts {
  long long stress = 0, displacement = 0, rotation = 0, total = 0;
};

/// The linear solver of the cycle: its name, statistics of its last solve and the Krylov
/// iterations of each solve (one per Newton step with contact).
struct LinearSolveRecord {
  std::string name;
  bool iterative = false;
  solvers::SolveStatistics last;
  /// Over the run, including the cycles before a restart (the checkpoint's counts).
  long long symbolicReuses = 0, preconditionerSetups = 0;
  int solves = 0;
  std::vector<int> iterationsPerSolve;  ///< empty with a direct solver
  /// Contact, Stopping = Fixed: the Krylov iterations that continued the settled state's solve
  /// (contact/BalancedStopping.hpp finalSolve), not in iterationsPerSolve.
  int finalSolveIterations = 0;
  /// A direct solver's seconds in this cycle (rank 0's clock): equilibration, analyses,
  /// factorisations and triangular solves, summed over the cycle's solves (0 for Krylov).
  double cycleEquilibrationSeconds = 0.0, cycleSymbolicSeconds = 0.0, cycleNumericSeconds = 0.0,
         cycleSolveSeconds = 0.0;
};

/// The contact state of a solved cycle.
struct ContactRecord {
  std::vector<contact::ContactPoint> points;  ///< this rank's, in the contact CSV's row order
  contact::ContactSummary summary;
  contact::ContactStatistics statistics;
  /// Hertz's values for the computed load, on the frictionless Hertz scenes (Half disc, Half
  /// ball) when the load presses.
  std::optional<contact::HertzComparison> hertz;
};

/// The mesh of the cycle as summary.json's "mesh" record describes it.
struct MeshRecord {
  long long vertices = 0, elements = 0;
  double measure = 0.0;  ///< of the discrete domain (with curved elements, their quadratic maps)
  int geometryOrder = 1;
  long long curvedElements = 0;
  double minAngleDeg = 0.0;
  std::vector<long long> elementsPerRank;
};

/// The fields of the cycle's XDMF step, on this rank's owned elements and vertices.
struct CycleFields {
  mesh::VertexOwnership vertices;  ///< the domain grid's points
  /// u^R (d per owned vertex, in `vertices.owned` order); empty without an estimate.
  std::vector<double> reconstructedDisplacement;
  std::optional<assembly::CellAverages> averages;  ///< of the solution (owned elements' order)
  std::optional<io::GridPiece> contactPoints;      ///< the contact points' grid (ContactFields.hpp)
};

struct CycleResults {
  int cycle = 0;
  bool solved = false;
  DofCounts dofs;
  std::optional<LinearSolveRecord> linearSolve;
  std::optional<ContactRecord> contact;
  std::optional<estimator::ErrorEstimate> estimate;
  double stressEnergyError = -1.0;  ///< ‖A^{1/2}(σ − σ_h)‖ when the exact solution is known
  std::optional<assembly::ErrorNorms> errors;  ///< against the exact solution, when known
  std::optional<CycleForces> forces;           ///< reactions and force balance of a solved cycle
  /// The error bars of the headline quantities (solved and estimated cycles).
  std::optional<EstimatedErrors> estimatedErrors;
  /// The accuracy targets of `Adaptivity` against this cycle's error bars (empty without).
  std::vector<adapt::TargetStatus> targets;
  MeshRecord mesh;
  /// Filled only when the run writes XDMF fields.
  std::optional<CycleFields> fields;
};

}  // namespace sc::app
