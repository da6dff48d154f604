#pragma once
// The run's output directory: created (with parents) before anything is written, and probed for
// writability up front, so that a bad Output/Directory fails at start-up with a clear message
// instead of after hours of computing.

#include <Teuchos_Comm.hpp>

#include <string>

namespace sc::io {

/// Create \p directory (and its parents) if needed and check that a file can be created in it.
/// Throws sc::core::InputError naming the directory and the reason.
void createOutputDirectory(const std::string& directory);

/// Collective version: rank 0 creates and probes, every rank throws the same error on failure.
void createOutputDirectory(const std::string& directory, const Teuchos::Comm<int>& comm);

}  // namespace sc::io
