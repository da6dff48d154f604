#pragma once
// CSV tables (e.g. contact_cycle<N>.csv, docs/output.md): a header and rows of numbers or strings.
// Doubles are written with 17 significant digits, so reading them back with strtod gives the
// same bits. Strings with commas, quotes or line breaks are quoted (RFC 4180).

#include <Teuchos_Comm.hpp>

#include <string>
#include <variant>
#include <vector>

namespace sc::io {

class CsvWriter {
public:
  using Value = std::variant<double, std::string>;
  using Row = std::vector<Value>;

  explicit CsvWriter(std::vector<std::string> header);

  /// Append a row of this rank; InputError if its width differs from the header's.
  void addRow(Row row);

  const std::vector<std::string>& header() const { return header_; }
  const std::vector<Row>& rows() const { return rows_; }

  /// "%.17g" (round-trips through strtod); "nan", "inf", "-inf" for non-finite values.
  static std::string formatValue(double value);
  /// Quoted if it contains a comma, quote, CR or LF.
  static std::string formatValue(const std::string& value);

  /// The rows of this rank as CSV lines (no header).
  std::string formatRows() const;
  /// Header line plus this rank's rows.
  std::string format() const;

  /// Not collective: write header plus this rank's rows to \p path atomically.
  void writeLocal(const std::string& path) const;

  /// Collective: gather every rank's rows to rank 0, which writes header plus all rows ordered by
  /// rank (rank 0's first) atomically. A failure throws on every rank.
  void writeGathered(const Teuchos::Comm<int>& comm, const std::string& path) const;

private:
  std::vector<std::string> header_;
  std::vector<Row> rows_;
};

/// Collective helper: concatenation of every rank's \p text on rank 0, in rank order (empty
/// string on other ranks).
std::string gatherTextToRoot(const Teuchos::Comm<int>& comm, const std::string& text);

}  // namespace sc::io
