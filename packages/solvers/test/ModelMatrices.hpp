#pragma once
// Model systems for the solver tests and the benchmark. Every matrix has a contiguous row map
// (Tpetra's uniform distribution of 0..N-1) and entries defined by formulas of the global
// indices, so the same system is built for any number of ranks.

#include <vector>

#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>

#include <sc/solvers/LinearAlgebraTypes.hpp>

namespace sc::solvers::testing {

/// 5-point finite-difference Laplacian on an n × n grid (Dirichlet boundary eliminated), SPD.
/// duplicateLastRow: row N−1 := row N−2 (exactly singular, same graph shape as a real row).
Teuchos::RCP<CrsMatrix> poisson2d(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, int n,
                                  bool duplicateLastRow = false);

/// 7-point Laplacian on an n × n × n grid, SPD.
Teuchos::RCP<CrsMatrix> poisson3d(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, int n);

/// Symmetric indefinite saddle point [[sM·K, sB·Bᵀ], [sB·B, 0]]: K = 2D Laplacian + I on an n × n
/// grid (n² unknowns), B (n²/2 × n²) has B[p,2p] = 2, B[p,2p+1] = −1, B[p,2p+3] = 0.5, so its
/// columns 2p form 2I: full row rank. With sM = 1e-8, sB = 1e4 the blocks differ by 12 orders of
/// magnitude, like compliance (~1/E) and divergence blocks (docs/theory.md §"Contact and
/// friction"). n must be even.
Teuchos::RCP<CrsMatrix> saddlePoint(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, int n,
                                    double scaleM, double scaleB);

/// Copy of A (same graph) in which every row whose global index is ≡ 0 mod period is replaced as a
/// contact row would be (docs/theory.md §"Contact and friction"): all entries 0 except the diagonal
/// = 1 and the entry in column row+1, if stored, = coupling (a slip row coupling σ_T to σ_N).
/// Non-symmetric. Only rows below rowLimit (if >= 0) are replaced: in a saddle point, contact rows
/// are stress rows.
Teuchos::RCP<CrsMatrix> withReplacedRows(const CrsMatrix& A, long long period, double coupling,
                                         long long rowLimit = -1);

/// Copy of A (same graph) with row `row` set to explicit zeros.
Teuchos::RCP<CrsMatrix> withZeroRow(const CrsMatrix& A, long long row);

/// Copy of A (same graph) with `shift` added to each diagonal entry (symmetric if A is).
Teuchos::RCP<CrsMatrix> withShiftedDiagonal(const CrsMatrix& A, double shift);

/// Manufactured solution x*_i = sin(0.37 i + 0.1) + 0.5 cos(0.011 i) (i = global index).
Teuchos::RCP<MultiVector> manufacturedSolution(const Teuchos::RCP<const Map>& map, int columns = 1);

/// Manufactured solution of saddlePoint(n, sM, sB) as the physics scales it: x*_u as above and
/// x*_p = (sM/sB)·(as above), so that both terms of the first block row have the same size (as
/// σ = O(load) and u = O(load/E) in mixed elasticity). nu = n² is the size of the first block.
Teuchos::RCP<MultiVector> manufacturedSaddleSolution(const Teuchos::RCP<const Map>& map,
                                                     long long nu, double scaleM, double scaleB);

/// max over columns of ‖x − y‖₂ / ‖y‖₂.
double relativeError(const MultiVector& x, const MultiVector& y);

/// The same restricted to the global indices [begin, end) (one block of a block system).
double relativeErrorInRange(const MultiVector& x, const MultiVector& y, long long begin,
                            long long end);

/// All entries of a distributed vector on rank 0 (in global order), empty on other ranks.
std::vector<double> gatherToRoot(const MultiVector& x);

}  // namespace sc::solvers::testing
