#include "sc/core/Parameters.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

#include <Teuchos_XMLParameterListHelpers.hpp>

#include "sc/core/Error.hpp"

namespace sc::core {
namespace {

std::string joinPath(const std::string& path, const std::string& name)
{
  return path.empty() ? name : path + "/" + name;
}

std::string quotedList(const std::vector<std::string>& items)
{
  std::ostringstream os;
  for (std::size_t i = 0; i < items.size(); ++i)
    os << (i ? ", " : "") << "'" << items[i] << "'";
  return os.str();
}

std::vector<std::string> keysOf(const Teuchos::ParameterList& list)
{
  std::vector<std::string> keys;
  for (auto it = list.begin(); it != list.end(); ++it)
    keys.push_back(list.name(it));
  return keys;
}

// Human-readable type name of an entry ("double", "int", "bool", "string", "Array(double)",
// "sublist").
std::string typeOf(const Teuchos::ParameterEntry& e)
{
  if (e.isList())
    return "sublist";
  const std::string t = e.getAny(false).typeName();
  if (t == "std::string" || t.find("basic_string") != std::string::npos)
    return "string";
  return t;
}

std::string valueOf(const Teuchos::ParameterEntry& e)
{
  std::ostringstream os;
  if (e.isList())
    os << "(sublist)";
  else
    e.getAny(false).print(os);
  return os.str();
}

std::string formatReal(double v)
{
  if (v >= kInfinity)
    return "inf";
  if (v <= -kInfinity)
    return "-inf";
  std::ostringstream os;
  os << std::setprecision(12) << v;
  return os.str();
}

bool isTemplateList(const Teuchos::ParameterList& valid)
{
  return valid.numParams() == 1 && valid.isSublist(kTemplateSublist);
}

// Levenshtein distance, case-insensitive (keys are short; quadratic is fine).
std::size_t editDistance(const std::string& a, const std::string& b)
{
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j)
    prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                        std::tolower(static_cast<unsigned char>(b[j - 1]));
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (same ? 0 : 1)});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

void checkList(Teuchos::ParameterList& user, const Teuchos::ParameterList& valid,
               const std::string& path, const std::string& origin);

void checkEntry(Teuchos::ParameterList& user, const std::string& name,
                const Teuchos::ParameterEntry& validEntry, const std::string& path,
                const std::string& origin)
{
  const std::string keyPath = joinPath(path, name);
  Teuchos::ParameterEntry& entry = user.getEntry(name);
  if (validEntry.isList() != entry.isList()) {
    SC_THROW_IF(true, InputError,
                origin << ": '" << keyPath << "' must be a "
                       << (validEntry.isList() ? "sublist (<ParameterList name=\"" + name + "\">)"
                                               : "parameter of type " + typeOf(validEntry))
                       << ", but the deck gives a " << (entry.isList() ? "sublist" : "parameter")
                       << ".");
  }
  if (entry.isList()) {
    checkList(user.sublist(name), Teuchos::getValue<Teuchos::ParameterList>(validEntry), keyPath,
              origin);
    return;
  }
  std::string got = typeOf(entry), want = typeOf(validEntry);
  if (got != want) {
    if (got == "int" && want == "double") {
      // type="int" value="1" for a real-valued key: take it as 1.0 rather than fail.
      const double v = Teuchos::getValue<int>(entry);
      user.set(name, v);
    } else {
      SC_THROW_IF(true, InputError,
                  origin << ": '" << keyPath << "' has type " << got << " (value " << valueOf(entry)
                         << "), but it must be of type " << want << ", e.g. <Parameter name=\""
                         << name << "\" type=\"" << want << "\" value=\"" << valueOf(validEntry)
                         << "\"/>.");
    }
  }
  if (auto v = validEntry.validator(); !v.is_null()) {
    try {
      v->validate(user.getEntry(name), name, path.empty() ? "(top level)" : path);
    } catch (const InputError& e) {
      throw InputError(origin + ": " + e.what());
    } catch (const std::exception& e) {
      throw InputError(origin + ": '" + keyPath + "' = " + valueOf(user.getEntry(name)) +
                       " is not valid: " + e.what());
    }
    user.getEntry(name).setValidator(v);
  }
  if (user.getEntry(name).docString().empty())
    user.getEntry(name).setDocString(validEntry.docString());
}

void fillDefaults(Teuchos::ParameterList& user, const Teuchos::ParameterList& valid)
{
  for (auto it = valid.begin(); it != valid.end(); ++it) {
    const std::string& name = valid.name(it);
    const Teuchos::ParameterEntry& ve = valid.entry(it);
    if (name == kTemplateSublist)
      continue;
    if (ve.isList()) {
      fillDefaults(user.sublist(name, false, ve.docString()),
                   Teuchos::getValue<Teuchos::ParameterList>(ve));
    } else if (!user.isParameter(name)) {
      user.setEntry(name, ve);
    }
  }
}

