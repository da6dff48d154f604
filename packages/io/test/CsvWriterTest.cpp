// CsvWriter: gathered in rank order, doubles bit-exact after a round trip through text.
#include <sc/io/CsvWriter.hpp>

#include "TestDirectory.hpp"

#include <sc/core/Error.hpp>

#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_UnitTestHarness.hpp>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

namespace {

using sc::io::test::freshDirectory;
using sc::io::test::temporaries;

// Awkward doubles: not representable in decimal, extremes, subnormal, negative zero.
std::vector<double> valuesOfRank(int rank)
{
  return {rank + 0.1,
          1.0 / 3.0 * (rank + 1),
          std::nextafter(1.0, 2.0),
          1e-300,
          std::numeric_limits<double>::denorm_min(),
          -0.0,
          std::numeric_limits<double>::max(),
          -2.5e17 * (rank + 1),
          M_PI};
}

std::vector<std::string> splitLines(const std::string& text)
{
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}

std::vector<std::string> splitFields(const std::string& line)
{
  std::vector<std::string> fields;
  std::string field;
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"')
        field += '"', ++i;
      else if (c == '"')
        quoted = false;
      else
        field += c;
    } else if (c == '"')
      quoted = true;
    else if (c == ',')
      fields.push_back(field), field.clear();
    else
      field += c;
  }
  fields.push_back(field);
  return fields;
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEUCHOS_UNIT_TEST(CsvWriter, GatheredInRankOrderBitExact)
{
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const int rank = comm->getRank(), size = comm->getSize();
  const std::string dir = freshDirectory(*comm, "csv");
  sc::io::CsvWriter csv({"rank", "label", "value"});
  // Rank 1 contributes no rows: empty pieces must work.
  if (rank != 1)
    for (double v : valuesOfRank(rank))
      csv.addRow(
          {static_cast<double>(rank), std::string("r, \"") + std::to_string(rank) + "\"", v});
  const std::string path = dir + "/contact_cycle0.csv";
  csv.writeGathered(*comm, path);
  comm->barrier();
  if (rank != 0) return;
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  const auto lines = splitLines(s.str());
  TEST_ASSERT(!lines.empty());
  TEST_EQUALITY(lines[0], "rank,label,value");
  std::size_t line = 1;
  for (int r = 0; r < size; ++r) {
    if (r == 1) continue;
    for (double v : valuesOfRank(r)) {
      TEST_ASSERT(line < lines.size());
      if (line >= lines.size()) return;
      const auto f = splitFields(lines[line++]);
      TEST_EQUALITY(f.size(), 3u);
      TEST_EQUALITY(std::strtod(f[0].c_str(), nullptr), static_cast<double>(r));
      TEST_EQUALITY(f[1], std::string("r, \"") + std::to_string(r) + "\"");
      const double back = std::strtod(f[2].c_str(), nullptr);
      TEST_ASSERT(sameBits(back, v));
    }
  }
  TEST_EQUALITY(line, lines.size());
  TEST_EQUALITY(temporaries(dir).size(), 0u);
}

TEUCHOS_UNIT_TEST(CsvWriter, RowWidthChecked)
{
  sc::io::CsvWriter csv({"a", "b"});
  TEST_THROW(csv.addRow({1.0}), sc::core::InputError);
  csv.addRow({1.0, std::string("x")});
  TEST_EQUALITY(csv.format(), "a,b\n1,x\n");
  TEST_EQUALITY(sc::io::CsvWriter::formatValue(0.1), "0.10000000000000001");
}

}  // namespace
