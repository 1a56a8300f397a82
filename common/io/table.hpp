#pragma once
/// One table of named, typed columns, written three ways from the one definition: the CSV
/// file (header row, then one line per row), the JSON array of objects in summary.json, and
/// the aligned table printed on the console. Plots read the CSV columns by their names.
///
///   Table table({{"n", Column::integer}, {"rmse", Column::real}});
///   table.add_row({n, rmse});
///   write_csv(out / "errors.csv", table);
///   summary["errors"] = table.json();
///   std::fputs(table.console().c_str(), stdout);

#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

namespace mcrt {

/// A column: its name (CSV header and JSON key) and what it holds.
struct Column {
  enum Kind { integer, real, text };
  /// How a real is written in the CSV, as printf would: %.{digits}g, %.{digits}f or
  /// %.{digits}e.
  enum Style { general, fixed, scientific };

  std::string name;
  Kind kind = real;
  int digits = 9;  ///< significant digits (general) or digits after the point (fixed, scientific)
  Style style = general;
};

/// One cell: an integer (signed or not), a real, a text, or empty (Cell{}: an empty CSV
/// field, null in JSON, allowed in any column). Integer types convert exactly.
class Cell {
 public:
  Cell() = default;
  template <class T>
  requires std::is_integral_v<T> Cell(
      T value) {  // NOLINT: implicit, so rows read as {n, rmse, "name"}
    if constexpr (std::is_signed_v<T>)
      value_ = static_cast<std::int64_t>(value);
    else
      value_ = static_cast<std::uint64_t>(value);
  }
  Cell(double value) : value_(value) {}                    // NOLINT
  Cell(std::string value) : value_(std::move(value)) {}    // NOLINT
  Cell(const char* value) : value_(std::string(value)) {}  // NOLINT

  bool is_integer() const { return value_.index() == 1 || value_.index() == 2; }
  bool is_real() const { return value_.index() == 3; }
  bool is_text() const { return value_.index() == 4; }
  bool is_empty() const { return value_.index() == 0; }
  /// The value as a double (integers converted), for reading a table back in code.
  double number() const;
  const std::string& string() const { return std::get<std::string>(value_); }

  /// The cell as the CSV writes it: integers in full, reals in `style` with `digits`, text
  /// as it is (a table's text never holds a comma, a quote or a newline), empty as nothing.
  std::string csv(int digits, Column::Style style = Column::general) const;
  nlohmann::ordered_json json() const;

 private:
  std::variant<std::monostate, std::int64_t, std::uint64_t, double, std::string> value_;
};

/// Whether a column holds timings, which differ from run to run: "seconds", "*_seconds",
/// "*per_second*" and "*efficiency*" (a rate per second of work).
bool is_timing_column(std::string_view name);

class Table {
 public:
  explicit Table(std::vector<Column> columns);

  /// Appends a row; throws std::logic_error unless it has one cell per column, each of its
  /// column's kind (a real column also takes integers, which it stores as reals).
  void add_row(std::vector<Cell> row);

  const std::vector<Column>& columns() const { return columns_; }
  std::size_t size() const { return rows_.size(); }
  bool empty() const { return rows_.empty(); }
  /// The cell of row `row` in the column named `name`; throws std::out_of_range if none.
  const Cell& at(std::size_t row, std::string_view name) const;
  /// Every value of a numeric column, in row order (empty cells are NaN).
  std::vector<double> numbers(std::string_view name) const;

  /// The CSV text: a header row of the names, then the rows.
  std::string csv() const;
  /// An array with one object per row, keys in column order, timing columns left out (they
  /// stay in the CSV): summary.json is the same whatever the machine or --threads.
  nlohmann::ordered_json json() const;
  /// The rows aligned under their names, reals to 4 significant digits; `only` picks and
  /// orders columns (all of them when empty); `indent` spaces start every line.
  std::string console(std::initializer_list<std::string_view> only = {}, int indent = 2) const;

 private:
  std::size_t index_of(std::string_view name) const;

  std::vector<Column> columns_;
  std::vector<std::vector<Cell>> rows_;
};

/// Writes table.csv() to `path` atomically (io/output.hpp); throws IoError on failure.
void write_csv(const std::filesystem::path& path, const Table& table);

}  // namespace mcrt