void checkList(Teuchos::ParameterList& user, const Teuchos::ParameterList& valid,
               const std::string& path, const std::string& origin)
{
  if (isTemplateList(valid)) {
    const Teuchos::ParameterList& tmpl = valid.sublist(kTemplateSublist);
    for (const std::string& name : keysOf(user)) {
      SC_THROW_IF(!user.isSublist(name), InputError,
                  origin << ": '" << joinPath(path, name) << "' must be a sublist (one per name, "
                         << "with the keys " << quotedList(keysOf(tmpl)) << ").");
      checkList(user.sublist(name), tmpl, joinPath(path, name), origin);
      fillDefaults(user.sublist(name), tmpl);
    }
    return;
  }
  for (const std::string& name : keysOf(user)) {
    if (!valid.isParameter(name)) {
      const std::vector<std::string> validKeys = keysOf(valid);
      const std::string suggestion = closestMatch(name, validKeys);
      SC_THROW_IF(true, InputError,
                  origin << ": unknown key '" << joinPath(path, name) << "'"
                         << (suggestion.empty() ? "" : " (did you mean '" + suggestion + "'?)")
                         << ". Valid keys in '" << (path.empty() ? "(top level)" : path)
                         << "': " << quotedList(validKeys)
                         << ". 'stresscontact --print-parameters' lists them with their documentation.");
    }
    checkEntry(user, name, valid.getEntry(name), path, origin);
  }
}

