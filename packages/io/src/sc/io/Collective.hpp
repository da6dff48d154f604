#pragma once
// Error handling for work that is done by one rank on behalf of all (rank 0 writes summary.json,
// renames a file) or checked on every rank before a collective call. If only the failing rank
// threw, the others would wait forever in the next collective operation; these helpers make every
// rank throw the same error instead.

#include <Teuchos_Comm.hpp>

#include <mpi.h>

#include <functional>
#include <string>

namespace sc::io {

/// The MPI communicator behind \p comm (Teuchos::MpiComm), or MPI_COMM_SELF for a SerialComm.
MPI_Comm rawMpiComm(const Teuchos::Comm<int>& comm);

/// Run \p task on rank 0 only. Collective: if it throws, every rank throws an exception of the
/// same sc::core type (Error, InputError, InternalError, ConvergenceError; anything else becomes
/// sc::core::Error) with the same message.
void runOnRoot(const Teuchos::Comm<int>& comm, const std::function<void()>& task);

/// Collective: every rank passes an empty string if its local check passed, or an error message.
/// If any rank failed, every rank throws sc::core::InputError (or InternalError if
/// \p internal) carrying the message of the lowest failing rank, prefixed with that rank.
void throwIfAnyRankFailed(const Teuchos::Comm<int>& comm, const std::string& localError,
                          bool internal = false);

}  // namespace sc::io
