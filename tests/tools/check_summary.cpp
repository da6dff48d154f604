// check_summary: assert numbers in a run's summary.json (regression tests in tests/).
//
//   check_summary FILE CHECK...
//   CHECK is one of
//     near:/json/pointer=VALUE:RELTOL     |x − VALUE| ≤ RELTOL·|VALUE|
//     eq:/json/pointer=VALUE              x == VALUE (numbers, booleans or strings)
//     ge:/json/pointer=VALUE  le:/json/pointer=VALUE  gt:/json/pointer=VALUE (x > VALUE)
//     size:/json/pointer=N                array or object has N entries
//     exists:/json/pointer
//     rate:FIRST:LAST=MIN:MAX             the convergence rate of η in DOFs over cycles FIRST..LAST
//                                         (least-squares −slope of log eta/total against log
//                                         dofs/total) lies in [MIN, MAX]
//     decreasing:FIRST                    eta/total strictly decreases from cycle FIRST on
//   A pointer component or cycle index "-1" means the last element of an array.
//
//   check_summary FILE --expected EXPECTED.json [--np N]
//   reads the checks from a file of expected values (tests/expected/README.md): an object with a
//   "source" (where the numbers come from) and "checks", a list of objects, each one CHECK above:
//     {"check": "near", "pointer": P, "value": V, "tolerance": RELTOL}
//     {"check": "eq" | "ge" | "le" | "gt" | "size", "pointer": P, "value": V}
//     {"check": "exists", "pointer": P}
//     {"check": "rate", "cycles": [FIRST, LAST], "min": MIN, "max": MAX}
//     {"check": "decreasing", "from_cycle": FIRST}
//   each with an optional "source" of its own. A value "@NP@" stands for N (the run's ranks).
// Prints one line per check (measured value, expected, tolerance) and exits 1 if any failed.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

using nlohmann::json;

