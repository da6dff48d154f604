// MUMPS behind DirectSolver, through dmumps_c.h (see the header for the data layout).

#include <sc/solvers/MumpsSolver.hpp>

#include <algorithm>
#include <climits>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include <dmumps_c.h>
#include <mpi.h>

#include <Teuchos_DefaultMpiComm.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_MultiVector.hpp>

#include <sc/core/Error.hpp>
#include <sc/solvers/SaddlePointOrdering.hpp>

// MUMPS documents its controls 1-based.
#define ICNTL(I) icntl[(I)-1]
#define CNTL(I) cntl[(I)-1]
#define INFOG(I) infog[(I)-1]

namespace sc::solvers {

struct MumpsSolver::Impl {
  DMUMPS_STRUC_C id{};
  bool initialized = false;
  const Teuchos::Comm<int>* commIdentity = nullptr;  // communicator of the MUMPS instance
  int rank = 0;

  // Distributed assembled input (ICNTL(18) = 3): 1-based global indices of the entries passed,
  // and the positions of those entries in the local CSR values (all of them for SYM = 0, the
  // lower triangle for SYM = 2).
  std::vector<MUMPS_INT> irn, jcn;
  std::vector<double> values;
  std::vector<size_t> entryPosition;

  // Centralised right-hand side / solution on rank 0.
  long long firstGid = 0;
  MUMPS_INT n = 0;
  Teuchos::RCP<const Map> hostMap;               // all N indices on rank 0
  Teuchos::RCP<const Tpetra::Import<>> gather;   // range map -> host map
  Teuchos::RCP<const Tpetra::Import<>> scatter;  // host map -> domain map
  std::vector<double> rhs;

  // Our pivot order (Ordering = METIS, ICNTL(7) = 1): PERM_IN on the host, 1-based positions.
  std::vector<MUMPS_INT> permIn;
  MPI_Comm rawComm = MPI_COMM_SELF;

  void call(int job)
  {
    id.job = job;
    dmumps_c(&id);
  }

