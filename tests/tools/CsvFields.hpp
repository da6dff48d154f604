#pragma once
// The fields of one line of a CSV file that StressContact writes (io::CsvWriter): comma-separated,
// a trailing comma meaning an empty last field. Shared by the check tools of tests/.
#include <sstream>
#include <string>
#include <vector>

namespace sc::testtools {

inline std::vector<std::string> splitCsvLine(const std::string& line)
{
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ','))
    out.push_back(cell);
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

}  // namespace sc::testtools
