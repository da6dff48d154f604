#include "sc/core/Parameters.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <limits>
#include <regex>
#include <sstream>

#include <Teuchos_FileInputSource.hpp>
#include <Teuchos_StringInputSource.hpp>
#include <Teuchos_XMLObject.hpp>
#include <Teuchos_XMLParameterListReader.hpp>

#include "sc/core/Error.hpp"
#include "sc/core/FloatingPointTraps.hpp"
#include "sc/core/ValueText.hpp"

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
  if (e.isList()) return "sublist";
  const std::string t = e.getAny(false).typeName();
  if (t == "std::string" || t.find("basic_string") != std::string::npos) return "string";
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
  if (v >= kInfinity) return "inf";
  if (v <= -kInfinity) return "-inf";
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
    if (name == kTemplateSublist) continue;
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
      SC_THROW_IF(
          true, InputError,
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

// "2 or 3": the lengths an array key may have.
std::string lengthsText(const std::vector<int>& sizes)
{
  std::ostringstream os;
  for (std::size_t i = 0; i < sizes.size(); ++i)
    os << (i ? " or " : "") << sizes[i];
  return os.str();
}

// An array key's length against the allowed ones (none: any length).
void checkArrayLength(const std::string& key, const Teuchos::ParameterEntry& entry, int n,
                      const std::vector<int>& sizes)
{
  SC_THROW_IF(!sizes.empty() && std::find(sizes.begin(), sizes.end(), n) == sizes.end(), InputError,
              "'" << key << "' = " << valueOf(entry) << " has " << n << " entries; it must have "
                  << lengthsText(sizes) << ".");
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

void IntRangeValidator::validate(const Teuchos::ParameterEntry& entry, const std::string& paramName,
                                 const std::string& sublistName) const
{
  const int* v = anyPtr<int>(entry);
  SC_THROW_IF(!v, InputError,
              "'" << sublistName << "/" << paramName << "' must be an int, got " << valueOf(entry));
  SC_THROW_IF(*v < lower_ || *v > upper_, InputError,
              "'" << sublistName << "/" << paramName << "' = " << *v
                  << " is out of range: valid values are integers in [" << lower_ << ", " << upper_
                  << "].");
}

ChoiceValidator::ChoiceValidator(std::vector<std::string> choices) : choices_(std::move(choices)) {}

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
  out << "# " << doc << "\n# Array(double) of "
      << (sizes_.empty() ? "any length" : "length " + lengthsText(sizes_)) << "\n";
}

void RealArrayValidator::validate(const Teuchos::ParameterEntry& entry,
                                  const std::string& paramName,
                                  const std::string& sublistName) const
{
  const auto* v = anyPtr<Teuchos::Array<double>>(entry);
  SC_THROW_IF(!v, InputError,
              "'" << sublistName << "/" << paramName << "' must be an Array(double) such as "
                  << "\"{0, -0.01}\", got " << valueOf(entry));
  checkArrayLength(sublistName + "/" + paramName, entry, static_cast<int>(v->size()), sizes_);
  for (double x : *v)
    SC_THROW_IF(!std::isfinite(x), InputError,
                "'" << sublistName << "/" << paramName << "' = " << valueOf(entry)
                    << " contains a non-finite number.");
}

ChoiceArrayValidator::ChoiceArrayValidator(std::vector<std::string> choices,
                                           std::vector<int> allowedSizes)
    : choices_(std::move(choices)), sizes_(std::move(allowedSizes))
{
}

void ChoiceArrayValidator::printDoc(const std::string& doc, std::ostream& out) const
{
  out << "# " << doc << "\n# Array(string) of " << quotedList(choices_) << ", of length"
      << (sizes_.empty() ? "" : " " + lengthsText(sizes_)) << "\n";
}

void ChoiceArrayValidator::validate(const Teuchos::ParameterEntry& entry,
                                    const std::string& paramName,
                                    const std::string& sublistName) const
{
  const std::string key = sublistName + "/" + paramName;
  const auto* v = anyPtr<Teuchos::Array<std::string>>(entry);
  SC_THROW_IF(!v, InputError,
              "'" << key << "' must be an Array(string) such as \"{" << choices_.front() << ", "
                  << choices_.back() << "}\", got " << valueOf(entry));
  checkArrayLength(key, entry, static_cast<int>(v->size()), sizes_);
  const auto entries = trimmedEntries(*v);
  for (std::size_t i = 0; i < entries.size(); ++i)
    if (std::find(choices_.begin(), choices_.end(), entries[i]) == choices_.end()) {
      const std::string suggestion = closestMatch(entries[i], choices_);
      SC_THROW_IF(true, InputError,
                  "'" << key << "' entry " << i + 1 << " = '" << entries[i] << "' is not valid"
                      << (suggestion.empty() ? "" : " (did you mean '" + suggestion + "'?)")
                      << ". Valid values: " << quotedList(choices_) << ".");
    }
}

// ---------------------------------------------------------------------------------------------
void declareReal(Teuchos::ParameterList& list, const std::string& name, double defaultValue,
                 const std::string& doc, double lower, bool lowerOpen, double upper, bool upperOpen)
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
  list.set(name, defaultValue, doc, Teuchos::rcp(new RealArrayValidator(std::move(allowedSizes))));
}

