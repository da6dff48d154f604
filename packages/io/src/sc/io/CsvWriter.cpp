#include <sc/io/CsvWriter.hpp>

#include <sc/io/AtomicFile.hpp>
#include <sc/core/Collective.hpp>

#include <sc/core/Error.hpp>

#include <cstdio>
#include <numeric>

namespace sc::io {

CsvWriter::CsvWriter(std::vector<std::string> header) : header_(std::move(header))
{
  SC_THROW_IF(header_.empty(), sc::core::InputError, "CsvWriter: the header has no columns");
}

void CsvWriter::addRow(Row row)
{
  SC_THROW_IF(row.size() != header_.size(), sc::core::InputError,
              "CsvWriter: row with " << row.size() << " values, the header has " << header_.size()
                                     << " columns (first: '" << header_.front() << "')");
  rows_.push_back(std::move(row));
}

std::string CsvWriter::formatValue(double value)
{
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", value);
  return buf;
}

std::string CsvWriter::formatValue(const std::string& value)
{
  if (value.find_first_of(",\"\r\n") == std::string::npos) return value;
  std::string out = "\"";
  for (char c : value) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

std::string CsvWriter::formatRows() const
{
  std::string out;
  for (const Row& row : rows_) {
    for (std::size_t i = 0; i < row.size(); ++i) {
      if (i > 0) out += ',';
      out += std::visit([](const auto& v) { return formatValue(v); }, row[i]);
    }
    out += '\n';
  }
  return out;
}

std::string CsvWriter::format() const
{
  std::string out;
  for (std::size_t i = 0; i < header_.size(); ++i) {
    if (i > 0) out += ',';
    out += formatValue(header_[i]);
  }
  return out + '\n' + formatRows();
}

void CsvWriter::writeLocal(const std::string& path) const { writeFileAtomically(path, format()); }

void CsvWriter::writeGathered(const Teuchos::Comm<int>& comm, const std::string& path) const
{
  const std::string all = gatherTextToRoot(comm, formatRows());
  core::runOnRoot(comm, [&] {
    CsvWriter headerOnly(header_);
    writeFileAtomically(path, headerOnly.format() + all);
  });
}

std::string gatherTextToRoot(const Teuchos::Comm<int>& comm, const std::string& text)
{
  // Raw MPI: Teuchos::gatherv has no char specialisation in Trilinos 13.2.
  const MPI_Comm mpiComm = core::rawMpiComm(comm);
  int size = 1, rank = 0;
  MPI_Comm_size(mpiComm, &size);
  MPI_Comm_rank(mpiComm, &rank);
  const int length = static_cast<int>(text.size());
  std::vector<int> lengths(static_cast<std::size_t>(size), 0);
  MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, mpiComm);
  std::vector<int> displs(static_cast<std::size_t>(size), 0);
  std::exclusive_scan(lengths.begin(), lengths.end(), displs.begin(), 0);
  const int total = rank == 0 ? displs.back() + lengths.back() : 0;
  std::vector<char> all(static_cast<std::size_t>(total) + 1);  // +1: never a null buffer
  std::vector<char> mine(text.begin(), text.end());
  mine.push_back('\0');
  MPI_Gatherv(mine.data(), length, MPI_CHAR, all.data(), lengths.data(), displs.data(), MPI_CHAR, 0,
              mpiComm);
  return rank == 0 ? std::string(all.data(), static_cast<std::size_t>(total)) : std::string();
}

}  // namespace sc::io
