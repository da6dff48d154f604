#pragma once
// Errors of StressContact. Every error says what is wrong, where it came from (file, line, key
// path, element, rank) and what would be valid. The driver catches them,
// prints a framed message and exits non-zero.

#include <sstream>
#include <stdexcept>
#include <string>

namespace sc::core {

/// Base class: message already complete (what, where, what would be valid).
class Error : public std::runtime_error {
public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

/// Bad user input: XML deck, parameter value, mesh file, command line.
class InputError : public Error {
public:
  using Error::Error;
};

/// A nonlinear or linear solver did not converge within its limits.
class ConvergenceError : public Error {
public:
  using Error::Error;
};

/// Something that should hold by construction does not (a bug, not bad input).
class InternalError : public Error {
public:
  using Error::Error;
};

}  // namespace sc::core

/// Throw ExceptionType with a message built from stream insertions when cond holds:
///   SC_THROW_IF(E <= 0, sc::core::InputError, "Material/Young modulus = " << E << " must be > 0");
#define SC_THROW_IF(cond, ExceptionType, streamMessage)                                            \
  do {                                                                                             \
    if (cond) {                                                                                    \
      std::ostringstream sc_throw_os_;                                                             \
      sc_throw_os_ << streamMessage;                                                               \
      throw ExceptionType(sc_throw_os_.str());                                                     \
    }                                                                                              \
  } while (false)
