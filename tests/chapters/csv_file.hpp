#pragma once
// A chapter's CSV file read back by column name, for the chapter tests: a plot or a test
// that names its columns keeps working when a column is added.

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace mcrt::testing {

class CsvFile {
 public:
  explicit CsvFile(const std::filesystem::path& path) {
    std::ifstream file(path);
    if (!file) throw std::runtime_error("cannot read " + path.string());
    std::string line;
    std::getline(file, line);
    header_ = split(line);
    while (std::getline(file, line))
      if (!line.empty()) rows_.push_back(split(line));
  }

  const std::vector<std::string>& header() const { return header_; }
  std::size_t size() const { return rows_.size(); }
  const std::vector<std::string>& row(std::size_t r) const { return rows_.at(r); }
  bool has(std::string_view name) const {
    for (const std::string& h : header_)
      if (h == name) return true;
    return false;
  }

  /// The cell of row r in the named column, as written.
  const std::string& text(std::size_t r, std::string_view name) const {
    return rows_.at(r).at(column(name));
  }
  double number(std::size_t r, std::string_view name) const { return std::stod(text(r, name)); }
  /// Every value of the named column, in row order.
  std::vector<double> numbers(std::string_view name) const {
    std::vector<double> values;
    for (std::size_t r = 0; r < rows_.size(); ++r) values.push_back(number(r, name));
    return values;
  }

  /// The file without the named columns (timings, which differ from run to run), as text.
  std::string without(const std::vector<std::string>& names) const {
    std::vector<bool> keep(header_.size(), true);
    for (const std::string& name : names) keep[column(name)] = false;
    std::string text = join(header_, keep);
    for (const std::vector<std::string>& r : rows_) text += join(r, keep);
    return text;
  }

 private:
  std::size_t column(std::string_view name) const {
    for (std::size_t i = 0; i < header_.size(); ++i)
      if (header_[i] == name) return i;
    throw std::out_of_range("no column named '" + std::string(name) + "'");
  }

  static std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> cells;
    std::stringstream stream(line);
    std::string cell;
    while (std::getline(stream, cell, ',')) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.emplace_back();
    return cells;
  }

  static std::string join(const std::vector<std::string>& cells, const std::vector<bool>& keep) {
    std::string text;
    for (std::size_t i = 0; i < cells.size(); ++i)
      if (keep[i]) text += cells[i] + ",";
    return text + "\n";
  }

  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
};

}  // namespace mcrt::testing
