#pragma once
// Strict parsing of parameter values written as text: XML decks and `--set` overrides.
// Teuchos' own conversions read "abc" as 0, "20600abc" as 20600 and an int "1.5" as 1;
// readParameterFile() checks every value of a deck with checkValueText() before Teuchos converts
// it, and applyOverride() parses with the functions below, so both paths accept the same texts.
//
// Accepted: the whole text (blanks around it allowed) is one number of the type: double (finite,
// e.g. "2.06e4"), int (decimal, within int's range), bool ("true"/"false", also "yes"/"no"/"1"/"0"
// in any case, as Teuchos reads them), arrays in braces ("{0, -0.01}", "{}").

#include <string>

#include <Teuchos_Array.hpp>

namespace sc::core {

/// "" when `text` is a valid value of the XML/--set type `type` ("double", "int", "bool",
/// "Array(double)", "Array(int)"; other types are not checked), else why not, e.g. "not a
/// number", "trailing characters 'abc'", "out of the range of int [...]", "entry 2 'abc': not a
/// number".
std::string checkValueText(const std::string& type, const std::string& text);

double parseDouble(const std::string& text);  ///< throws InputError with checkValueText's reason
int parseInt(const std::string& text);        ///< throws InputError with checkValueText's reason
Teuchos::Array<double> parseDoubleArray(const std::string& text);  ///< throws InputError

}  // namespace sc::core
