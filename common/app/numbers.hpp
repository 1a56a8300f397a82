#pragma once
/// The numbers of the command line, read exactly as written. A whole number is decimal digits
/// only ("010" is ten, never octal); a real number is decimal notation ("0.5", "2e9") and
/// finite. Nothing is clamped. A refusal is CLI::ValidationError, one line under 200
/// characters naming the flag and what it accepts:
///   --seed: give a whole number from 0 to 18446744073709551615 (-1 is below 0)

#include <cstdint>
#include <string>
#include <string_view>

namespace mcrt {

/// `text` as a whole number from `lowest` to `highest`; `what` names what is accepted.
std::uint64_t parse_whole_number(std::string_view text, std::string_view flag, std::uint64_t lowest,
                                 std::uint64_t highest, std::string_view what = "a whole number");

/// `text` as a finite real number ([sign] digits [. digits] [e [sign] digits]; -0 is 0) from
/// `lowest` to `highest`.
double parse_real_number(std::string_view text, std::string_view flag, double lowest,
                         double highest, std::string_view what = "a number");

/// What a flag accepts: "--albedo: give a number from 0 to 1".
std::string real_number_range(std::string_view flag, double lowest, double highest,
                              std::string_view what = "a number");

/// A bound written plainly: 1, 0.001, 1000000, and 1e15 rather than fifteen zeros.
std::string plain_number(double value);

}  // namespace mcrt
