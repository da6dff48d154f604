// compare_summaries: do two runs' summary.json agree cycle by cycle? (checkpoint/restart tests,
// docs/adaptivity.md "Checkpoint and restart")
//
//   compare_summaries EXPECTED ACTUAL [--rtol R] [--atol A] [--ignore KEY]...
//
// Both must have "converged" equal and the same number of cycles; in every cycle every value
// (recursively) must agree: the same keys, numbers within |a − b| ≤ R·max(|a|, |b|) (default
// R = 1e-12) or |a − b| ≤ A (default 0: for quantities at rounding level, such as an estimator
// part that is zero up to rounding; integers exactly), strings, booleans and nulls equal. Skipped:
// wall times
// ("timings" and any key containing "seconds"), the peak memory ("memory") and any object key
// given with --ignore. Prints every difference (pointer, both values,
// relative difference) and exits 1 if there is one, 2 on a usage or file error.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

using nlohmann::json;

namespace {

struct Comparison {
  double rtol = 1e-12;
  double atol = 0.0;
  std::set<std::string> ignored{"timings", "memory"};
  bool skipped(const std::string& key) const
  {
    return ignored.count(key) || key.find("seconds") != std::string::npos;
  }
  int differences = 0;
  long long numbers = 0;
  double worst = 0.0;

  void report(const std::string& where, const json& a, const json& b, const std::string& why)
  {
    ++differences;
    std::cout << "DIFFERENT " << where << ": expected " << a.dump() << ", got " << b.dump() << " ("
              << why << ")\n";
  }

  void compare(const json& a, const json& b, const std::string& where)
  {
    if (a.is_number() && b.is_number()) {
      ++numbers;
      if (a.is_number_integer() && b.is_number_integer()) {
        if (a.get<long long>() != b.get<long long>()) report(where, a, b, "integers differ");
        return;
      }
      const double x = a.get<double>(), y = b.get<double>();
      const double scale = std::max(std::abs(x), std::abs(y));
      const double rel = scale > 0.0 ? std::abs(x - y) / scale : 0.0;
      if (std::abs(x - y) <= atol) return;
      worst = std::max(worst, rel);
      if (!(rel <= rtol)) {
        std::ostringstream os;
        os << "relative difference " << rel;
        report(where, a, b, os.str());
      }
      return;
    }
    if (a.type() != b.type()) {
      report(where, a, b, "types differ");
      return;
    }
    if (a.is_object()) {
      for (const auto& item : a.items()) {
        if (skipped(item.key())) continue;
        if (!b.contains(item.key()))
          report(where + "/" + item.key(), item.value(), json(), "missing");
        else
          compare(item.value(), b[item.key()], where + "/" + item.key());
      }
      for (const auto& item : b.items())
        if (!skipped(item.key()) && !a.contains(item.key()))
          report(where + "/" + item.key(), json(), item.value(), "not expected");
    } else if (a.is_array()) {
      if (a.size() != b.size()) {
        report(where, json(a.size()), json(b.size()), "array lengths differ");
        return;
      }
      for (std::size_t i = 0; i < a.size(); ++i)
        compare(a[i], b[i], where + "/" + std::to_string(i));
    } else if (a != b) {
      report(where, a, b, "values differ");
    }
  }
};

json load(const std::string& path)
{
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open '" + path + "'");
  return json::parse(in);
}

}  // namespace

int main(int argc, char* argv[])
{
  try {
    Comparison c;
    std::string files[2];
    int nfiles = 0;
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      if (a == "--rtol" && i + 1 < argc)
        c.rtol = std::stod(argv[++i]);
      else if (a == "--atol" && i + 1 < argc)
        c.atol = std::stod(argv[++i]);
      else if (a == "--ignore" && i + 1 < argc)
        c.ignored.insert(argv[++i]);
      else if (nfiles < 2 && a.rfind("--", 0) != 0)
        files[nfiles++] = a;
      else
        throw std::runtime_error("unexpected argument '" + a + "'");
    }
    if (nfiles != 2)
      throw std::runtime_error(
          "usage: compare_summaries EXPECTED ACTUAL [--rtol R] [--atol A] [--ignore KEY]...");
    const json a = load(files[0]), b = load(files[1]);
    if (!a.contains("cycles") || !b.contains("cycles") || !a["cycles"].is_array() ||
        !b["cycles"].is_array())
      throw std::runtime_error("both files need a 'cycles' array");
    c.compare(a.value("converged", json()), b.value("converged", json()), "/converged");
    c.compare(a["cycles"].size(), b["cycles"].size(), "/cycles (count)");
    c.compare(a["cycles"], b["cycles"], "/cycles");
    std::cout << a["cycles"].size() << " cycles, " << c.numbers
              << " numbers compared, largest relative "
              << "difference " << c.worst << " (tolerance " << c.rtol << "): "
              << (c.differences ? std::to_string(c.differences) + " difference(s)" : "the same")
              << "\n";
    return c.differences ? 1 : 0;
  } catch (const std::exception& e) {
    std::cerr << "compare_summaries: " << e.what() << "\n";
    return 2;
  }
}