template <typename T>
const T* anyPtr(const Teuchos::ParameterEntry& e)
{
  return e.getAny(false).type() == typeid(T) ? &Teuchos::any_cast<T>(e.getAny(false)) : nullptr;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
RealRangeValidator::RealRangeValidator(double lower, bool lowerOpen, double upper, bool upperOpen)
  : lower_(lower), upper_(upper), lowerOpen_(lowerOpen), upperOpen_(upperOpen)
{
}

std::string RealRangeValidator::rangeString() const
{
  std::ostringstream os;
  os << (lowerOpen_ || lower_ <= -kInfinity ? "(" : "[") << formatReal(lower_) << ", "
     << formatReal(upper_) << (upperOpen_ || upper_ >= kInfinity ? ")" : "]");
  return os.str();
}

void RealRangeValidator::printDoc(const std::string& doc, std::ostream& out) const
{
  out << "# " << doc << "\n# Valid range: " << rangeString() << "\n";
}

void RealRangeValidator::validate(const Teuchos::ParameterEntry& entry,
                                  const std::string& paramName,
                                  const std::string& sublistName) const
{
  const double* v = anyPtr<double>(entry);
  SC_THROW_IF(!v, InputError,
              "'" << sublistName << "/" << paramName << "' must be a double, got "
                  << valueOf(entry));
  const bool ok = std::isfinite(*v) && (lowerOpen_ ? *v > lower_ : *v >= lower_) &&
                  (upperOpen_ ? *v < upper_ : *v <= upper_);
  SC_THROW_IF(!ok, InputError,
              "'" << sublistName << "/" << paramName << "' = " << formatReal(*v)
                  << " is out of range: valid values are " << rangeString() << ".");
}

IntRangeValidator::IntRangeValidator(int lower, int upper) : lower_(lower), upper_(upper) {}

void IntRangeValidator::printDoc(const std::string& doc, std::ostream& out) const
{
  out << "# " << doc << "\n# Valid range: [" << lower_ << ", " << upper_ << "]\n";
}

void IntRangeValidator::validate(const Teuchos::ParameterEntry& entry,
                                 const std::string& paramName,
                                 const std::string& sublistName) const
{
  const int* v = anyPtr<int>(entry);
  SC_THROW_IF(!v, InputError,
              "'" << sublistName << "/" << paramName << "' must be an int, got "
                  << valueOf(entry));
  SC_THROW_IF(*v < lower_ || *v > upper_, InputError,
              "'" << sublistName << "/" << paramName << "' = " << *v
                  << " is out of range: valid values are integers in [" << lower_ << ", " << upper_
                  << "].");
}

ChoiceValidator::ChoiceValidator(std::vector<std::string> choices) : choices_(std::move(choices))
{
}

void ChoiceValidator::printDoc(const std::string& doc, std::ostream& out) const
{
  out << "# " << doc << "\n# Valid values: " << quotedList(choices_) << "\n";
}

Teuchos::ParameterEntryValidator::ValidStringsList ChoiceValidator::validStringValues() const
{
  return Teuchos::rcp(new Teuchos::Array<std::string>(choices_.begin(), choices_.end()));
}

void ChoiceValidator::validate(const Teuchos::ParameterEntry& entry, const std::string& paramName,
                               const std::string& sublistName) const
{
  const std::string* v = anyPtr<std::string>(entry);
  SC_THROW_IF(!v, InputError,
              "'" << sublistName << "/" << paramName << "' must be a string, got "
                  << valueOf(entry));
  if (std::find(choices_.begin(), choices_.end(), *v) == choices_.end()) {
    const std::string suggestion = closestMatch(*v, choices_);
    SC_THROW_IF(true, InputError,
                "'" << sublistName << "/" << paramName << "' = '" << *v << "' is not valid"
                    << (suggestion.empty() ? "" : " (did you mean '" + suggestion + "'?)")
                    << ". Valid values: " << quotedList(choices_) << ".");
  }
}

RealArrayValidator::RealArrayValidator(std::vector<int> allowedSizes)
  : sizes_(std::move(allowedSizes))
{
}

void RealArrayValidator::printDoc(const std::string& doc, std::ostream& out) const
{
  out << "# " << doc << "\n# Array(double) of length";
  for (std::size_t i = 0; i < sizes_.size(); ++i)
    out << (i ? " or " : " ") << sizes_[i];
  out << "\n";
}

void RealArrayValidator::validate(const Teuchos::ParameterEntry& entry,
                                  const std::string& paramName,
                                  const std::string& sublistName) const
{
  const auto* v = anyPtr<Teuchos::Array<double>>(entry);
  SC_THROW_IF(!v, InputError,
              "'" << sublistName << "/" << paramName << "' must be an Array(double) such as "
                  << "\"{0, -0.01}\", got " << valueOf(entry));
  const int n = static_cast<int>(v->size());
  if (!sizes_.empty() && std::find(sizes_.begin(), sizes_.end(), n) == sizes_.end()) {
    std::ostringstream os;
    for (std::size_t i = 0; i < sizes_.size(); ++i)
      os << (i ? " or " : "") << sizes_[i];
    SC_THROW_IF(true, InputError,
                "'" << sublistName << "/" << paramName << "' = " << valueOf(entry) << " has "
                    << n << " entries; it must have " << os.str() << ".");
  }
  for (double x : *v)
    SC_THROW_IF(!std::isfinite(x), InputError,
                "'" << sublistName << "/" << paramName << "' = " << valueOf(entry)
                    << " contains a non-finite number.");
}

// ---------------------------------------------------------------------------------------------
void declareReal(Teuchos::ParameterList& list, const std::string& name, double defaultValue,
                 const std::string& doc, double lower, bool lowerOpen, double upper,
                 bool upperOpen)
{
  list.set(name, defaultValue, doc,
           Teuchos::rcp(new RealRangeValidator(lower, lowerOpen, upper, upperOpen)));
}

void declareInt(Teuchos::ParameterList& list, const std::string& name, int defaultValue,
                const std::string& doc, int lower, int upper)
{
  list.set(name, defaultValue, doc, Teuchos::rcp(new IntRangeValidator(lower, upper)));
}

void declareChoice(Teuchos::ParameterList& list, const std::string& name,
                   const std::string& defaultValue, const std::vector<std::string>& choices,
                   const std::string& doc)
{
  list.set(name, defaultValue, doc, Teuchos::rcp(new ChoiceValidator(choices)));
}

void declareBool(Teuchos::ParameterList& list, const std::string& name, bool defaultValue,
                 const std::string& doc)
{
  list.set(name, defaultValue, doc);
}

void declareString(Teuchos::ParameterList& list, const std::string& name,
                   const std::string& defaultValue, const std::string& doc)
{
  list.set(name, defaultValue, doc);
}

void declareRealArray(Teuchos::ParameterList& list, const std::string& name,
                      const Teuchos::Array<double>& defaultValue, const std::string& doc,
                      std::vector<int> allowedSizes)
{
  list.set(name, defaultValue, doc,
           Teuchos::rcp(new RealArrayValidator(std::move(allowedSizes))));
}

void validateParameters(Teuchos::ParameterList& user, const Teuchos::ParameterList& valid,
                        const std::string& origin)
{
  checkList(user, valid, "", origin);
  fillDefaults(user, valid);
}

Teuchos::RCP<Teuchos::ParameterList> readParameterFile(const std::string& path)
{
  std::ifstream in(path);
  SC_THROW_IF(!in, InputError,
              "cannot open the input deck '" << path << "' (no such file or not readable).");
  try {
    return Teuchos::getParametersFromXmlFile(path);
  } catch (const std::exception& e) {
    SC_THROW_IF(true, InputError,
                "the input deck '" << path << "' is not a valid Teuchos XML parameter list: "
                                   << e.what());
  }
  return Teuchos::null;
}

void applyOverride(Teuchos::ParameterList& user, const Teuchos::ParameterList& valid,
                   const std::string& assignment)
{
  const auto eq = assignment.find('=');
  SC_THROW_IF(eq == std::string::npos || eq == 0, InputError,
              "--set expects Path/To/Key=value, got '" << assignment << "'.");
  const std::string path = assignment.substr(0, eq), text = assignment.substr(eq + 1);
  std::vector<std::string> parts;
  std::stringstream ss(path);
  for (std::string p; std::getline(ss, p, '/');)
    parts.push_back(p);
  const Teuchos::ParameterList* v = &valid;
  Teuchos::ParameterList* u = &user;
  std::string where;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    const Teuchos::ParameterList* next = nullptr;
    if (isTemplateList(*v))
      next = &v->sublist(kTemplateSublist);
    else if (v->isSublist(parts[i]))
      next = &v->sublist(parts[i]);
    SC_THROW_IF(!next, InputError,
                "--set " << assignment << ": '" << joinPath(where, parts[i])
                         << "' is not a sublist. Valid keys in '" << (where.empty() ? "(top level)" : where)
                         << "': " << quotedList(keysOf(*v)) << ".");
    v = next;
    u = &u->sublist(parts[i]);
    where = joinPath(where, parts[i]);
  }
  const std::string& key = parts.back();
  SC_THROW_IF(!v->isParameter(key) || v->isSublist(key), InputError,
              "--set " << assignment << ": unknown key '" << path << "'. Valid keys in '"
                       << (where.empty() ? "(top level)" : where) << "': " << quotedList(keysOf(*v))
                       << ".");
  const Teuchos::ParameterEntry& ve = v->getEntry(key);
  const std::string type = typeOf(ve);
  try {
    std::size_t used = 0;
    if (type == "double") {
      const double x = std::stod(text, &used);
      SC_THROW_IF(used != text.size(), InputError, "trailing characters");
      u->set(key, x);
    } else if (type == "int") {
      const int x = std::stoi(text, &used);
      SC_THROW_IF(used != text.size(), InputError, "trailing characters");
      u->set(key, x);
    } else if (type == "bool") {
      SC_THROW_IF(text != "true" && text != "false", InputError, "expected true or false");
      u->set(key, text == "true");
    } else if (type == "string") {
      u->set(key, text);
    } else if (type == "Array(double)") {
      u->set(key, Teuchos::fromStringToArray<double>(text));
    } else {
      SC_THROW_IF(true, InputError, "type " << type << " cannot be set from the command line");
    }
  } catch (const std::exception& e) {
    SC_THROW_IF(true, InputError,
                "--set " << assignment << ": '" << text << "' is not a valid " << type
                         << " for '" << path << "' (" << e.what() << ").");
  }
}

