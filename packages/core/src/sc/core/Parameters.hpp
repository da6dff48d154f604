#pragma once
// Parameter-list conventions of StressContact (docs/output.md, docs/architecture.md "Parameters").
//
// Every component describes its sublist in a static getValidParameters(): each entry has a
// default, a doc string and, for ranges and choices, a validator. The driver merges those lists
// into one master list, checks a user's deck against it with validateParameters() (unknown keys,
// wrong types and bad values are InputErrors that name the key path, the value and what would be
// valid), and fills in the defaults.
//
// A sublist whose keys are user-chosen names (e.g. "Boundary Conditions/<boundary name>") is
// declared with a single template sublist named "<...>"; every user sublist in that place is
// checked against the template.

#include <string>
#include <vector>

#include <Teuchos_Array.hpp>
#include <Teuchos_ParameterEntryValidator.hpp>
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

namespace sc::core {

/// Real (double) value in an interval whose ends may be open, closed or infinite.
class RealRangeValidator : public Teuchos::ParameterEntryValidator {
public:
  RealRangeValidator(double lower, bool lowerOpen, double upper, bool upperOpen);
  const std::string getXMLTypeName() const override { return "sc::RealRangeValidator"; }
  void printDoc(const std::string& docString, std::ostream& out) const override;
  ValidStringsList validStringValues() const override { return Teuchos::null; }
  void validate(const Teuchos::ParameterEntry& entry, const std::string& paramName,
                const std::string& sublistName) const override;
  std::string rangeString() const;

private:
  double lower_, upper_;
  bool lowerOpen_, upperOpen_;
};

/// Integer value in a closed interval [lower, upper].
class IntRangeValidator : public Teuchos::ParameterEntryValidator {
public:
  IntRangeValidator(int lower, int upper);
  const std::string getXMLTypeName() const override { return "sc::IntRangeValidator"; }
  void printDoc(const std::string& docString, std::ostream& out) const override;
  ValidStringsList validStringValues() const override { return Teuchos::null; }
  void validate(const Teuchos::ParameterEntry& entry, const std::string& paramName,
                const std::string& sublistName) const override;

private:
  int lower_, upper_;
};

/// One of a fixed set of strings.
class ChoiceValidator : public Teuchos::ParameterEntryValidator {
public:
  explicit ChoiceValidator(std::vector<std::string> choices);
  const std::string getXMLTypeName() const override { return "sc::ChoiceValidator"; }
  void printDoc(const std::string& docString, std::ostream& out) const override;
  ValidStringsList validStringValues() const override;
  void validate(const Teuchos::ParameterEntry& entry, const std::string& paramName,
                const std::string& sublistName) const override;
  const std::vector<std::string>& choices() const { return choices_; }

private:
  std::vector<std::string> choices_;
};

/// Array(double) with a fixed set of allowed lengths (e.g. {2, 3} for a point in 2D or 3D).
class RealArrayValidator : public Teuchos::ParameterEntryValidator {
public:
  explicit RealArrayValidator(std::vector<int> allowedSizes);
  const std::string getXMLTypeName() const override { return "sc::RealArrayValidator"; }
  void printDoc(const std::string& docString, std::ostream& out) const override;
  ValidStringsList validStringValues() const override { return Teuchos::null; }
  void validate(const Teuchos::ParameterEntry& entry, const std::string& paramName,
                const std::string& sublistName) const override;

private:
  std::vector<int> sizes_;
};

/// Array(string) whose entries are each one of a fixed set of strings (surrounding blanks
/// ignored), with a fixed set of allowed lengths (e.g. one entry per space dimension).
class ChoiceArrayValidator : public Teuchos::ParameterEntryValidator {
public:
  ChoiceArrayValidator(std::vector<std::string> choices, std::vector<int> allowedSizes);
  const std::string getXMLTypeName() const override { return "sc::ChoiceArrayValidator"; }
  void printDoc(const std::string& docString, std::ostream& out) const override;
  ValidStringsList validStringValues() const override { return Teuchos::null; }
  void validate(const Teuchos::ParameterEntry& entry, const std::string& paramName,
                const std::string& sublistName) const override;

private:
  std::vector<std::string> choices_;
  std::vector<int> sizes_;
};

inline constexpr double kInfinity = 1e308;
/// Name of the template sublist of a sublist with user-chosen keys.
inline const std::string kTemplateSublist = "<...>";

// Declaring entries (each with a default and a doc string).
void declareReal(Teuchos::ParameterList& list, const std::string& name, double defaultValue,
                 const std::string& doc, double lower = -kInfinity, bool lowerOpen = false,
                 double upper = kInfinity, bool upperOpen = false);
void declareInt(Teuchos::ParameterList& list, const std::string& name, int defaultValue,
                const std::string& doc, int lower, int upper);
void declareChoice(Teuchos::ParameterList& list, const std::string& name,
                   const std::string& defaultValue, const std::vector<std::string>& choices,
                   const std::string& doc);
void declareBool(Teuchos::ParameterList& list, const std::string& name, bool defaultValue,
                 const std::string& doc);
void declareString(Teuchos::ParameterList& list, const std::string& name,
                   const std::string& defaultValue, const std::string& doc);
void declareRealArray(Teuchos::ParameterList& list, const std::string& name,
                      const Teuchos::Array<double>& defaultValue, const std::string& doc,
                      std::vector<int> allowedSizes);
/// Declare an Array(string) of choices (default: empty, i.e. not given).
void declareChoiceArray(Teuchos::ParameterList& list, const std::string& name,
                        const std::vector<std::string>& choices, const std::string& doc,
                        std::vector<int> allowedSizes);
/// The entries of an Array(string) without surrounding blanks ("{a, b}" is read as "a", " b").
std::vector<std::string> trimmedEntries(const Teuchos::Array<std::string>& entries);

/// Check `user` against `valid` (recursively), then fill in defaults. Throws InputError naming
/// `origin` (e.g. the deck's file name), the key path, the value and what would be valid. int
/// values given for double keys are converted (an XML author writing type="int" for 1 means 1.0).
void validateParameters(Teuchos::ParameterList& user, const Teuchos::ParameterList& valid,
                        const std::string& origin);

/// The deepest nesting of XML elements a deck may have (readParameterFile). Far above any real
/// deck (the shipped ones nest 4 levels: deck, sublist, sublist, parameter) and far below the
/// depth at which Teuchos' recursive XML-to-list conversion overflows the stack (about 9,900
/// levels with the default 8 MiB stack).
inline constexpr int kMaxDeckNestingDepth = 64;

/// Read a Teuchos XML parameter file; a missing or malformed file, or one nested deeper than
/// kMaxDeckNestingDepth, is an InputError naming it.
Teuchos::RCP<Teuchos::ParameterList> readParameterFile(const std::string& path);

/// Apply a command-line override "Path/To/Key=value": the type comes from the valid list (double,
/// int, bool, string, Array(double) as "{1, 2}"). Unknown paths are InputErrors.
void applyOverride(Teuchos::ParameterList& user, const Teuchos::ParameterList& valid,
                   const std::string& assignment);

/// The closest of `candidates` to `word` by edit distance, or "" if none is close.
std::string closestMatch(const std::string& word, const std::vector<std::string>& candidates);

/// Print a valid list as documentation: every key with type, default, doc and valid values.
void printParameterDocumentation(const Teuchos::ParameterList& valid, std::ostream& out);

}  // namespace sc::core
