#pragma once
// Ruiz's iterative equilibration (D. Ruiz, "A scaling algorithm to equilibrate both rows and
// columns norms in matrices", RAL-TR-2001-034): repeatedly divide row i by sqrt(‖row i‖_∞) and
// column j by sqrt(‖column j‖_∞) until all norms are close to 1. docs/theory.md §"Contact and
// friction": the stress, displacement and rotation blocks differ in scale by orders of magnitude
// (compliance ~ 1/E); the unscaled system failed in MUMPS in the prototype.
//
// The factors are rounded to powers of two at the end, so D_r A D_c, D_r b and D_c y are exact in
// floating point: equilibration changes the pivots seen by the factorisation, never the data. Only
// maxima enter, so the factors are bit-identical for any number of ranks.

#include <Teuchos_RCP.hpp>

#include <sc/solvers/LinearAlgebraTypes.hpp>

namespace sc::solvers {

class RuizEquilibration {
public:
  /// symmetric: use one factor for rows and columns (D A D stays symmetric if A is); it is
  /// d_i ← d_i / sqrt(max(‖row i‖, ‖column i‖)).
  RuizEquilibration(bool symmetric, int maxIterations, double tolerance);
  ~RuizEquilibration();

  /// Compute D_r, D_c for A. A zero row or column (a singular matrix) throws sc::core::Error
  /// naming its global index, on every rank.
  void compute(const CrsMatrix& A);

  /// A fresh fill-complete copy of D_r A D_c (same graph as A).
  Teuchos::RCP<CrsMatrix> scaledCopy(const CrsMatrix& A) const;
  /// D_r A D_c written into the values of B, which shares A's graph (a matrix from an earlier
  /// scaledCopy of a matrix on that graph): no allocation, for repeated solves on one graph.
  void scaleInto(const CrsMatrix& A, CrsMatrix& B) const;

  /// Row factors on A's range map, column factors on A's domain map.
  const Vector& rowScaling() const { return *rowScale_; }
  const Vector& columnScaling() const { return *colScale_; }
  /// Sweeps done by the last compute() and max |1 − norm| before rounding.
  int iterations() const { return iterations_; }
  double lastDeviation() const { return deviation_; }

private:
  bool symmetric_;
  int maxIterations_;
  double tolerance_;
  int iterations_ = 0;
  double deviation_ = 0.0;
  Teuchos::RCP<Vector> rowScale_;
  Teuchos::RCP<Vector> colScale_;
};

}  // namespace sc::solvers
