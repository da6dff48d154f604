// libFuzzer target: a deck formula (Boundary Conditions/<part>/Expression, Body Force/Expression)
// compiled by sc::core::Expression (muparser) and evaluated at a few points, as the application
// does. The input is the formula text (its first line, at most 1000 characters).
// sc::core::InputError is expected (syntax errors, unknown names, non-finite values); anything
// else is a finding. muparser is not instrumented: coverage feedback comes from our code only.
#include <cstddef>
#include <cstdint>
#include <string>

#include <sc/core/Error.hpp>
#include <sc/core/Expression.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  std::string formula(reinterpret_cast<const char*>(data), size < 1000 ? size : 1000);
  formula = formula.substr(0, formula.find('\n'));
  try {
    const sc::core::Expression e(formula, "Body Force/Expression");
    const double points[3][3] = {{0.0, 0.0, 0.0}, {0.5, -1.0, 2.0}, {1e3, 1e-3, -7.0}};
    for (const auto& x : points)
      (void)e(x, 3);
  } catch (const sc::core::InputError&) {
  }
  return 0;
}
