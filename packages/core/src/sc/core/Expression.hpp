#pragma once
// Formulas of the coordinates in a deck (docs/user-guide.md "Loads and supports"): a load or a
// support may be given as one formula per component instead of constant values, e.g. the
// body force {0, -9.81*(2 - y)}. Evaluated with muparser (https://beltoforion.de/en/muparser/)
// at the quadrature points where the data enters the system.
//
// Variables: x, y, z (z = 0 in 2D) and t, the time of the current load step (docs/theory.md
// §"Load steps"; t = 1 in a run without load steps); constant: pi. muparser's functions (sin, cos,
// tan, asin, acos, atan, sinh, cosh, tanh, sqrt, exp, ln, log10, abs, sign, rint, ...), the
// operators
// + - * / ^, comparisons and the conditional a ? b : c. A deck's Array(string) is split at
// commas by Teuchos, so a formula cannot contain a comma (write min(a, b) as a < b ? a : b).
//
// muparser stays out of this header: the packages that evaluate formulas link sc_core only.
#include <memory>
#include <string>
#include <vector>

#include <Teuchos_Array.hpp>
#include <Teuchos_ParameterEntryValidator.hpp>
#include <Teuchos_ParameterList.hpp>

namespace sc::core {

class Expression {
public:
  /// Compiles `formula`. `key` is the deck key that holds it, as the messages name it (e.g.
  /// "Boundary Conditions/Top/Expression" entry 2). A syntax error or a name that is not a
  /// variable, constant or function is an InputError naming the key, the formula and muparser's
  /// message with the position.
  Expression(const std::string& formula, const std::string& key);

  /// The value at the point x (dim coordinates; the missing ones are 0). A result that is not
  /// finite (a division by zero, sqrt of a negative number, ...) is an InputError naming the key,
  /// the formula and the point: the deck's data must be defined wherever the body is.
  double operator()(const double* x, int dim) const;

  /// The value at x without the finiteness check: NaN where muparser cannot evaluate the
  /// formula, and ±inf or NaN as the formula gives them. For callers that probe points near the
  /// body (a search that backs off where the formula is not finite) and report themselves.
  double unchecked(const double* x, int dim) const;

  /// Whether the formula uses the variable `name` (x, y, z or t), as muparser reports it.
  bool uses(const std::string& name) const;

  const std::string& formula() const;
  const std::string& key() const;

  /// The time t that every formula sees: the current load step's (1 without load steps). Set by
  /// the application before a step's assembly (one time per process).
  static void setLoadTime(double t);
  static double loadTime();

private:
  struct Impl;
  // Shared by copies: an Expression is compiled once and copied into the boundary conditions.
  // Evaluation writes the point into the parser's variables, so an Expression and its copies
  // must not be evaluated concurrently (the code is MPI-parallel, one thread per rank).
  std::shared_ptr<Impl> impl_;
};

/// One Expression per entry of `formulas`; entry i (1-based) is named "'<key>' entry i".
std::vector<Expression> compileExpressions(const Teuchos::Array<std::string>& formulas,
                                           const std::string& key);

/// Array(string) of formulas with a fixed set of allowed lengths. validate() compiles every
/// formula, so that --check reports a malformed formula before any work.
class ExpressionArrayValidator : public Teuchos::ParameterEntryValidator {
public:
  explicit ExpressionArrayValidator(std::vector<int> allowedSizes);
  const std::string getXMLTypeName() const override { return "sc::ExpressionArrayValidator"; }
  void printDoc(const std::string& docString, std::ostream& out) const override;
  ValidStringsList validStringValues() const override { return Teuchos::null; }
  void validate(const Teuchos::ParameterEntry& entry, const std::string& paramName,
                const std::string& sublistName) const override;

private:
  std::vector<int> sizes_;
};

/// Declare an Array(string) of formulas (default: empty, i.e. not given).
void declareExpressionArray(Teuchos::ParameterList& list, const std::string& name,
                            const std::string& doc, std::vector<int> allowedSizes);

}  // namespace sc::core
