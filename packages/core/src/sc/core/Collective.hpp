#pragma once
// StressContact's collective operations over a Teuchos communicator: sums, maxima and minima
// over ranks, broadcasts of numbers, strings and vectors from one rank, and the agreement on
// errors (docs/architecture.md "Collective operations"). Every function here is collective: all
// ranks of the communicator call it, in the same order.
//
// Errors: work done by one rank on behalf of all (rank 0 runs Gmsh, writes summary.json) or a
// check done on each rank before a collective call must end the same way on every rank. If only
// the failing rank threw, the others would wait forever in the next collective operation:
// runOnRoot and throwIfAnyRankFailed make every rank throw the same error, and ErrorAgreement
// lets the program's ranks agree on the exit status of an error (or find that it is one rank's).
//
// Teuchos_CommHelpers stays in Collective.cpp: callers include only Teuchos_Comm.hpp.

#include <Teuchos_Comm.hpp>

#include <mpi.h>

#include <functional>
#include <string>
#include <vector>

namespace sc::core {

using Comm = Teuchos::Comm<int>;

// ----------------------------------------------------------------------------- reductions
/// The sum, maximum or minimum of `local` over all ranks, on every rank.
int sumOverRanks(const Comm& comm, int local);
long long sumOverRanks(const Comm& comm, long long local);
double sumOverRanks(const Comm& comm, double local);
int maxOverRanks(const Comm& comm, int local);
long long maxOverRanks(const Comm& comm, long long local);
double maxOverRanks(const Comm& comm, double local);
int minOverRanks(const Comm& comm, int local);
long long minOverRanks(const Comm& comm, long long local);
double minOverRanks(const Comm& comm, double local);

/// Element-wise over ranks: `global[i]` = the sum (maximum, minimum) of every rank's `local[i]`,
/// i < n. `local` and `global` must not overlap.
void sumOverRanks(const Comm& comm, int n, const int* local, int* global);
void sumOverRanks(const Comm& comm, int n, const long long* local, long long* global);
void sumOverRanks(const Comm& comm, int n, const double* local, double* global);
void maxOverRanks(const Comm& comm, int n, const double* local, double* global);
void minOverRanks(const Comm& comm, int n, const double* local, double* global);

/// Element-wise sum of equally long vectors over ranks.
std::vector<double> sumOverRanks(const Comm& comm, const std::vector<double>& local);
std::vector<long long> sumOverRanks(const Comm& comm, const std::vector<long long>& local);

/// Every rank's `mine` concatenated in rank order, on every rank (the lengths may differ).
std::vector<double> gatherAllConcatenated(const Comm& comm, const std::vector<double>& mine);

// ----------------------------------------------------------------------------- broadcasts
/// Rank `root`'s value replaces every other rank's (vectors and strings take its length).
void broadcast(const Comm& comm, int root, int& value);
void broadcast(const Comm& comm, int root, long& value);
void broadcast(const Comm& comm, int root, long long& value);
void broadcast(const Comm& comm, int root, double& value);
void broadcast(const Comm& comm, int root, std::string& value);
void broadcast(const Comm& comm, int root, std::vector<int>& value);
void broadcast(const Comm& comm, int root, std::vector<double>& value);

// ----------------------------------------------------------------------------- errors
/// The MPI communicator behind `comm` (Teuchos::MpiComm), or MPI_COMM_SELF for a SerialComm.
MPI_Comm rawMpiComm(const Comm& comm);

/// Run `task` on rank 0 only. If it throws, every rank throws an exception of the same sc::core
/// type (Error, InputError, InternalError, ConvergenceError; anything else becomes Error) with
/// the same message.
void runOnRoot(const Comm& comm, const std::function<void()>& task);

/// Every rank passes an empty string if its local check passed, or an error message. If any
/// rank failed, every rank throws InputError (InternalError if `internal`) carrying the message
/// of the lowest failing rank, prefixed with that rank when there are several ranks.
void throwIfAnyRankFailed(const Comm& comm, const std::string& localError, bool internal = false);

/// The ranks' agreement on the exit status of an error that reached main(): normally every rank
/// fails together (input is the same everywhere and the library's checks are collective), and
/// then rank 0 alone reports it; an error of one rank only must abort the job rather than hang
/// it. Uses a communicator of its own, so that the agreement never mixes with a collective
/// operation of the run that the other ranks may still be in.
class ErrorAgreement {
public:
  explicit ErrorAgreement(const Comm& comm);
  ~ErrorAgreement();
  ErrorAgreement(const ErrorAgreement&) = delete;
  ErrorAgreement& operator=(const ErrorAgreement&) = delete;

  /// Called by every rank that failed, with its exit status `code` (> 0). Returns the largest
  /// status of all ranks if every rank reports within `seconds`; otherwise 0 (the error is this
  /// rank's alone). After a 0 the agreement stays open: the destructor waits for the other
  /// ranks, so a caller that goes on must make them report (the program aborts instead).
  int agree(int code, double seconds);

private:
  MPI_Comm comm_ = MPI_COMM_NULL;
  MPI_Request pending_ = MPI_REQUEST_NULL;
  int send_ = 0, worst_ = 0;
};

}  // namespace sc::core