namespace {

const json* resolve(const json& root, const std::string& pointer)
{
  const json* node = &root;
  std::stringstream ss(pointer);
  std::string part;
  std::getline(ss, part, '/');  // leading empty component
  while (std::getline(ss, part, '/')) {
    if (node->is_array()) {
      long i = std::stol(part);
      if (i < 0) i += static_cast<long>(node->size());
      if (i < 0 || i >= static_cast<long>(node->size())) return nullptr;
      node = &(*node)[static_cast<std::size_t>(i)];
    } else if (node->is_object() && node->contains(part)) {
      node = &(*node)[part];
    } else {
      return nullptr;
    }
  }
  return node;
}

// The cycles FIRST..LAST (negative: from the end) as (log DOFs, log η) pairs.
std::vector<std::pair<double, double>> etaAgainstDofs(const json& root, long first, long last)
{
  std::vector<std::pair<double, double>> points;
  const json& cycles = root.at("cycles");
  const long n = static_cast<long>(cycles.size());
  if (first < 0) first += n;
  if (last < 0) last += n;
  for (long i = std::max(first, 0L); i <= std::min(last, n - 1); ++i)
    points.emplace_back(std::log(cycles[i].at("dofs").at("total").get<double>()),
                        std::log(cycles[i].at("eta").at("total").get<double>()));
  return points;
}

bool checkEta(const json& root, const std::string& kind, const std::string& rest,
              std::ostringstream& msg)
{
  if (kind == "decreasing") {
    const auto p = etaAgainstDofs(root, std::stol(rest), -1);
    bool ok = p.size() >= 2;
    for (std::size_t i = 1; i < p.size(); ++i)
      ok = ok && p[i].second < p[i - 1].second;
    msg << "eta/total over " << p.size() << " cycles from cycle " << rest
        << (ok ? " decreases" : " does not decrease");
    return ok;
  }
  // rate:FIRST:LAST=MIN:MAX
  const auto eq = rest.find('=');
  const std::string range = rest.substr(0, eq), bounds = rest.substr(eq + 1);
  const auto c1 = range.find(':'), c2 = bounds.find(':');
  const auto p =
      etaAgainstDofs(root, std::stol(range.substr(0, c1)), std::stol(range.substr(c1 + 1)));
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = static_cast<double>(p.size());
  for (const auto& [x, y] : p) {
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  const double rate = -(n * sxy - sx * sy) / (n * sxx - sx * sx);
  const double lo = std::stod(bounds.substr(0, c2)), hi = std::stod(bounds.substr(c2 + 1));
  msg << "rate of eta in DOFs over cycles " << range << " (" << p.size() << " cycles): " << rate
      << ", expected in [" << lo << ", " << hi << "]";
  return p.size() >= 2 && rate >= lo && rate <= hi;
}

// A number or other JSON value as check_summary reads it back (doubles in their shortest
// round-trip form, so that the file's value and the checked one are the same double).
std::string text(const json& v, const std::string& np)
{
  if (v.is_string()) return v.get<std::string>() == "@NP@" ? np : v.get<std::string>();
  return v.dump();
}

// The CHECK strings of an expected-values file (format above); throws on a malformed entry.
std::vector<std::string> checksOfFile(const std::string& path, const std::string& np)
{
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open '" + path + "'");
  const json file = json::parse(in);
  if (!file.is_object() || !file.contains("source") || !file.at("source").is_string() ||
      file.at("source").get<std::string>().empty() || !file.contains("checks") ||
      !file.at("checks").is_array() || file.at("checks").empty())
    throw std::runtime_error("'" + path + "' needs a non-empty \"source\" and \"checks\"");
  std::vector<std::string> checks;
  for (const json& c : file.at("checks")) {
    const std::string kind = c.at("check").get<std::string>();
    std::string check;
    if (kind == "rate")
      check = "rate:" + text(c.at("cycles").at(0), np) + ":" + text(c.at("cycles").at(1), np) +
              "=" + text(c.at("min"), np) + ":" + text(c.at("max"), np);
    else if (kind == "decreasing")
      check = "decreasing:" + text(c.at("from_cycle"), np);
    else if (kind == "exists")
      check = "exists:" + c.at("pointer").get<std::string>();
    else if (kind == "near")
      check = "near:" + c.at("pointer").get<std::string>() + "=" + text(c.at("value"), np) + ":" +
              text(c.at("tolerance"), np);
    else if (kind == "eq" || kind == "ge" || kind == "le" || kind == "gt" || kind == "size")
      check = kind + ":" + c.at("pointer").get<std::string>() + "=" + text(c.at("value"), np);
    else
      throw std::runtime_error("'" + path + "': unknown check '" + kind + "'");
    checks.push_back(check);
  }
  return checks;
}

}  // namespace

int main(int argc, char* argv[])
{
  if (argc < 3) {
    std::cerr
        << "usage: check_summary FILE CHECK... | check_summary FILE --expected FILE [--np N]\n";
    return 2;
  }
  std::vector<std::string> checks(argv + 2, argv + argc);
  if (checks[0] == "--expected") {
    if (checks.size() != 2 && !(checks.size() == 4 && checks[2] == "--np")) {
      std::cerr << "usage: check_summary FILE --expected FILE [--np N]\n";
      return 2;
    }
    try {
      checks = checksOfFile(checks[1], checks.size() == 4 ? checks[3] : "1");
    } catch (const std::exception& e) {
      std::cerr << "check_summary: expected values: " << e.what() << "\n";
      return 1;
    }
  }
  std::ifstream in(argv[1]);
  if (!in) {
    std::cerr << "check_summary: cannot open '" << argv[1] << "'\n";
    return 1;
  }
  json root;
  try {
    root = json::parse(in);
  } catch (const std::exception& e) {
    std::cerr << "check_summary: '" << argv[1] << "' is not valid JSON: " << e.what() << "\n";
    return 1;
  }
  int failures = 0;
  for (const std::string& check : checks) {
    const auto colon = check.find(':');
    const std::string kind = check.substr(0, colon);
    if (kind == "rate" || kind == "decreasing") {
      std::ostringstream msg;
      msg << kind << " ";
      bool ok = false;
      try {
        ok = checkEta(root, kind, check.substr(colon + 1), msg);
      } catch (const std::exception& e) {
        msg << "cannot evaluate: " << e.what();
      }
      std::cout << (ok ? "  ok    " : "  FAIL  ") << msg.str() << "\n";
      failures += ok ? 0 : 1;
      continue;
    }
    std::string rest = check.substr(colon + 1), pointer = rest, expected, tol;
    if (const auto eq = rest.find('='); eq != std::string::npos) {
      pointer = rest.substr(0, eq);
      expected = rest.substr(eq + 1);
      if (kind == "near") {
        const auto c = expected.rfind(':');
        tol = expected.substr(c + 1);
        expected = expected.substr(0, c);
      }
    }
    const json* node = resolve(root, pointer);
    bool ok = false;
    std::ostringstream msg;
    msg << kind << " " << pointer << ": ";
    if (!node) {
      msg << "missing";
    } else if (kind == "exists") {
      ok = true;
      msg << "present";
    } else if (kind == "size") {
      ok = node->size() == std::stoul(expected);
      msg << "size " << node->size() << ", expected " << expected;
    } else if (kind == "eq") {
      json want;
      try {
        want = json::parse(expected);
      } catch (...) {
        want = expected;  // bare string
      }
      ok = (*node == want) ||
           (node->is_number() && want.is_number() && node->get<double>() == want.get<double>());
      msg << node->dump() << ", expected " << want.dump();
    } else if (node->is_number()) {
      const double x = node->get<double>(), v = std::stod(expected);
      if (kind == "near") {
        const double rel = std::stod(tol);
        ok = std::abs(x - v) <= rel * std::abs(v);
        msg.precision(10);
        msg << x << ", expected " << v << " ± " << rel * 100 << "% (rel. error "
            << (v != 0 ? std::abs(x - v) / std::abs(v) : std::abs(x)) << ")";
      } else if (kind == "ge") {
        ok = x >= v;
        msg << x << " >= " << v;
      } else if (kind == "le") {
        ok = x <= v;
        msg << x << " <= " << v;
      } else if (kind == "gt") {
        ok = x > v;
        msg << x << " > " << v;
      } else {
        msg << "unknown check kind";
      }
    } else {
      msg << node->dump() << " is not a number";
    }
    std::cout << (ok ? "  ok    " : "  FAIL  ") << msg.str() << "\n";
    failures += ok ? 0 : 1;
  }
  std::cout << (static_cast<int>(checks.size()) - failures) << " passed, " << failures << " failed"
            << std::endl;
  return failures ? 1 : 0;
}
