#include "sc/core/Collective.hpp"

#include <chrono>
#include <exception>
#include <thread>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultMpiComm.hpp>

#include "sc/core/Error.hpp"

namespace sc::core {
namespace {

template <class T>
T reduce(const Comm& comm, Teuchos::EReductionType op, T local)
{
  T global{};
  Teuchos::reduceAll<int, T>(comm, op, local, Teuchos::outArg(global));
  return global;
}

template <class T>
void reduce(const Comm& comm, Teuchos::EReductionType op, int n, const T* local, T* global)
{
  if (n > 0) Teuchos::reduceAll<int, T>(comm, op, n, local, global);
}

template <class T>
void broadcastScalar(const Comm& comm, int root, T& value)
{
  Teuchos::broadcast<int, T>(comm, root, &value);
}

template <class T>
void broadcastVector(const Comm& comm, int root, std::vector<T>& v)
{
  int n = static_cast<int>(v.size());
  Teuchos::broadcast<int, int>(comm, root, &n);
  v.resize(static_cast<std::size_t>(n));
  if (n > 0) Teuchos::broadcast<int, T>(comm, root, n, v.data());
}

enum ErrorKind : int { kNone = 0, kError, kInput, kInternal, kConvergence };

[[noreturn]] void throwKind(int kind, const std::string& message)
{
  switch (kind) {
  case kInput: throw InputError(message);
  case kInternal: throw InternalError(message);
  case kConvergence: throw ConvergenceError(message);
  default: throw Error(message);
  }
}

}  // namespace

int sumOverRanks(const Comm& c, int v) { return reduce(c, Teuchos::REDUCE_SUM, v); }
long long sumOverRanks(const Comm& c, long long v) { return reduce(c, Teuchos::REDUCE_SUM, v); }
double sumOverRanks(const Comm& c, double v) { return reduce(c, Teuchos::REDUCE_SUM, v); }
int maxOverRanks(const Comm& c, int v) { return reduce(c, Teuchos::REDUCE_MAX, v); }
long long maxOverRanks(const Comm& c, long long v) { return reduce(c, Teuchos::REDUCE_MAX, v); }
double maxOverRanks(const Comm& c, double v) { return reduce(c, Teuchos::REDUCE_MAX, v); }
int minOverRanks(const Comm& c, int v) { return reduce(c, Teuchos::REDUCE_MIN, v); }
long long minOverRanks(const Comm& c, long long v) { return reduce(c, Teuchos::REDUCE_MIN, v); }
double minOverRanks(const Comm& c, double v) { return reduce(c, Teuchos::REDUCE_MIN, v); }

void sumOverRanks(const Comm& c, int n, const int* l, int* g)
{
  reduce(c, Teuchos::REDUCE_SUM, n, l, g);
}
void sumOverRanks(const Comm& c, int n, const long long* l, long long* g)
{
  reduce(c, Teuchos::REDUCE_SUM, n, l, g);
}
void sumOverRanks(const Comm& c, int n, const double* l, double* g)
{
  reduce(c, Teuchos::REDUCE_SUM, n, l, g);
}
void maxOverRanks(const Comm& c, int n, const double* l, double* g)
{
  reduce(c, Teuchos::REDUCE_MAX, n, l, g);
}
void minOverRanks(const Comm& c, int n, const double* l, double* g)
{
  reduce(c, Teuchos::REDUCE_MIN, n, l, g);
}

std::vector<double> sumOverRanks(const Comm& comm, const std::vector<double>& local)
{
  std::vector<double> global(local.size(), 0.0);
  sumOverRanks(comm, static_cast<int>(local.size()), local.data(), global.data());
  return global;
}

std::vector<long long> sumOverRanks(const Comm& comm, const std::vector<long long>& local)
{
  std::vector<long long> global(local.size(), 0);
  sumOverRanks(comm, static_cast<int>(local.size()), local.data(), global.data());
  return global;
}

std::vector<double> gatherAllConcatenated(const Comm& comm, const std::vector<double>& mine)
{
  int n = static_cast<int>(mine.size());
  const int total = sumOverRanks(comm, n);
  std::vector<int> sizes(static_cast<std::size_t>(comm.getSize()));
  Teuchos::gatherAll<int, int>(comm, 1, &n, comm.getSize(), sizes.data());
  // Through a zero-padded sum: simple, and the vectors gathered this way (contact points) are
  // small. A sum also turns −0 into +0, which the stored contact files rely on being stable.
  std::vector<double> padded(static_cast<std::size_t>(total), 0.0);
  int offset = 0;
  for (int r = 0; r < comm.getRank(); ++r)
    offset += sizes[static_cast<std::size_t>(r)];
  std::copy(mine.begin(), mine.end(), padded.begin() + offset);
  return sumOverRanks(comm, padded);
}

void broadcast(const Comm& c, int root, int& v) { broadcastScalar(c, root, v); }
void broadcast(const Comm& c, int root, long& v) { broadcastScalar(c, root, v); }
void broadcast(const Comm& c, int root, long long& v) { broadcastScalar(c, root, v); }
void broadcast(const Comm& c, int root, double& v) { broadcastScalar(c, root, v); }
void broadcast(const Comm& c, int root, std::vector<int>& v) { broadcastVector(c, root, v); }
void broadcast(const Comm& c, int root, std::vector<double>& v) { broadcastVector(c, root, v); }

void broadcast(const Comm& comm, int root, std::string& value)
{
  std::vector<char> chars(value.begin(), value.end());
  broadcastVector(comm, root, chars);
  value.assign(chars.begin(), chars.end());
}

MPI_Comm rawMpiComm(const Comm& comm)
{
  // A SerialComm has no MPI communicator behind it: that process works alone.
  if (const auto* mpi = dynamic_cast<const Teuchos::MpiComm<int>*>(&comm))
    return (*mpi->getRawMpiComm())();
  return MPI_COMM_SELF;
}

void runOnRoot(const Comm& comm, const std::function<void()>& task)
{
  int kind = kNone;
  std::string message;
  if (comm.getRank() == 0) {
    // Most specific types first: they all derive from Error.
    try {
      task();
    } catch (const InputError& e) {
      kind = kInput, message = e.what();
    } catch (const InternalError& e) {
      kind = kInternal, message = e.what();
    } catch (const ConvergenceError& e) {
      kind = kConvergence, message = e.what();
    } catch (const std::exception& e) {
      kind = kError, message = e.what();
    }
  }
  broadcast(comm, 0, kind);
  if (kind == kNone) return;
  broadcast(comm, 0, message);
  throwKind(kind, message);
}

void throwIfAnyRankFailed(const Comm& comm, const std::string& localError, bool internal)
{
  const int size = comm.getSize();
  const int firstFailing = minOverRanks(comm, localError.empty() ? size : comm.getRank());
  if (firstFailing == size) return;
  std::string message = localError;
  broadcast(comm, firstFailing, message);
  throwKind(internal ? kInternal : kInput,
            size > 1 ? "rank " + std::to_string(firstFailing) + ": " + message : message);
}

ErrorAgreement::ErrorAgreement(const Comm& comm) { MPI_Comm_dup(rawMpiComm(comm), &comm_); }

ErrorAgreement::~ErrorAgreement()
{
  if (pending_ != MPI_REQUEST_NULL) MPI_Wait(&pending_, MPI_STATUS_IGNORE);
  MPI_Comm_free(&comm_);
}

int ErrorAgreement::agree(int code, double seconds)
{
  send_ = code;
  MPI_Iallreduce(&send_, &worst_, 1, MPI_INT, MPI_MAX, comm_, &pending_);
  const double start = MPI_Wtime();
  for (int done = 0;;) {
    MPI_Test(&pending_, &done, MPI_STATUS_IGNORE);
    if (done) return worst_;
    if (MPI_Wtime() - start > seconds) return 0;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
}

}  // namespace sc::core
