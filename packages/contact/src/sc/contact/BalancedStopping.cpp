#include "sc/contact/BalancedStopping.hpp"

#include <algorithm>
#include <cmath>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include <sc/core/Error.hpp>
#include <sc/solvers/LinearSolver.hpp>

namespace sc::contact {

namespace {

// The solver's own tolerance and residual limit come back however a solve below ends.
struct RestoreSolverSettings {
  solvers::LinearSolver& s;
  double tolerance = s.relativeTolerance(), limit = s.maximumRelativeResidual();
  ~RestoreSolverSettings()
  {
    s.setRelativeTolerance(tolerance);
    s.setMaximumRelativeResidual(limit);
  }
};

// ‖A^{1/2} e_σ‖ of the solver's error estimate e = P⁻¹(rhs − K x); `error` is work space.
double estimatedAlgebraicError(const solvers::LinearSolver& solver,
                               const Tpetra::MultiVector<>& rhs, const Tpetra::MultiVector<>& x,
                               Tpetra::MultiVector<>& error, const Tpetra::CrsMatrix<>& energy,
                               long long stressDofs)
{
  SC_THROW_IF(!solver.estimateError(rhs, x, error), core::InternalError,
              "Contact/Newton/Stopping: the solver " << solver.name()
                                                     << " gives no error estimate");
  return BalancedStopping::stressEnergyNorm(energy, error, stressDofs);
}

}  // namespace

BalancedStopping BalancedStopping::fromParameters(const Teuchos::ParameterList& newtonList)
{
  BalancedStopping s;
  s.balanced_ = newtonList.get<std::string>("Stopping") == "Balanced";
  s.fraction_ = newtonList.get<double>("Balance fraction");
  return s;
}

bool BalancedStopping::appliesTo(const solvers::LinearSolver& solver) const
{
  return balanced_ && eta_ > 0.0 && solver.isIterative();
}

double BalancedStopping::stressEnergyNorm(const Tpetra::CrsMatrix<>& energy,
                                          const Tpetra::MultiVector<>& v, long long stressDofs)
{
  Tpetra::MultiVector<> vs(v, Teuchos::Copy), Av(energy.getRangeMap(), 1);
  const auto& map = *vs.getMap();
  auto data = vs.getDataNonConst(0);
  for (std::size_t i = 0; i < map.getNodeNumElements(); ++i)
    if (map.getGlobalElement(static_cast<int>(i)) >= stressDofs) data[i] = 0.0;
  energy.apply(vs, Av);
  Teuchos::Array<double> dot(1);
  vs.dot(Av, dot());
  return std::sqrt(std::max(0.0, dot[0]));
}

BalancedStopping::Result BalancedStopping::solve(solvers::LinearSolver& solver,
                                                 const Tpetra::MultiVector<>& rhs,
                                                 Tpetra::MultiVector<>& x,
                                                 const Tpetra::CrsMatrix<>& energy,
                                                 long long stressDofs)
{
  const RestoreSolverSettings restore{solver};
  const double fixedTolerance = restore.tolerance;
  const double limit = restore.limit;

  const double bound = fraction_ * eta_;
  // The tolerance expected to give half the bound: from the error per unit of relative residual
  // of the last solve, or (first balanced solve) the relative bound γ η/‖A^{1/2}σ_h‖.
  double tolerance =
      errorPerResidual_ > 0.0 ? 0.5 * bound / errorPerResidual_ : fraction_ * relativeEta_;
  tolerance = std::clamp(tolerance, fixedTolerance, kLoosestTolerance);
  Result r;
  Tpetra::MultiVector<> error(x.getMap(), 1);
  for (;;) {
    solver.setRelativeTolerance(tolerance);
    // The Krylov solver checks its own tolerance; the residual limit (a guard against singular
    // systems) must not reject a solve that meets a looser one.
    if (limit > 0.0) solver.setMaximumRelativeResidual(std::max(limit, tolerance));
    solver.solve(rhs, x);  // from the current x: a tighter repeat continues where it stopped
    r.iterations += solver.lastSolveStats().iterations;
    r.tolerance = tolerance;
    ++r.stages;
    r.algebraicError = estimatedAlgebraicError(solver, rhs, x, error, energy, stressDofs);
    const double residual = solver.lastSolveStats().relativeResidual;
    if (residual > 0.0) errorPerResidual_ = r.algebraicError / residual;
    if (r.algebraicError <= bound || tolerance <= fixedTolerance) break;
    // Not yet balanced: the tolerance for half the bound, at least 10× tighter than this one.
    tolerance =
        std::max(fixedTolerance, std::min(0.1 * tolerance, 0.5 * bound / errorPerResidual_));
  }
  return r;
}

bool BalancedStopping::finalApplies(const solvers::LinearSolver& solver) const
{
  return !balanced_ && eta_ > 0.0 && solver.isIterative();
}

double BalancedStopping::finalFraction() { return kFinalFraction; }

BalancedStopping::Result BalancedStopping::finalSolve(solvers::LinearSolver& solver,
                                                      const Tpetra::MultiVector<>& rhs,
                                                      Tpetra::MultiVector<>& x,
                                                      const Tpetra::CrsMatrix<>& energy,
                                                      long long stressDofs) const
{
  const RestoreSolverSettings restore{solver};
  const double fixedTolerance = restore.tolerance;
  const double bound = finalFraction() * eta_;
  Result r;
  Tpetra::MultiVector<> error(x.getMap(), 1), saved(x, Teuchos::Copy);
  r.algebraicError = estimatedAlgebraicError(solver, rhs, x, error, energy, stressDofs);
  double residual = solver.lastSolveStats().relativeResidual;
  r.tolerance = fixedTolerance;
  // A relative residual below ~1e-13 is out of reach in double precision.
  constexpr double kTightest = 1e-13;
  while (r.algebraicError > bound && residual > kTightest && r.stages < 4) {
    const double perResidual = r.algebraicError / std::max(residual, 1e-300);
    const double tolerance =
        std::max(kTightest, std::min(0.1 * residual, 0.5 * bound / perResidual));
    solver.setRelativeTolerance(tolerance);
    Tpetra::deep_copy(saved, x);
    try {
      solver.solve(rhs, x);
    } catch (const core::ConvergenceError&) {
      // every rank throws together: keep the iterate before this stage
      Tpetra::deep_copy(x, saved);
      break;
    }
    r.iterations += solver.lastSolveStats().iterations;
    r.tolerance = tolerance;
    ++r.stages;
    residual = solver.lastSolveStats().relativeResidual;
    r.algebraicError = estimatedAlgebraicError(solver, rhs, x, error, energy, stressDofs);
  }
  return r;
}

}  // namespace sc::contact