std::string closestMatch(const std::string& word, const std::vector<std::string>& candidates)
{
  std::string best;
  std::size_t bestDist = std::numeric_limits<std::size_t>::max();
  for (const auto& c : candidates) {
    const std::size_t d = editDistance(word, c);
    if (d < bestDist) {
      bestDist = d;
      best = c;
    }
  }
  // Close means: at most a third of the word differs (typos, not different words).
  return (bestDist <= std::max<std::size_t>(1, word.size() / 3)) ? best : std::string();
}

namespace {
void printDocRec(const Teuchos::ParameterList& valid, const std::string& path, std::ostream& out)
{
  for (auto it = valid.begin(); it != valid.end(); ++it) {
    const std::string& name = valid.name(it);
    const Teuchos::ParameterEntry& e = valid.entry(it);
    const std::string keyPath = joinPath(path, name == kTemplateSublist ? "<name>" : name);
    if (e.isList()) {
      out << "\n[" << keyPath << "]";
      if (!e.docString().empty())
        out << "  " << e.docString();
      out << "\n";
      printDocRec(Teuchos::getValue<Teuchos::ParameterList>(e), keyPath, out);
      continue;
    }
    out << "  " << keyPath << " : " << typeOf(e) << " = " << valueOf(e) << "\n";
    out << "      " << e.docString() << "\n";
    if (auto v = e.validator(); !v.is_null()) {
      std::ostringstream doc;
      v->printDoc("", doc);
      std::string line;
      std::istringstream lines(doc.str());
      while (std::getline(lines, line))
        if (line.size() > 2 && line != "# ")
          out << "      " << line.substr(2) << "\n";
    }
  }
}
}  // namespace

void printParameterDocumentation(const Teuchos::ParameterList& valid, std::ostream& out)
{
  printDocRec(valid, "", out);
}

}  // namespace sc::core
