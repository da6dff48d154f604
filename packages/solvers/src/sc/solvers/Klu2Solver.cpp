// Amesos2 KLU2 behind DirectSolver. The only translation unit that includes Amesos2.
//
// Why we gather ourselves: with Debian's Trilinos 13.2, Amesos2's own gather (the path taken when
// the matrix's communicator has more than one rank) returned wrong solutions for a plain
// distributed 5-point Laplacian (relative error 0.7 at 2 and 4 ranks, also with every row owned
// by rank 0), while its serial path is exact. So the matrix, the right-hand sides and the
// solution are moved to and from rank 0 with Tpetra, and Amesos2 only ever sees a matrix on
// MPI_COMM_SELF. Errors on rank 0 are broadcast so that every rank throws the same one.

#include <sc/solvers/Klu2Solver.hpp>

#include <algorithm>
#include <exception>
#include <limits>
#include <numeric>
#include <vector>

#include <Amesos2.hpp>
#include <Teuchos_DefaultMpiComm.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_MultiVector.hpp>

#include <sc/core/Collective.hpp>
#include <sc/core/Error.hpp>

namespace sc::solvers {

struct Klu2Solver::Impl {
  Teuchos::RCP<const Teuchos::Comm<int>> comm;    // the operator's communicator
  Teuchos::RCP<const Map> rootMap;                // every row on rank 0 (distributed comm)
  Teuchos::RCP<const Tpetra::Import<>> toRoot;    // row map -> root map
  Teuchos::RCP<const Tpetra::Import<>> fromRoot;  // root map -> domain map
  Teuchos::RCP<const Map> serialMap;              // 0..N-1 on MPI_COMM_SELF (rank 0 only)
  Teuchos::RCP<const CrsMatrix> serialMatrix;     // rank 0 only
  Teuchos::RCP<Amesos2::Solver<CrsMatrix, MultiVector>> solver;  // rank 0 only
  long long indexBase = 0;

  bool isRoot() const { return comm->getRank() == 0; }
  void gatherMatrix(const CrsMatrix& A);
};

namespace {

// Run f on rank 0 only; if it throws, every rank throws sc::core::Error naming the phase.
template <class F>
void onRoot(const Teuchos::Comm<int>& comm, const std::string& phase, F f)
{
  sc::core::runOnRoot(comm, [&] {
    try {
      f();
    } catch (const std::exception& e) {
      // Amesos2's messages start with file:line and "Throw number"; keep their last line.
      std::string message = e.what();
      while (!message.empty() && (message.back() == '\n' || message.back() == ' '))
        message.pop_back();
      const auto nl = message.find_last_of('\n');
      if (nl != std::string::npos) message = message.substr(nl + 1);
      throw sc::core::Error("KLU2 " + phase + " failed: " + message +
                            (phase == "numerical factorisation"
                                 ? " (the matrix is singular to working precision)"
                                 : ""));
    }
  });
}

}  // namespace

void Klu2Solver::Impl::gatherMatrix(const CrsMatrix& A)
{
  // All rows to rank 0 (collective), then a serial copy with columns 0..N-1 sorted in each row.
  const auto rooted = Tpetra::importAndFillCompleteCrsMatrix<CrsMatrix>(Teuchos::rcpFromRef(A),
                                                                        *toRoot, rootMap, rootMap);
  if (!isRoot()) return;
  const auto lcl = rooted->getLocalMatrixHost();
  const auto colMap = rooted->getColMap();
  const size_t n = rooted->getNodeNumRows();
  const size_t nnz = lcl.values.extent(0);
  Kokkos::View<size_t*, Kokkos::HostSpace> rowPtr("rowPtr", n + 1);
  Kokkos::View<int*, Kokkos::HostSpace> cols("cols", nnz);
  Kokkos::View<double*, Kokkos::HostSpace> vals("vals", nnz);
  std::vector<size_t> order;
  for (size_t i = 0; i < n; ++i) {
    const size_t begin = lcl.graph.row_map(i), end = lcl.graph.row_map(i + 1);
    rowPtr(i) = begin;
    order.resize(end - begin);
    std::iota(order.begin(), order.end(), begin);
    auto gcol = [&](size_t k) { return colMap->getGlobalElement(lcl.graph.entries(k)); };
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return gcol(a) < gcol(b); });
    for (size_t k = begin; k < end; ++k) {
      cols(k) = static_cast<int>(gcol(order[k - begin]) - indexBase);
      vals(k) = lcl.values(order[k - begin]);
    }
  }
  rowPtr(n) = nnz;
  auto S = Teuchos::rcp(new CrsMatrix(serialMap, serialMap, rowPtr, cols, vals));
  S->fillComplete(serialMap, serialMap);
  serialMatrix = S;
}