void declareChoiceArray(Teuchos::ParameterList& list, const std::string& name,
                        const std::vector<std::string>& choices, const std::string& doc,
                        std::vector<int> allowedSizes)
{
  list.set(name, Teuchos::Array<std::string>(), doc,
           Teuchos::rcp(new ChoiceArrayValidator(choices, std::move(allowedSizes))));
}

void validateParameters(Teuchos::ParameterList& user, const Teuchos::ParameterList& valid,
                        const std::string& origin)
{
  checkList(user, valid, "", origin);
  fillDefaults(user, valid);
}

namespace {

std::string trimmed(const std::string& text)
{
  const auto first = text.find_first_not_of(" \t\n\r");
  if (first == std::string::npos) return "";
  const auto last = text.find_last_not_of(" \t\n\r");
  return text.substr(first, last - first + 1);
}

std::string checkDoubleText(const std::string& raw, double* out)
{
  const std::string t = trimmed(raw);
  if (t.empty()) return "empty value";
  errno = 0;
  char* end = nullptr;
  double v = 0;
  {
    // glibc's strtod raises FE_OVERFLOW for "1e999" (and FE_INVALID for nothing); the result is
    // checked below, so the flag is not a fault here.
    FloatingPointTrapsSuspended strtodMayOverflow;
    v = std::strtod(t.c_str(), &end);
  }
  if (end == t.c_str()) return "not a number";
  if (*end != '\0') return "trailing characters '" + std::string(end) + "'";
  if (!std::isfinite(v))
    return errno == ERANGE ? "out of the range of double" : "not a finite number";
  if (out) *out = v;
  return "";
}

std::string checkIntText(const std::string& raw, int* out)
{
  const std::string t = trimmed(raw);
  if (t.empty()) return "empty value";
  errno = 0;
  char* end = nullptr;
  const long long v = std::strtoll(t.c_str(), &end, 10);
  if (end == t.c_str()) return "not an integer";
  if (*end != '\0') return "trailing characters '" + std::string(end) + "'";
  if (errno == ERANGE || v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max())
    return "out of the range of int [" + std::to_string(std::numeric_limits<int>::min()) + ", " +
           std::to_string(std::numeric_limits<int>::max()) + "]";
  if (out) *out = static_cast<int>(v);
  return "";
}

std::string checkBoolText(const std::string& raw)
{
  std::string t = trimmed(raw);
  std::transform(t.begin(), t.end(), t.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (const char* ok : {"true", "false", "yes", "no", "1", "0"})
    if (t == ok) return "";
  return "expected true or false";
}

// "{a, b, c}": each element checked by `element`; "{}" is the empty array.
template <typename F>
std::string checkArrayText(const std::string& raw, F element)
{
  const std::string t = trimmed(raw);
  if (t.size() < 2 || t.front() != '{' || t.back() != '}')
    return "an array is written in braces, e.g. {0, -0.01}";
  const std::string inner = t.substr(1, t.size() - 2);
  if (trimmed(inner).empty()) return "";
  std::size_t start = 0, index = 1;
  while (true) {
    const auto comma = inner.find(',', start);
    const std::string item =
        inner.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const std::string why = element(item);
    if (!why.empty()) return "entry " + std::to_string(index) + " '" + trimmed(item) + "': " + why;
    if (comma == std::string::npos) return "";
    start = comma + 1;
    ++index;
  }
}

std::string indefinite(const std::string& type)
{
  return (type == "int" || type.rfind("Array", 0) == 0 ? "an " : "a ") + type;
}

// Teuchos messages carry "file:line:", "Throw number = N" and "Throw test that evaluated to
// true: ..." lines meant for developers; keep only the sentences for the user.
std::string withoutTeuchosNoise(const std::string& message)
{
  std::istringstream in(message);
  std::ostringstream out;
  bool first = true;
  for (std::string line; std::getline(in, line);) {
    const std::string t = trimmed(line);
    if (t.empty() || t.rfind("Throw number", 0) == 0 ||
        t.rfind("Throw test that evaluated", 0) == 0)
      continue;
    // "/usr/include/trilinos/Teuchos_X.cpp:123:" alone or as the prefix of the sentence
    static const std::regex source(R"(^\S+\.(cpp|hpp|h):[0-9]+:\s*)");
    const std::string sentence = std::regex_replace(t, source, "");
    if (sentence.empty()) continue;
    out << (first ? "" : " ") << sentence;
    first = false;
  }
  return out.str();
}

// How deeply the elements of an XML text nest (a self-closing element counts as one level).
// Comments, CDATA sections, processing instructions, declarations and quoted attribute values
// are skipped; malformed text is left to Teuchos' parser, which reports it. Iterative, so that
// any depth can be measured without recursion.
int xmlNestingDepth(const std::string& text)
{
  int depth = 0, deepest = 0;
  const std::size_t n = text.size();
  auto skipPast = [&](std::size_t from, const char* end) {
    const std::size_t at = text.find(end, from);
    return at == std::string::npos ? n : at + std::char_traits<char>::length(end);
  };
  for (std::size_t i = text.find('<'); i < n; i = text.find('<', i)) {
    if (text.compare(i, 4, "<!--") == 0) {
      i = skipPast(i + 4, "-->");
      continue;
    }
    if (text.compare(i, 9, "<![CDATA[") == 0) {
      i = skipPast(i + 9, "]]>");
      continue;
    }
    if (text.compare(i, 2, "<?") == 0) {
      i = skipPast(i + 2, "?>");
      continue;
    }
    if (text.compare(i, 2, "<!") == 0) {
      i = skipPast(i + 2, ">");
      continue;
    }
    std::size_t j = i + 1;
    for (char quote = 0; j < n; ++j) {
      const char c = text[j];
      if (quote != 0) {
        if (c == quote) quote = 0;
      } else if (c == '"' || c == '\'') {
        quote = c;
      } else if (c == '>') {
        break;
      }
    }
    if (j >= n) break;
    if (text[i + 1] == '/')
      depth = std::max(0, depth - 1);
    else if (text[j - 1] == '/')
      deepest = std::max(deepest, depth + 1);
    else
      deepest = std::max(deepest, ++depth);
    i = j + 1;
  }
  return deepest;
}

// The raw XML of a deck: every number parsed strictly, no key twice in one list.
void checkXmlList(const Teuchos::XMLObject& list, const std::string& path, const std::string& file)
{
  std::vector<std::string> seen;
  for (int i = 0; i < list.numChildren(); ++i) {
    const Teuchos::XMLObject& child = list.getChild(i);
    const std::string& tag = child.getTag();
    if ((tag != "Parameter" && tag != "ParameterList") || !child.hasAttribute("name"))
      continue;  // Teuchos reports malformed entries itself
    const std::string name = child.getAttribute("name");
    const std::string keyPath = joinPath(path, name);
    SC_THROW_IF(std::find(seen.begin(), seen.end(), name) != seen.end(), InputError,
                "'" << file << "': '" << keyPath << "' is given twice in '"
                    << (path.empty() ? "(top level)" : path)
                    << "'; give each key once (one value would silently override the other).");
    seen.push_back(name);
    if (tag == "ParameterList") {
      checkXmlList(child, keyPath, file);
      continue;
    }
    if (!child.hasAttribute("type") || !child.hasAttribute("value")) continue;
    const std::string type = child.getAttribute("type"), text = child.getAttribute("value");
    const std::string why = checkValueText(type, text);
    SC_THROW_IF(!why.empty(), InputError,
                "'" << file << "': '" << keyPath << "' = '" << text << "' is not "
                    << indefinite(type) << " (" << why << ").");
  }
}

}  // namespace

std::vector<std::string> trimmedEntries(const Teuchos::Array<std::string>& entries)
{
  std::vector<std::string> out;
  for (const auto& e : entries)
    out.push_back(trimmed(e));
  return out;
}

std::string checkValueText(const std::string& type, const std::string& text)
{
  if (type == "double") return checkDoubleText(text, nullptr);
  if (type == "int") return checkIntText(text, nullptr);
  if (type == "bool") return checkBoolText(text);
  if (type == "Array(double)")
    return checkArrayText(text, [](const std::string& x) { return checkDoubleText(x, nullptr); });
  if (type == "Array(int)")
    return checkArrayText(text, [](const std::string& x) { return checkIntText(x, nullptr); });
  return "";
}

double parseDouble(const std::string& text)
{
  double v = 0;
  const std::string why = checkDoubleText(text, &v);
  SC_THROW_IF(!why.empty(), InputError, why);
  return v;
}

int parseInt(const std::string& text)
{
  int v = 0;
  const std::string why = checkIntText(text, &v);
  SC_THROW_IF(!why.empty(), InputError, why);
  return v;
}

Teuchos::Array<double> parseDoubleArray(const std::string& text)
{
  const std::string why = checkValueText("Array(double)", text);
  SC_THROW_IF(!why.empty(), InputError, why);
  Teuchos::Array<double> values;
  const std::string t = trimmed(text);
  std::stringstream inner(t.substr(1, t.size() - 2));
  if (!trimmed(inner.str()).empty())
    for (std::string item; std::getline(inner, item, ',');)
      values.push_back(parseDouble(item));
  return values;
}

// "{a, b}" as the XML reader reads an Array(string) (Teuchos splits at commas; formulas are
// compiled, and their errors reported, when the deck is read).
Teuchos::Array<std::string> parseStringArray(const std::string& text)
{
  const std::string why = checkArrayText(text, [](const std::string&) { return std::string(); });
  SC_THROW_IF(!why.empty(), InputError, why);
  return Teuchos::fromStringToArray<std::string>(trimmed(text));
}

// Besides Teuchos' checks: the deck is no directory, every number is parsed strictly
// (checkValueText) and no key is given twice in one list.
Teuchos::RCP<Teuchos::ParameterList> readParameterFile(const std::string& path)
{
  std::error_code ec;
  SC_THROW_IF(std::filesystem::is_directory(path, ec), InputError,
              "the input deck '" << path << "' is a directory, not an XML file.");
  std::ifstream in(path);
  SC_THROW_IF(!in, InputError,
              "cannot open the input deck '" << path << "' (no such file or not readable).");
  // Teuchos converts the XML tree to a parameter list recursively, and so does checkXmlList: a
  // deck nested some 10,000 levels deep overflowed the stack. The depth is therefore measured on
  // the text, before Teuchos builds anything from it.
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // A UTF-8 byte-order mark (some Windows editors write one) is not XML to Teuchos' reader, whose
  // message ("character data outside of an enclosing tag") did not mention it: it is skipped. A
  // UTF-16 deck is refused by name.
  if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) text.erase(0, 3);
  SC_THROW_IF(text.compare(0, 2, "\xFF\xFE") == 0 || text.compare(0, 2, "\xFE\xFF") == 0,
              InputError,
              "the input deck '" << path << "' is UTF-16 text (it starts with a UTF-16 byte-order "
                                 << "mark); save it as UTF-8.");
  {
    const int depth = xmlNestingDepth(text);
    SC_THROW_IF(depth > kMaxDeckNestingDepth, InputError,
                "the input deck '" << path << "' nests its XML elements " << depth
                                   << " levels deep; at most " << kMaxDeckNestingDepth
                                   << " levels are accepted (a deck's <ParameterList> holds "
                                   << "sublists a few levels deep: the shipped decks use 4).");
  }
  Teuchos::XMLObject xml;
  try {
    xml = Teuchos::StringInputSource(text).getObject();  // the text checked above
  } catch (const std::exception& e) {
    SC_THROW_IF(true, InputError,
                "the input deck '" << path << "' is not a valid Teuchos XML parameter list: "
                                   << withoutTeuchosNoise(e.what()));
  }
  SC_THROW_IF(xml.isEmpty() || xml.getTag() != "ParameterList", InputError,
              "the input deck '" << path << "' is not a valid Teuchos XML parameter list: "
                                 << "its root element must be <ParameterList>.");
  checkXmlList(xml, "", path);
  try {
    Teuchos::XMLParameterListReader reader;
    reader.setAllowsDuplicateSublists(false);
    return Teuchos::rcp(new Teuchos::ParameterList(reader.toParameterList(xml)));
  } catch (const std::exception& e) {
    SC_THROW_IF(true, InputError,
                "the input deck '" << path << "' is not a valid Teuchos XML parameter list: "
                                   << withoutTeuchosNoise(e.what()));
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
                         << "' is not a sublist. Valid keys in '"
                         << (where.empty() ? "(top level)" : where)
                         << "': " << quotedList(keysOf(*v)) << ".");
    v = next;
    u = &u->sublist(parts[i]);
    where = joinPath(where, parts[i]);
  }
  const std::string& key = parts.back();
  if (v->isSublist(key) || isTemplateList(*v)) {
    const Teuchos::ParameterList& sub =
        isTemplateList(*v) ? v->sublist(kTemplateSublist) : v->sublist(key);
    const Teuchos::ParameterList& keys = isTemplateList(sub) ? sub.sublist(kTemplateSublist) : sub;
    SC_THROW_IF(true, InputError,
                "--set " << assignment << ": '" << path << "' is a sublist, not a key; set one of "
                         << "its keys (--set \"" << path << (isTemplateList(sub) ? "/<name>" : "")
                         << "/Key=value\"): " << quotedList(keysOf(keys)) << ".");
  }
  SC_THROW_IF(!v->isParameter(key), InputError,
              "--set " << assignment << ": unknown key '" << path << "'. Valid keys in '"
                       << (where.empty() ? "(top level)" : where) << "': " << quotedList(keysOf(*v))
                       << ".");
  const Teuchos::ParameterEntry& ve = v->getEntry(key);
  const std::string type = typeOf(ve);
  try {
    if (type == "double") {
      u->set(key, parseDouble(text));
    } else if (type == "int") {
      u->set(key, parseInt(text));
    } else if (type == "bool") {
      SC_THROW_IF(text != "true" && text != "false", InputError, "expected true or false");
      u->set(key, text == "true");
    } else if (type == "string") {
      u->set(key, text);
    } else if (type == "Array(double)") {
      u->set(key, parseDoubleArray(text));
    } else if (type == "Array(string)") {
      u->set(key, parseStringArray(text));
    } else {
      SC_THROW_IF(true, InputError, "type " << type << " cannot be set from the command line");
    }
  } catch (const std::exception& e) {
    SC_THROW_IF(true, InputError,
                "--set " << assignment << ": '" << text << "' is not a valid " << type << " for '"
                         << path << "' (" << e.what() << ").");
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
      if (!e.docString().empty()) out << "  " << e.docString();
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
        if (line.size() > 2 && line != "# ") out << "      " << line.substr(2) << "\n";
    }
  }
}
}  // namespace

void printParameterDocumentation(const Teuchos::ParameterList& valid, std::ostream& out)
{
  printDocRec(valid, "", out);
}

}  // namespace sc::core
