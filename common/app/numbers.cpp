#include "app/numbers.hpp"

#include <charconv>
#include <cmath>
#include <optional>
#include <regex>

#include <CLI/Error.hpp>
#include <fmt/format.h>

namespace mcrt {

namespace {

const std::regex k_whole(R"(\d+)");
const std::regex k_decimal(R"([+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?)");

bool matches(std::string_view text, const std::regex& grammar) {
  return std::regex_match(text.begin(), text.end(), grammar);
}

// `text` fit for a one-line message: control characters replaced, at most 40 shown.
std::string shown(std::string_view text) {
  std::string result;
  for (const char c : text.substr(0, 40))
    result += (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) ? '?' : c;
  return text.size() > 40 ? result + "..." : result;
}

// `value` if it lies in [lowest, highest] (written as `low`, `high`); else the refusal,
// "<accepted> (<why>)", `why` saying what is wrong when there is no value.
template <class T>
T checked(std::optional<T> value, std::string_view text, const std::string& accepted, T lowest,
          T highest, const std::string& low, const std::string& high, std::string why) {
  if (value && *value < lowest) why = fmt::format("{} is below {}", shown(text), low);
  if (value && *value > highest) why = fmt::format("{} is above {}", shown(text), high);
  if (value && why.empty()) return *value;
  throw CLI::ValidationError(fmt::format("{} ({})", accepted, why));
}

}  // namespace

std::string plain_number(double value) {
  if (std::abs(value) < 1e7) return fmt::format("{}", value);
  std::string text = fmt::format("{:g}", value);
  if (const std::size_t e = text.find("e+"); e != std::string::npos) text.erase(e + 1, 1);
  return text;
}

std::string real_number_range(std::string_view flag, double lowest, double highest,
                              std::string_view what) {
  return fmt::format("{}: give {} from {} to {}", flag, what, plain_number(lowest),
                     plain_number(highest));
}

std::uint64_t parse_whole_number(std::string_view text, std::string_view flag, std::uint64_t lowest,
                                 std::uint64_t highest, std::string_view what) {
  std::optional<std::uint64_t> value;
  std::string why;
  if (std::uint64_t v = 0; !matches(text, k_whole))
    why = text.starts_with('-') && matches(text.substr(1), k_whole)
              ? fmt::format("{} is below {}", shown(text), lowest)
              : fmt::format("'{}' is not one", shown(text));
  else if (std::from_chars(text.data(), text.data() + text.size(), v).ec != std::errc())
    why = shown(text) + " is too large";
  else
    value = v;
  const std::string low = std::to_string(lowest), high = std::to_string(highest);
  return checked(value, text, fmt::format("{}: give {} from {} to {}", flag, what, low, high),
                 lowest, highest, low, high, why);
}

double parse_real_number(std::string_view text, std::string_view flag, double lowest,
                         double highest, std::string_view what) {
  std::optional<double> value;
  std::string why = fmt::format("'{}' is not one", shown(text));
  if (matches(text, k_decimal)) {
    const std::string_view digits = text.starts_with('+') ? text.substr(1) : text;
    double v = 0.0;  // from_chars takes no plus sign
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
    if (error == std::errc() && std::isfinite(v))
      value = v + 0.0;  // -0 becomes 0
    else
      why = shown(text) + " is out of range";  // written right, beyond what a double holds
  }
  return checked(value, text, real_number_range(flag, lowest, highest, what), lowest, highest,
                 plain_number(lowest), plain_number(highest), value ? "" : why);
}

}  // namespace mcrt
