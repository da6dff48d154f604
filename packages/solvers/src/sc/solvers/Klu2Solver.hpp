#pragma once
// Amesos2's KLU2 (serial sparse LU with BTF and AMD ordering). Amesos2 gathers a distributed
// matrix onto rank 0, factorises there and scatters the solution: exact for any rank count, but
// neither the memory nor the time scale with ranks. Use it for small problems and as the reference.

#include <memory>

#include <sc/solvers/DirectSolver.hpp>

namespace sc::solvers {

class Klu2Solver : public DirectSolver {
public:
  Klu2Solver();
  ~Klu2Solver() override;
  std::string name() const override { return "KLU2"; }

  /// Amesos2::query("KLU2"): false if this Trilinos was built without it.
  static bool isAvailable();

protected:
  void doSymbolicFactorization(const Teuchos::RCP<const CrsMatrix>& A) override;
  void doNumericFactorization(const Teuchos::RCP<const CrsMatrix>& A) override;
  void doSolve(const MultiVector& b, MultiVector& x) override;

private:
  struct Impl;  // holds the Amesos2::Solver (keeps Amesos2's headers out of this one)
  std::unique_ptr<Impl> impl_;
};

}  // namespace sc::solvers
