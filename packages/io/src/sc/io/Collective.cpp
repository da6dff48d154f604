#include <sc/io/Collective.hpp>

#include <sc/core/Error.hpp>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultMpiComm.hpp>

#include <exception>
#include <vector>

namespace sc::io {

namespace {

enum ErrorKind : int { kNone = 0, kError, kInput, kInternal, kConvergence };

// Send rank `root`'s string to all ranks.
std::string broadcastString(const Teuchos::Comm<int>& comm, int root, const std::string& s)
{
  int length = static_cast<int>(s.size());
  Teuchos::broadcast<int, int>(comm, root, &length);
  std::vector<char> buffer(s.begin(), s.end());
  buffer.resize(static_cast<std::size_t>(length));
  if (length > 0)
    Teuchos::broadcast<int, char>(comm, root, length, buffer.data());
  return std::string(buffer.begin(), buffer.end());
}

[[noreturn]] void throwKind(int kind, const std::string& message)
{
  switch (kind) {
    case kInput: throw sc::core::InputError(message);
    case kInternal: throw sc::core::InternalError(message);
    case kConvergence: throw sc::core::ConvergenceError(message);
    default: throw sc::core::Error(message);
  }
}

}  // namespace

MPI_Comm rawMpiComm(const Teuchos::Comm<int>& comm)
{
  // A SerialComm has no MPI communicator behind it: that process works alone.
  if (const auto* mpi = dynamic_cast<const Teuchos::MpiComm<int>*>(&comm))
    return (*mpi->getRawMpiComm())();
  return MPI_COMM_SELF;
}

void runOnRoot(const Teuchos::Comm<int>& comm, const std::function<void()>& task)
{
  int kind = kNone;
  std::string message;
  if (comm.getRank() == 0) {
    // Most specific types first: they all derive from sc::core::Error.
    try {
      task();
    } catch (const sc::core::InputError& e) {
      kind = kInput, message = e.what();
    } catch (const sc::core::InternalError& e) {
      kind = kInternal, message = e.what();
    } catch (const sc::core::ConvergenceError& e) {
      kind = kConvergence, message = e.what();
    } catch (const std::exception& e) {
      kind = kError, message = e.what();
    }
  }
  Teuchos::broadcast<int, int>(comm, 0, &kind);
  if (kind == kNone)
    return;
  message = broadcastString(comm, 0, message);
  throwKind(kind, message);
}

void throwIfAnyRankFailed(const Teuchos::Comm<int>& comm, const std::string& localError,
                          bool internal)
{
  const int size = comm.getSize();
  const int mine = localError.empty() ? size : comm.getRank();
  int firstFailing = size;
  Teuchos::reduceAll<int, int>(comm, Teuchos::REDUCE_MIN, mine, Teuchos::outArg(firstFailing));
  if (firstFailing == size)
    return;
  const std::string message = broadcastString(comm, firstFailing, localError);
  const std::string full =
      size > 1 ? "rank " + std::to_string(firstFailing) + ": " + message : message;
  throwKind(internal ? kInternal : kInput, full);
}

}  // namespace sc::io
