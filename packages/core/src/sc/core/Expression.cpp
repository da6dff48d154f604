#include "sc/core/Expression.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <vector>

#include <muParser.h>

#include "sc/core/Error.hpp"
#include "sc/core/FloatingPointTraps.hpp"

namespace sc::core {
namespace {

const char* const kWhatIsValid =
    "variables x, y, z (z = 0 in 2D) and t (the load step's time), the constant pi, functions such "
    "as sin, cos, tan, sqrt, "
    "exp, ln, log10, abs, sign, operators + - * / ^, comparisons and a ? b : c; no commas";

bool isIdentifier(const std::string& token)
{
  return !token.empty() &&
         (std::isalpha(static_cast<unsigned char>(token[0])) || token[0] == '_') &&
         std::all_of(token.begin(), token.end(), [](char c) {
           return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
         });
}

std::string pointText(const double* x, int dim)
{
  std::ostringstream os;
  os << std::setprecision(10) << "(";
  for (int i = 0; i < dim; ++i)
    os << (i ? ", " : "") << x[i];
  os << ")";
  return os.str();
}

}  // namespace

namespace {
double g_loadTime = 1.0;  // Expression::setLoadTime
}  // namespace

void Expression::setLoadTime(double t) { g_loadTime = t; }
double Expression::loadTime() { return g_loadTime; }

struct Expression::Impl {
  std::string formula, key;
  double x = 0.0, y = 0.0, z = 0.0, t = 1.0;  // the parser reads the point and time from here
  mu::Parser parser;
};

Expression::Expression(const std::string& formula, const std::string& key)
    : impl_(std::make_shared<Impl>())
{
  Impl& I = *impl_;
  I.formula = formula;
  I.key = key;
  try {
    // Only pi: muparser's own constants (_pi, _e) are not part of the documented syntax.
    I.parser.ClearConst();
    I.parser.DefineConst("pi", M_PI);
    I.parser.DefineVar("x", &I.x);
    I.parser.DefineVar("y", &I.y);
    I.parser.DefineVar("z", &I.z);
    I.parser.DefineVar("t", &I.t);
    I.parser.SetExpr(formula);
    // muparser parses on the first evaluation: evaluate once (at the origin, where the result
    // may be anything; finiteness is checked where the formula is used) to report syntax errors.
    FloatingPointTrapsSuspended userFormula;
    I.parser.Eval();
  } catch (const mu::Parser::exception_type& e) {
    std::ostringstream hint;
    // muparser reports a missing ')' without a position: name the '(' that is not closed (the
    // innermost one; positions count from 0, as in muparser's other messages).
    if (e.GetCode() == mu::ecMISSING_PARENS) {
      std::vector<std::size_t> open;
      for (std::size_t i = 0; i < formula.size(); ++i) {
        if (formula[i] == '(')
          open.push_back(i);
        else if (formula[i] == ')' && !open.empty())
          open.pop_back();
      }
      if (!open.empty()) hint << " at position " << open.back() << ": the '(' there is not closed";
    }
    if (e.GetCode() == mu::ecUNASSIGNABLE_TOKEN && isIdentifier(e.GetToken()))
      hint << " ('" << e.GetToken() << "' is not a variable, constant or function)";
    // An unbalanced parenthesis is most often a comma inside a formula, at which the deck's
    // Array(string) was split.
    if (std::count(formula.begin(), formula.end(), '(') !=
        std::count(formula.begin(), formula.end(), ')'))
      hint << " (unbalanced parentheses: a formula cannot contain a comma, the array is split at "
           << "commas; write min(a, b) as a < b ? a : b)";
    SC_THROW_IF(true, InputError,
                key << " = '" << formula << "' is not a valid formula: " << e.GetMsg() << hint.str()
                    << ". Valid: " << kWhatIsValid << ".");
  }
}

double Expression::operator()(const double* x, int dim) const
{
  Impl& I = *impl_;
  I.x = dim > 0 ? x[0] : 0.0;
  I.y = dim > 1 ? x[1] : 0.0;
  I.z = dim > 2 ? x[2] : 0.0;
  I.t = g_loadTime;
  double v = 0.0;
  try {
    // A formula may divide by zero or take sqrt(-1) at some point: the result is checked below
    // and reported with the key, so the floating-point traps of the tests must not fire here.
    FloatingPointTrapsSuspended userFormula;
    v = I.parser.Eval();
  } catch (const mu::Parser::exception_type& e) {
    SC_THROW_IF(true, InputError,
                I.key << " = '" << I.formula << "' cannot be evaluated at " << pointText(x, dim)
                      << " (t = " << g_loadTime << ")"
                      << ": " << e.GetMsg() << ".");
  }
  SC_THROW_IF(!std::isfinite(v), InputError,
              I.key << " = '" << I.formula << "' evaluates to "
                    << (std::isnan(v) ? "NaN"
                        : v > 0       ? "inf"
                                      : "-inf")
                    << " at the point " << pointText(x, dim) << " (t = " << g_loadTime << ")"
                    << " of the body: give a formula that is finite wherever it is used.");
  return v;
}

double Expression::unchecked(const double* x, int dim) const
{
  Impl& I = *impl_;
  I.x = dim > 0 ? x[0] : 0.0;
  I.y = dim > 1 ? x[1] : 0.0;
  I.z = dim > 2 ? x[2] : 0.0;
  I.t = g_loadTime;
  try {
    FloatingPointTrapsSuspended userFormula;
    return I.parser.Eval();
  } catch (const mu::Parser::exception_type&) {
    return std::nan("");
  }
}

bool Expression::uses(const std::string& name) const
{
  // GetUsedVar parses the formula again in a mode that only collects names: the formula was
  // compiled by the constructor, so it cannot fail here.
  const auto used = impl_->parser.GetUsedVar();
  return used.find(name) != used.end();
}

const std::string& Expression::formula() const { return impl_->formula; }
const std::string& Expression::key() const { return impl_->key; }

std::vector<Expression> compileExpressions(const Teuchos::Array<std::string>& formulas,
                                           const std::string& key)
{
  std::vector<Expression> out;
  out.reserve(formulas.size());
  for (std::size_t i = 0; i < formulas.size(); ++i)
    out.emplace_back(formulas[i], "'" + key + "' entry " + std::to_string(i + 1));
  return out;
}

// ---------------------------------------------------------------------------------------------
ExpressionArrayValidator::ExpressionArrayValidator(std::vector<int> allowedSizes)
    : sizes_(std::move(allowedSizes))
{
}

void ExpressionArrayValidator::printDoc(const std::string& doc, std::ostream& out) const
{
  out << "# " << doc << "\n# Array(string) of formulas of x, y, z, t (muparser), of length";
  for (std::size_t i = 0; i < sizes_.size(); ++i)
    out << (i ? " or " : " ") << sizes_[i];
  out << "\n";
}

void ExpressionArrayValidator::validate(const Teuchos::ParameterEntry& entry,
                                        const std::string& paramName,
                                        const std::string& sublistName) const
{
  const std::string key = sublistName + "/" + paramName;
  const Teuchos::any& any = entry.getAny(false);
  SC_THROW_IF(any.type() != typeid(Teuchos::Array<std::string>), InputError,
              "'" << key
                  << "' must be an Array(string) of formulas such as \"{0, -9.81*(2 - y)}\".");
  const auto& formulas = Teuchos::any_cast<Teuchos::Array<std::string>>(any);
  const int n = static_cast<int>(formulas.size());
  if (!sizes_.empty() && std::find(sizes_.begin(), sizes_.end(), n) == sizes_.end()) {
    std::ostringstream os;
    for (std::size_t i = 0; i < sizes_.size(); ++i)
      os << (i ? " or " : "") << sizes_[i];
    SC_THROW_IF(true, InputError,
                "'" << key << "' = " << formulas << " has " << n << " formulas; it must have "
                    << os.str() << " (a formula cannot contain a comma: the array is split at "
                    << "commas; write min(a, b) as a < b ? a : b).");
  }
  compileExpressions(formulas, key);
}

void declareExpressionArray(Teuchos::ParameterList& list, const std::string& name,
                            const std::string& doc, std::vector<int> allowedSizes)
{
  list.set(name, Teuchos::Array<std::string>(), doc,
           Teuchos::rcp(new ExpressionArrayValidator(std::move(allowedSizes))));
}

}  // namespace sc::core
