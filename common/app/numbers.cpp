#include "app/numbers.hpp"

#include <charconv>
#include <cmath>
#include <regex>
#include <system_error>

#include <CLI/Error.hpp>
#include <fmt/format.h>

namespace mcrt {

namespace {

// A whole number: decimal digits only. A real one in decimal notation: [sign] digits
// [. digits] [e [sign] digits], at least one digit before or after the point.
const std::regex k_whole(R"(\d+)");
const std::regex k_decimal(R"([+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?)");

bool all_digits(std::string_view text) {
  return std::regex_match(text.begin(), text.end(), k_whole);
}

bool is_decimal_notation(std::string_view text) {
  return std::regex_match(text.begin(), text.end(), k_decimal);
}

}  // namespace

std::string plain_number(double value) {
  if (std::abs(value) >= 1e7) {
    std::string text = fmt::format("{:g}", value);
    const std::size_t e = text.find("e+");
    if (e != std::string::npos) text.erase(e + 1, 1);
    return text;
  }
  return fmt::format("{}", value);
}

std::string quoted_for_message(std::string_view text) {
  constexpr std::size_t k_longest = 40;
  std::string shown;
  for (char c : text.substr(0, k_longest))
    shown += (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) ? '?' : c;
  if (text.size() > k_longest) shown += "...";
  return shown;
}

std::optional<std::uint64_t> read_whole_number(std::string_view text) {
  if (!all_digits(text)) return std::nullopt;
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value, 10);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

std::optional<double> read_real_number(std::string_view text) {
  if (!is_decimal_notation(text)) return std::nullopt;
  if (text.front() == '+') text.remove_prefix(1);  // from_chars takes no plus sign
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value,
                                            std::chars_format::general);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
    return std::nullopt;
  return value + 0.0;  // -0 becomes 0
}

std::string whole_number_range(std::string_view flag, std::uint64_t lowest,
                               std::uint64_t highest) {
  return fmt::format("{}: give a whole number from {} to {}", flag, lowest, highest);
}

std::string real_number_range(std::string_view flag, double lowest, double highest) {
  return fmt::format("{}: give a number from {} to {}", flag, plain_number(lowest), plain_number(highest));
}

std::uint64_t parse_whole_number(std::string_view text, std::string_view flag, std::uint64_t lowest,
                                 std::uint64_t highest) {
  const std::string accepted = whole_number_range(flag, lowest, highest);
  const std::string shown = quoted_for_message(text);
  const std::optional<std::uint64_t> value = read_whole_number(text);
  if (!value) {
    if (all_digits(text))
      throw CLI::ValidationError(fmt::format("{} ({} is too large)", accepted, shown));
    if (text.size() > 1 && text.front() == '-' && all_digits(text.substr(1)))
      throw CLI::ValidationError(fmt::format("{} ({} is below {})", accepted, shown, lowest));
    throw CLI::ValidationError(fmt::format("{} ('{}' is not one)", accepted, shown));
  }
  if (*value < lowest)
    throw CLI::ValidationError(fmt::format("{} ({} is below {})", accepted, shown, lowest));
  if (*value > highest)
    throw CLI::ValidationError(fmt::format("{} ({} is above {})", accepted, shown, highest));
  return *value;
}

double parse_real_number(std::string_view text, std::string_view flag, double lowest,
                         double highest) {
  const std::string accepted = real_number_range(flag, lowest, highest);
  const std::string shown = quoted_for_message(text);
  const std::optional<double> value = read_real_number(text);
  if (!value) {
    if (is_decimal_notation(text))  // written correctly, but beyond what a double holds
      throw CLI::ValidationError(fmt::format("{} ({} is out of range)", accepted, shown));
    throw CLI::ValidationError(fmt::format("{} ('{}' is not one)", accepted, shown));
  }
  if (*value < lowest)
    throw CLI::ValidationError(fmt::format("{} ({} is below {})", accepted, shown, plain_number(lowest)));
  if (*value > highest)
    throw CLI::ValidationError(fmt::format("{} ({} is above {})", accepted, shown, plain_number(highest)));
  return *value;
}

}  // namespace mcrt