Klu2Solver::Klu2Solver() : impl_(std::make_unique<Impl>())
{
  SC_THROW_IF(!isAvailable(), sc::core::InputError,
              "Linear Solver/Type = KLU2: this Trilinos build has no Amesos2 KLU2; use MUMPS");
}

Klu2Solver::~Klu2Solver() = default;

bool Klu2Solver::isAvailable() { return Amesos2::query("KLU2"); }

void Klu2Solver::doSymbolicFactorization(const Teuchos::RCP<const CrsMatrix>& A)
{
  Impl& m = *impl_;
  m.comm = A->getComm();
  const auto N = A->getGlobalNumRows();
  SC_THROW_IF(N > static_cast<Tpetra::global_size_t>(std::numeric_limits<int>::max()),
              sc::core::InputError,
              "KLU2: the system has " << N << " rows, more than KLU2's int index limit");
  m.indexBase = A->getRowMap()->getMinAllGlobalIndex();
  SC_THROW_IF(A->getRowMap()->getMaxAllGlobalIndex() - m.indexBase + 1 != static_cast<long long>(N),
              sc::core::InternalError,
              "KLU2: the row map must hold the global indices " << m.indexBase << ".."
                                                                << m.indexBase + N - 1);
  m.rootMap = Teuchos::rcp(new Map(N, m.isRoot() ? N : 0, m.indexBase, m.comm));
  m.toRoot = Teuchos::rcp(new Tpetra::Import<>(A->getRowMap(), m.rootMap));
  m.fromRoot = Teuchos::rcp(new Tpetra::Import<>(m.rootMap, A->getDomainMap()));
  m.solver = Teuchos::null;
  m.serialMatrix = Teuchos::null;
  if (m.isRoot()) {
    Teuchos::RCP<const Teuchos::Comm<int>> self =
        Teuchos::rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
    m.serialMap = Teuchos::rcp(new Map(N, 0, self));
  }
  m.gatherMatrix(*A);
  onRoot(*m.comm, "symbolic factorisation", [&] {
    m.solver = Amesos2::create<CrsMatrix, MultiVector>("KLU2", m.serialMatrix);
    m.solver->symbolicFactorization();
  });
}

void Klu2Solver::doNumericFactorization(const Teuchos::RCP<const CrsMatrix>& A)
{
  Impl& m = *impl_;
  // New values, same graph (DirectSolver checked it): keep the symbolic phase (docs/theory.md
  // §"Linear solvers").
  m.gatherMatrix(*A);
  long long nnzLU = 0;
  onRoot(*m.comm, "numerical factorisation", [&] {
    m.solver->setA(m.serialMatrix, Amesos2::SYMBFACT);
    m.solver->numericFactorization();
    nnzLU = static_cast<long long>(m.solver->getStatus().getNnzLU());
  });
  sc::core::broadcast(*m.comm, 0, nnzLU);
  stats_.factorNonzeros = nnzLU;
}

void Klu2Solver::doSolve(const MultiVector& b, MultiVector& x)
{
  Impl& m = *impl_;
  const size_t nrhs = b.getNumVectors();
  MultiVector bRoot(m.rootMap, nrhs, false), xRoot(m.rootMap, nrhs, false);
  bRoot.doImport(b, *m.toRoot, Tpetra::INSERT);
  onRoot(*m.comm, "solve", [&] {
    // Views of the rank-0 data as serial multivectors (same memory, no copy).
    MultiVector bSerial(bRoot, m.serialMap), xSerial(xRoot, m.serialMap);
    m.solver->solve(Teuchos::ptrFromRef(xSerial), Teuchos::ptrFromRef(bSerial));
  });
  x.doImport(xRoot, *m.fromRoot, Tpetra::INSERT);
}

}  // namespace sc::solvers
