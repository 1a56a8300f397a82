#include "io/table.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

#include "io/output.hpp"

namespace mcrt {

double Cell::number() const {
  switch (value_.index()) {
    case 0: return std::numeric_limits<double>::quiet_NaN();
    case 1: return static_cast<double>(std::get<1>(value_));
    case 2: return static_cast<double>(std::get<2>(value_));
    case 3: return std::get<3>(value_);
    default: throw std::logic_error("Cell::number: the cell holds text");
  }
}

std::string Cell::csv(int digits, Column::Style style) const {
  switch (value_.index()) {
    case 0: return {};
    case 1: return fmt::format("{}", std::get<1>(value_));
    case 2: return fmt::format("{}", std::get<2>(value_));
    case 3:
      switch (style) {
        case Column::fixed: return fmt::format("{:.{}f}", std::get<3>(value_), digits);
        case Column::scientific: return fmt::format("{:.{}e}", std::get<3>(value_), digits);
        default: return fmt::format("{:.{}g}", std::get<3>(value_), digits);
      }
    default: return std::get<4>(value_);
  }
}

nlohmann::ordered_json Cell::json() const {
  switch (value_.index()) {
    case 0: return nullptr;
    case 1: return std::get<1>(value_);
    case 2: return std::get<2>(value_);
    case 3: return std::get<3>(value_);
    default: return std::get<4>(value_);
  }
}

Table::Table(std::vector<Column> columns) : columns_(std::move(columns)) {
  for (std::size_t i = 0; i < columns_.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (columns_[i].name == columns_[j].name)
        throw std::logic_error("Table: two columns named '" + columns_[i].name + "'");
}

void Table::add_row(std::vector<Cell> row) {
  if (row.size() != columns_.size())
    throw std::logic_error(
        fmt::format("Table: a row of {} cells for {} columns", row.size(), columns_.size()));
  for (std::size_t i = 0; i < row.size(); ++i) {
    const Column& column = columns_[i];
    const bool fits = row[i].is_empty()                ? true
                      : column.kind == Column::integer ? row[i].is_integer()
                      : column.kind == Column::real    ? !row[i].is_text()
                                                       : row[i].is_text();
    if (!fits)
      throw std::logic_error("Table: a cell of the wrong kind in column '" + column.name + "'");
    if (column.kind == Column::real && row[i].is_integer()) row[i] = Cell(row[i].number());
  }
  rows_.push_back(std::move(row));
}

std::size_t Table::index_of(std::string_view name) const {
  for (std::size_t i = 0; i < columns_.size(); ++i)
    if (columns_[i].name == name) return i;
  throw std::out_of_range("Table: no column named '" + std::string(name) + "'");
}

const Cell& Table::at(std::size_t row, std::string_view name) const {
  return rows_.at(row)[index_of(name)];
}

std::vector<double> Table::numbers(std::string_view name) const {
  const std::size_t column = index_of(name);
  std::vector<double> values;
  values.reserve(rows_.size());
  for (const std::vector<Cell>& row : rows_) values.push_back(row[column].number());
  return values;
}

std::string Table::csv() const {
  std::string text;
  // Appended piece by piece: "," + a temporary trips a false -Wrestrict in g++ 12.
  for (std::size_t i = 0; i < columns_.size(); ++i) {
    if (i) text += ',';
    text += columns_[i].name;
  }
  text += '\n';
  for (const std::vector<Cell>& row : rows_) {
    for (std::size_t i = 0; i < row.size(); ++i) {
      if (i) text += ',';
      text += row[i].csv(columns_[i].digits, columns_[i].style);
    }
    text += '\n';
  }
  return text;
}

bool is_timing_column(std::string_view name) {
  const auto ends_with = [&](std::string_view end) {
    return name.size() >= end.size() && name.substr(name.size() - end.size()) == end;
  };
  return name == "seconds" || ends_with("_seconds") ||
         name.find("per_second") != std::string_view::npos ||
         name.find("efficiency") != std::string_view::npos;
}

nlohmann::ordered_json Table::json() const {
  nlohmann::ordered_json array = nlohmann::ordered_json::array();
  for (const std::vector<Cell>& row : rows_) {
    nlohmann::ordered_json object = nlohmann::ordered_json::object();
    for (std::size_t i = 0; i < row.size(); ++i)
      if (!is_timing_column(columns_[i].name)) object[columns_[i].name] = row[i].json();
    array.push_back(std::move(object));
  }
  return array;
}

std::string Table::console(std::initializer_list<std::string_view> only, int indent) const {
  std::vector<std::size_t> shown;
  for (std::string_view name : only) shown.push_back(index_of(name));
  if (only.size() == 0)
    for (std::size_t i = 0; i < columns_.size(); ++i) shown.push_back(i);
  // The cells as printed (reals to 4 significant digits), then each column's width.
  std::vector<std::vector<std::string>> cells(rows_.size() + 1);
  for (std::size_t c : shown) cells[0].push_back(columns_[c].name);
  for (std::size_t r = 0; r < rows_.size(); ++r)
    for (std::size_t c : shown) cells[r + 1].push_back(rows_[r][c].csv(4));
  std::vector<std::size_t> width(shown.size(), 0);
  for (const std::vector<std::string>& line : cells)
    for (std::size_t i = 0; i < line.size(); ++i) width[i] = std::max(width[i], line[i].size());
  std::string text;
  for (const std::vector<std::string>& line : cells) {
    text += std::string(static_cast<std::size_t>(indent), ' ');
    for (std::size_t i = 0; i < line.size(); ++i)
      text += fmt::format("{}{:>{}}", i ? "  " : "", line[i], width[i]);
    text += '\n';
  }
  return text;
}

void write_csv(const std::filesystem::path& path, const Table& table) {
  write_file_atomic(path, table.csv());
}

}  // namespace mcrt