  void terminate()
  {
    if (!initialized) return;
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (!finalized) call(-2);
    initialized = false;
  }
};

namespace {

const char* phaseName(int job)
{
  switch (job) {
  case -1: return "initialisation (JOB = -1)";
  case 1: return "analysis (JOB = 1)";
  case 2: return "factorisation (JOB = 2)";
  case 3: return "solve (JOB = 3)";
  default: return "call";
  }
}

// INFOG(1) is global: every rank sees the same value and throws the same error.
void checkInfo(const DMUMPS_STRUC_C& id, int job)
{
  const int code = id.INFOG(1);
  SC_THROW_IF(code < 0, sc::core::Error,
              "MUMPS " << phaseName(job) << " failed: INFOG(1) = " << code
                       << ", INFOG(2) = " << id.INFOG(2) << ": " << MumpsSolver::errorMeaning(code)
                       << " (N = " << id.n << ", SYM = " << id.sym << ")");
}

// Ordering = METIS: the matrix graph gathered on rank 0 (the host, where the sequential analysis
// runs), ordered there by saddlePointOrdering, returned as MUMPS' PERM_IN (1-based positions; empty
// on the other ranks). Collective.
std::vector<MUMPS_INT> metisPivotOrder(const CrsMatrix& A, long long firstGid, MPI_Comm comm,
                                       bool verbose)
{
  const double t0 = MPI_Wtime();
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  const auto rowMap = A.getRowMap();
  const auto colMap = A.getColMap();
  const auto lclA = A.getLocalMatrixHost();
  const int nRows = static_cast<int>(A.getNodeNumRows());
  // Per owned row: its 0-based global index, its length, whether its diagonal is zero; then the
  // 0-based global columns of all owned rows.
  std::vector<int> rows(static_cast<size_t>(nRows)), lengths(static_cast<size_t>(nRows));
  std::vector<char> zero(static_cast<size_t>(nRows));
  std::vector<int> cols;
  cols.reserve(static_cast<size_t>(lclA.graph.entries.extent(0)));
  for (int i = 0; i < nRows; ++i) {
    const long long gi = rowMap->getGlobalElement(i) - firstGid;
    rows[static_cast<size_t>(i)] = static_cast<int>(gi);
    bool diagonal = false;
    const auto b = lclA.graph.row_map(i), e = lclA.graph.row_map(i + 1);
    for (auto k = b; k < e; ++k) {
      const long long gj = colMap->getGlobalElement(lclA.graph.entries(k)) - firstGid;
      cols.push_back(static_cast<int>(gj));
      if (gj == gi && lclA.values(k) != 0.0) diagonal = true;
    }
    lengths[static_cast<size_t>(i)] = static_cast<int>(e - b);
    zero[static_cast<size_t>(i)] = diagonal ? 0 : 1;
  }
  const long long localEntries = static_cast<long long>(cols.size());
  long long globalEntries = 0;
  MPI_Allreduce(&localEntries, &globalEntries, 1, MPI_LONG_LONG, MPI_SUM, comm);
  SC_THROW_IF(globalEntries > INT_MAX, sc::core::InputError,
              "Linear Solver/MUMPS/Ordering = METIS: the matrix has "
                  << globalEntries << " entries, more than the gather on rank 0 allows (" << INT_MAX
                  << "); use AMF");
  std::vector<int> rowCounts(static_cast<size_t>(size)), entryCounts(static_cast<size_t>(size));
  const int localEntryCount = static_cast<int>(localEntries);
  MPI_Gather(&nRows, 1, MPI_INT, rowCounts.data(), 1, MPI_INT, 0, comm);
  MPI_Gather(&localEntryCount, 1, MPI_INT, entryCounts.data(), 1, MPI_INT, 0, comm);
  std::vector<int> rowOffsets(static_cast<size_t>(size), 0),
      entryOffsets(static_cast<size_t>(size), 0);
  int totalRows = 0, totalEntries = 0;
  if (rank == 0)
    for (int r = 0; r < size; ++r) {
      rowOffsets[static_cast<size_t>(r)] = totalRows;
      entryOffsets[static_cast<size_t>(r)] = totalEntries;
      totalRows += rowCounts[static_cast<size_t>(r)];
      totalEntries += entryCounts[static_cast<size_t>(r)];
    }
  std::vector<int> allRows(static_cast<size_t>(totalRows)),
      allLengths(static_cast<size_t>(totalRows)), allCols(static_cast<size_t>(totalEntries));
  std::vector<char> allZero(static_cast<size_t>(totalRows));
  MPI_Gatherv(rows.data(), nRows, MPI_INT, allRows.data(), rowCounts.data(), rowOffsets.data(),
              MPI_INT, 0, comm);
  MPI_Gatherv(lengths.data(), nRows, MPI_INT, allLengths.data(), rowCounts.data(),
              rowOffsets.data(), MPI_INT, 0, comm);
  MPI_Gatherv(zero.data(), nRows, MPI_CHAR, allZero.data(), rowCounts.data(), rowOffsets.data(),
              MPI_CHAR, 0, comm);
  MPI_Gatherv(cols.data(), localEntryCount, MPI_INT, allCols.data(), entryCounts.data(),
              entryOffsets.data(), MPI_INT, 0, comm);
  cols = std::vector<int>();
  const double t1 = MPI_Wtime();

  std::vector<MUMPS_INT> permIn;
  int failed = 0;
  std::string message;
  if (rank == 0) {
    try {
      // CSR in global row order.
      const int n = totalRows;
      std::vector<std::int64_t> start(static_cast<size_t>(n) + 1, 0);
      std::vector<char> zeroDiagonal(static_cast<size_t>(n));
      for (int r = 0; r < n; ++r) {
        start[static_cast<size_t>(allRows[static_cast<size_t>(r)]) + 1] =
            allLengths[static_cast<size_t>(r)];
        zeroDiagonal[static_cast<size_t>(allRows[static_cast<size_t>(r)])] =
            allZero[static_cast<size_t>(r)];
      }
      for (int i = 0; i < n; ++i)
        start[static_cast<size_t>(i) + 1] += start[static_cast<size_t>(i)];
      std::vector<int> columns(static_cast<size_t>(totalEntries));
      std::int64_t source = 0;
      for (int r = 0; r < n; ++r) {
        const auto len = allLengths[static_cast<size_t>(r)];
        std::copy(allCols.begin() + source, allCols.begin() + source + len,
                  columns.begin() + start[static_cast<size_t>(allRows[static_cast<size_t>(r)])]);
        source += len;
      }
      allCols = std::vector<int>();
      double metisSeconds = 0.0;
      const auto position = saddlePointOrdering(n, start, columns, zeroDiagonal, &metisSeconds);
      permIn.resize(static_cast<size_t>(n));
      for (int i = 0; i < n; ++i)
        permIn[static_cast<size_t>(i)] =
            static_cast<MUMPS_INT>(position[static_cast<size_t>(i)] + 1);
      if (verbose) {
        const long long zeros = std::count(zeroDiagonal.begin(), zeroDiagonal.end(), 1);
        std::printf("StressContact METIS ordering: %d unknowns (%lld with a zero diagonal), "
                    "%d entries; gather %.3f s, ordering %.3f s (METIS_NodeND %.3f s)\n",
                    n, zeros, totalEntries, t1 - t0, MPI_Wtime() - t1, metisSeconds);
        std::fflush(stdout);
      }
    } catch (const std::exception& e) {
      failed = 1;
      message = e.what();
    }
  }
  MPI_Bcast(&failed, 1, MPI_INT, 0, comm);
  SC_THROW_IF(failed != 0, sc::core::Error,
              "Linear Solver/MUMPS/Ordering = METIS failed"
                  << (rank == 0 ? ": " + message : std::string(" on rank 0")));
  return permIn;
}

}  // namespace

std::string MumpsSolver::errorMeaning(int infog1)
{
  switch (infog1) {
  case -1: return "an error occurred on rank INFOG(2)";
  case -2: return "the number of entries NNZ is out of range";
  case -3: return "invalid JOB (e.g. factorisation without analysis)";
  case -5:
  case -7: return "memory allocation failed during analysis";
  case -6: return "the matrix is structurally singular (INFOG(2) = structural rank)";
  case -8:
    return "integer workspace too small for factorisation: increase MUMPS/Memory relaxation "
           "percent";
  case -9:
    return "real workspace too small for factorisation: increase MUMPS/Memory relaxation percent";
  case -10: return "the matrix is numerically singular";
  case -11: return "real workspace too small for the solve";
  case -12: return "real workspace too small for iterative refinement";
  case -13: return "memory allocation failed (out of memory; INFOG(2) = requested size)";
  case -14: return "integer workspace too small for the solve";
  case -15: return "integer workspace too small for iterative refinement";
  case -16: return "N is out of range";
  case -17: return "internal send buffer too small";
  case -19: return "ICNTL(23) (maximum memory) is too small";
  case -20: return "internal reception buffer too small";
  case -21: return "PAR = 0 is not allowed on one process";
  case -22: return "a pointer array is missing or has the wrong size";
  case -40: return "SYM = 1 but the matrix is not positive definite";
  default: return "see the MUMPS 5.5 user guide, section 8 (error diagnostics)";
  }
}

MumpsSolver::MumpsSolver(const MumpsOptions& options)
    : impl_(std::make_unique<Impl>()), options_(options)
{
}

MumpsSolver::~MumpsSolver()
{
  // JOB = -2 is collective: solvers are destroyed on every rank together, like Tpetra objects.
  impl_->terminate();
}

void MumpsSolver::symmetryChanged()
{
  // SYM is fixed at JOB = -1: the next analysis re-initialises (collectively, on every rank).
  impl_->commIdentity = nullptr;
}

void MumpsSolver::doSymbolicFactorization(const Teuchos::RCP<const CrsMatrix>& A)
{
  Impl& m = *impl_;
  const auto comm = A->getComm();
  const auto rowMap = A->getRowMap();
  const auto colMap = A->getColMap();

  // --- checks: MUMPS takes 32-bit 1-based indices 1..N of uniquely owned rows
  const long long nGlobal = static_cast<long long>(A->getGlobalNumRows());
  SC_THROW_IF(nGlobal > INT_MAX, sc::core::InputError,
              "MUMPS: the system has " << nGlobal << " rows, more than MUMPS' 32-bit index limit "
                                       << INT_MAX);
  const long long firstGid = rowMap->getMinAllGlobalIndex();
  SC_THROW_IF(rowMap->getMaxAllGlobalIndex() - firstGid + 1 != nGlobal || !rowMap->isOneToOne(),
              sc::core::InternalError,
              "MUMPS: the row map must own the global indices "
                  << firstGid << ".." << firstGid + nGlobal - 1 << " once each");
  SC_THROW_IF(!A->getRangeMap()->isSameAs(*rowMap), sc::core::InternalError,
              "MUMPS: the range map must equal the row map");

  // --- (re)initialise the instance on A's communicator
  if (!m.initialized || m.commIdentity != comm.get()) {
    m.terminate();
    MPI_Comm raw = MPI_COMM_SELF;
    const auto mpiComm = Teuchos::rcp_dynamic_cast<const Teuchos::MpiComm<int>>(comm);
    if (!mpiComm.is_null())
      raw = *mpiComm->getRawMpiComm();
    else
      SC_THROW_IF(comm->getSize() != 1, sc::core::InternalError,
                  "MUMPS: the matrix's communicator is not an MPI communicator");
    m.id = DMUMPS_STRUC_C{};
    m.rawComm = raw;
    m.id.comm_fortran = static_cast<MUMPS_INT>(MPI_Comm_c2f(raw));
    m.id.par = 1;  // the host takes part in the factorisation
    m.id.sym = isSymmetric() ? 2 : 0;
    m.call(-1);
    checkInfo(m.id, -1);
    m.initialized = true;
    m.commIdentity = comm.get();
    m.rank = comm->getRank();
  }
  DMUMPS_STRUC_C& id = m.id;
  if (options_.verbose) {
    id.ICNTL(1) = 6;  // errors
    id.ICNTL(2) = 0;  // diagnostics
    id.ICNTL(3) = 6;  // global information, on the host
    id.ICNTL(4) = 2;
  } else {
    id.ICNTL(1) = -1;
    id.ICNTL(2) = -1;
    id.ICNTL(3) = -1;
    id.ICNTL(4) = 0;
  }
  id.ICNTL(5) = 0;  // assembled matrix
  // Ordering = METIS (5): MUMPS 5.5.1 as Debian builds it has no METIS and would fall back to its
  // automatic choice; we compute a METIS ordering that respects the zero diagonal block and give
  // it as the pivot order (ICNTL(7) = 1, PERM_IN on the host; docs/solvers.md "Ordering").
  const bool ownOrdering = options_.ordering == 5;
  id.ICNTL(7) = ownOrdering ? 1 : options_.ordering;
  // MUMPS' own scaling, applied on top of ours (the matrix it sees is D_r A D_c when
  // equilibrating).
  id.ICNTL(8) = options_.scaling >= 0 ? options_.scaling : (equilibrationEnabled() ? 0 : 77);
  id.ICNTL(14) = options_.memoryRelaxationPercent;
  id.ICNTL(18) = 3;  // distributed assembled matrix: structure at analysis, values at factorisation
  id.ICNTL(20) = 0;  // dense centralised right-hand side
  id.ICNTL(21) = 0;  // centralised solution
  // Sequential analysis on the gathered graph: the ordering, hence the factors, do not depend on
  // the number of ranks (results agree across rank counts, docs/theory.md §"Parallel model").
  id.ICNTL(28) = 1;
  // Block low-rank (MUMPS 5.5): chosen at the analysis, which plans the BLR clustering of the
  // fronts; CNTL(7) is the accuracy of the compressed blocks (docs/solvers.md "Block low-rank").
  id.ICNTL(35) = options_.lowRankTolerance > 0.0 ? 2 : 0;
  id.CNTL(7) = options_.lowRankTolerance;

  // --- local entries with 1-based global indices
  const auto lclA = A->getLocalMatrixHost();
  const auto nRows = static_cast<int>(A->getNodeNumRows());
  const bool lowerOnly = id.sym != 0;  // MUMPS sums a_ij and a_ji for SYM != 0
  m.irn.clear();
  m.jcn.clear();
  m.entryPosition.clear();
  for (int i = 0; i < nRows; ++i) {
    const long long gi = rowMap->getGlobalElement(i) - firstGid + 1;
    for (auto k = lclA.graph.row_map(i); k < lclA.graph.row_map(i + 1); ++k) {
      const long long gj = colMap->getGlobalElement(lclA.graph.entries(k)) - firstGid + 1;
      SC_THROW_IF(gj < 1 || gj > nGlobal, sc::core::InternalError,
                  "MUMPS: column index " << gj + firstGid - 1 << " outside the row index range");
      if (lowerOnly && gj > gi) continue;
      m.irn.push_back(static_cast<MUMPS_INT>(gi));
      m.jcn.push_back(static_cast<MUMPS_INT>(gj));
      m.entryPosition.push_back(static_cast<size_t>(k));
    }
  }
  m.values.resize(m.entryPosition.size());
  for (size_t e = 0; e < m.entryPosition.size(); ++e)
    m.values[e] = lclA.values(m.entryPosition[e]);

  m.n = static_cast<MUMPS_INT>(nGlobal);
  m.firstGid = firstGid;
  id.n = m.n;
  id.nnz_loc = static_cast<MUMPS_INT8>(m.irn.size());
  id.nz_loc = 0;  // superseded by nnz_loc (64-bit)
  id.irn_loc = m.irn.data();
  id.jcn_loc = m.jcn.data();
  id.a_loc = m.values.data();

  // --- gather/scatter plans for the centralised right-hand side and solution
  const Tpetra::global_size_t nG = static_cast<Tpetra::global_size_t>(nGlobal);
  m.hostMap =
      Teuchos::rcp(new Map(nG, m.rank == 0 ? static_cast<size_t>(nGlobal) : 0, firstGid, comm));
  m.gather = Teuchos::rcp(new Tpetra::Import<>(A->getRangeMap(), m.hostMap));
  m.scatter = Teuchos::rcp(new Tpetra::Import<>(m.hostMap, A->getDomainMap()));

  if (ownOrdering) {
    m.permIn = metisPivotOrder(*A, firstGid, m.rawComm, options_.verbose);
    id.perm_in = m.rank == 0 ? m.permIn.data() : nullptr;
  } else {
    m.permIn.clear();
    id.perm_in = nullptr;
  }

  m.call(1);
  checkInfo(id, 1);
  stats_.mumpsEstimatedMemoryMaxMB = id.INFOG(16);
  stats_.mumpsEstimatedMemoryTotalMB = id.INFOG(17);
}

void MumpsSolver::doNumericFactorization(const Teuchos::RCP<const CrsMatrix>& A)
{
  Impl& m = *impl_;
  DMUMPS_STRUC_C& id = m.id;
  SC_THROW_IF(!m.initialized, sc::core::InternalError, "MUMPS: factorisation before analysis");
  // Same graph as at the analysis (DirectSolver checked it): refresh the values only.
  const auto lclA = A->getLocalMatrixHost();
  SC_THROW_IF(static_cast<size_t>(lclA.values.extent(0)) <
                  (m.entryPosition.empty() ? 0 : m.entryPosition.back() + 1),
              sc::core::InternalError, "MUMPS: the matrix has fewer entries than at the analysis");
  for (size_t e = 0; e < m.entryPosition.size(); ++e)
    m.values[e] = lclA.values(m.entryPosition[e]);
  id.a_loc = m.values.data();

  for (int attempt = 0;; ++attempt) {
    m.call(2);
    const int code = id.INFOG(1);
    if ((code == -8 || code == -9) && attempt < options_.workspaceRetries) {
      // Pivoting needed more workspace than the analysis estimated (common for indefinite
      // saddle-point matrices with delayed pivots): retry with twice the relaxation.
      id.ICNTL(14) = std::max(20, 2 * id.ICNTL(14));
      ++stats_.workspaceRetries;
      continue;
    }
    checkInfo(id, 2);
    break;
  }
  // INFOG(29): entries in the factors (negative: in millions).
  const long long nf = id.INFOG(29);
  stats_.factorNonzeros = nf >= 0 ? nf : -nf * 1000000LL;
  stats_.mumpsFactorMemoryMaxMB = id.INFOG(18);
  stats_.mumpsFactorMemoryTotalMB = id.INFOG(19);
  stats_.mumpsMemoryMaxMB = id.INFOG(21);
  stats_.mumpsMemoryTotalMB = id.INFOG(22);
  stats_.mumpsScaling = id.INFOG(33);
}

void MumpsSolver::doSolve(const MultiVector& b, MultiVector& x)
{
  Impl& m = *impl_;
  DMUMPS_STRUC_C& id = m.id;
  const size_t nrhs = b.getNumVectors();
  MultiVector onHost(m.hostMap, nrhs, false);
  onHost.doImport(b, *m.gather, Tpetra::INSERT);
  if (m.rank == 0) {
    m.rhs.resize(static_cast<size_t>(m.n) * nrhs);
    onHost.get1dCopy(Teuchos::ArrayView<double>(m.rhs), static_cast<size_t>(m.n));
    id.rhs = m.rhs.data();
    id.lrhs = m.n;
  }
  id.nrhs = static_cast<MUMPS_INT>(nrhs);
  m.call(3);
  checkInfo(id, 3);
  if (m.rank == 0) {
    for (size_t j = 0; j < nrhs; ++j) {
      auto col = onHost.getDataNonConst(j);
      for (MUMPS_INT i = 0; i < m.n; ++i)
        col[i] = m.rhs[j * static_cast<size_t>(m.n) + i];
    }
  }
  x.doImport(onHost, *m.scatter, Tpetra::INSERT);
}

}  // namespace sc::solvers
