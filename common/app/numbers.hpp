#pragma once
/// The numbers of the command line, read exactly as written. A whole number is decimal digits
/// and nothing else: "010" is ten (never octal eight), and a sign, a hex prefix, a space, a
/// point or trailing text make it no number. A real number is decimal notation (digits, one
/// point, an exponent: "0.5", "2e9") and finite: nan, inf and hex floats are no numbers.
/// Nothing is clamped: a value outside its range is refused, never moved to the nearest bound.
///
/// A refusal is CLI::ValidationError with one line under 200 characters that names the flag
/// and says in plain words what it accepts:
///   --seed: give a whole number from 0 to 18446744073709551615 (18446744073709551616 is too large)

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace mcrt {

/// `text` as a whole number if it is one: decimal digits only, at most 2^64 - 1.
std::optional<std::uint64_t> read_whole_number(std::string_view text);

/// `text` as a real number if it is one: [sign] digits [. digits] [e [sign] digits], finite.
/// A negative zero is read as zero.
std::optional<double> read_real_number(std::string_view text);

/// What a flag accepts, in plain words: "--seed: give a whole number from 0 to 18446744073709551615".
std::string whole_number_range(std::string_view flag, std::uint64_t lowest, std::uint64_t highest);
/// The same for real numbers: "--albedo: give a number from 0 to 1".
std::string real_number_range(std::string_view flag, double lowest, double highest);

/// `text` read as a whole number from `lowest` to `highest` (inclusive), or CLI::ValidationError
/// naming `flag`.
std::uint64_t parse_whole_number(std::string_view text, std::string_view flag, std::uint64_t lowest,
                                 std::uint64_t highest);

/// `text` read as a finite real number from `lowest` to `highest` (inclusive), or
/// CLI::ValidationError naming `flag`.
double parse_real_number(std::string_view text, std::string_view flag, double lowest,
                         double highest);

/// A bound written plainly: 1, 0.001, 16384, 1000000, and 1e15 rather than fifteen zeros.
std::string plain_number(double value);

/// `text` as it may be quoted in a one-line message: control characters replaced, and cut to a
/// few dozen characters.
std::string quoted_for_message(std::string_view text);

}  // namespace mcrt
