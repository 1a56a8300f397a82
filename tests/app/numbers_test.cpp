// The number reader of every numeric flag (common/app/numbers.hpp, add_number_option in
// common/app/cli.hpp): numbers read as written, nothing clamped, finite reals only, and a
// one-line message under 200 characters naming the flag and the range.

#include "app/numbers.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <gtest/gtest.h>

#include "app/cli.hpp"

using mcrt::parse_real_number;
using mcrt::parse_whole_number;

namespace {

constexpr std::uint64_t k_most = std::numeric_limits<std::uint64_t>::max();

// The message of the error parse_whole_number throws for --seed, or "" when it accepts.
std::string seed_rejection(const std::string& text, std::uint64_t lowest = 0,
                           std::uint64_t highest = k_most) {
  try {
    parse_whole_number(text, "--seed", lowest, highest);
  } catch (const CLI::ValidationError& e) {
    return e.what();
  }
  return "";
}

std::string albedo_rejection(const std::string& text) {
  try {
    parse_real_number(text, "--albedo", 0.0, 1.0);
  } catch (const CLI::ValidationError& e) {
    return e.what();
  }
  return "";
}

TEST(WholeNumberTest, LeadingZerosAreDecimalNeverOctal) {
  EXPECT_EQ(parse_whole_number("010", "--width", 1, 100), 10u);
  EXPECT_EQ(parse_whole_number("08", "--width", 1, 100), 8u);
  EXPECT_EQ(parse_whole_number("0", "--seed", 0, k_most), 0u);
}

TEST(WholeNumberTest, SeedsRunFromZeroToTwoToTheSixtyFourMinusOneAndNoFurther) {
  EXPECT_EQ(parse_whole_number("18446744073709551615", "--seed", 0, k_most), k_most);
  const std::string beyond = seed_rejection("18446744073709551616");  // not clamped
  EXPECT_NE(beyond.find("--seed"), std::string::npos) << beyond;
  EXPECT_NE(beyond.find("18446744073709551615"), std::string::npos) << beyond;
  EXPECT_NE(seed_rejection("99999999999999999999999999"), "");
}

TEST(WholeNumberTest, HexSignsSpacesPointsAndTrailingTextAreRejected) {
  for (const char* text : {"0x10", "0X10", "+1", "-0", " 1", "1 ", "1.0", "1e3", "1,2", "12abc", "",
                           "ten", "\t7", "1_000"})
    EXPECT_NE(seed_rejection(text), "") << "'" << text << "'";
}

TEST(WholeNumberTest, MinusOneGetsAShortMessageWithThePlainRange) {
  const std::string message = seed_rejection("-1");
  EXPECT_EQ(message, "--seed: give a whole number from 0 to 18446744073709551615 (-1 is below 0)");
}

TEST(WholeNumberTest, TheBoundsAreInclusiveAndOutsideIsRejected) {
  EXPECT_EQ(parse_whole_number("1", "--width", 1, 16384), 1u);
  EXPECT_EQ(parse_whole_number("16384", "--width", 1, 16384), 16384u);
  EXPECT_NE(seed_rejection("0", 1, 16384).find("below 1"), std::string::npos);
  EXPECT_NE(seed_rejection("16385", 1, 16384).find("above 16384"), std::string::npos);
}

TEST(RealNumberTest, DecimalNotationIsRead) {
  EXPECT_EQ(parse_real_number("0.5", "--albedo", 0.0, 1.0), 0.5);
  EXPECT_EQ(parse_real_number("1e3", "--emission", 0.0, 1e6), 1000.0);
  EXPECT_EQ(parse_real_number("2E9", "--max-rays", 1.0, 1e15), 2e9);
  EXPECT_EQ(parse_real_number(".25", "--albedo", 0.0, 1.0), 0.25);
  EXPECT_EQ(parse_real_number("+1", "--albedo", 0.0, 1.0), 1.0);
  EXPECT_EQ(parse_real_number("010", "--emission", 0.0, 1e6), 10.0);
  const double zero = parse_real_number("-0", "--albedo", 0.0, 1.0);
  EXPECT_EQ(zero, 0.0);
  EXPECT_FALSE(std::signbit(zero));  // -0 is read as 0
}

TEST(RealNumberTest, NanInfinityHexAndJunkAreRejected) {
  for (const char* text : {"nan", "NaN", "-nan", "inf", "-inf", "infinity", "0x1p-1", "1e400",
                           "-1e400", "0.5x", "", ".", "e5", "1e", "0.5 ", "1..2", "1e+"})
    EXPECT_NE(albedo_rejection(text), "") << "'" << text << "'";
}

TEST(RealNumberTest, OutOfRangeIsRejectedNotClamped) {
  EXPECT_EQ(albedo_rejection("1.5"), "--albedo: give a number from 0 to 1 (1.5 is above 1)");
  EXPECT_NE(albedo_rejection("-0.1").find("below 0"), std::string::npos);
  EXPECT_EQ(albedo_rejection("1"), "");
}

TEST(NumberMessageTest, EveryMessageIsOneLineUnder200CharactersNamingTheFlag) {
  const std::string long_text(5000, '7');
  std::vector<std::string> messages;
  for (const std::string& text :
       {std::string("-1"), std::string("18446744073709551616"), std::string("0x10"), long_text,
        std::string("a\nb"), std::string(300, 'x')})
    messages.push_back(seed_rejection(text));
  for (const std::string& text : {std::string("nan"), std::string("inf"), std::string("1e400"),
                                  std::string(300, '9') + "e9", std::string("x\r\ny")})
    messages.push_back(albedo_rejection(text));
  for (const std::string& message : messages) {
    EXPECT_LT(message.size(), 200u) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(message.find('\r'), std::string::npos) << message;
    EXPECT_TRUE(message.rfind("--seed: ", 0) == 0 || message.rfind("--albedo: ", 0) == 0)
        << message;
  }
}

TEST(NumberMessageTest, RangesAreWrittenPlainly) {
  EXPECT_EQ(mcrt::real_number_range("--max-rays", 1.0, 1e15),
            "--max-rays: give a number from 1 to 1e15");
  EXPECT_EQ(mcrt::real_number_range("--fixed-q", 0.001, 0.999),
            "--fixed-q: give a number from 0.001 to 0.999");
  EXPECT_EQ(mcrt::real_number_range("--emission", 0.0, 1e6),
            "--emission: give a number from 0 to 1000000");
}

// add_number_option: the reader behind a CLI11 flag, with its default kept and recorded.
TEST(AddNumberOptionTest, ParsesIntoTheVariableAndRefusesWithTheFlagsName) {
  std::uint64_t seed = 1;
  int width = 640;
  double albedo = 0.5;
  CLI::App app;
  app.option_defaults()->always_capture_default();
  mcrt::add_number_option(app, "--seed", seed, "Random seed", 0, k_most);
  mcrt::add_number_option(app, "--width", width, "Image width", 1, 16384);
  mcrt::add_number_option(app, "--albedo", albedo, "Albedo", 0.0, 1.0);
  app.parse(std::vector<std::string>{});
  EXPECT_EQ(seed, 1u);
  EXPECT_EQ(width, 640);
  EXPECT_EQ(mcrt::flags_json(app)["width"], "640");
  EXPECT_EQ(mcrt::flags_json(app)["albedo"], "0.5");
  // CLI11 takes the arguments reversed.
  app.parse(std::vector<std::string>{"1e0", "--albedo", "010", "--width", "18446744073709551615",
                                     "--seed"});
  EXPECT_EQ(seed, k_most);
  EXPECT_EQ(width, 10);
  EXPECT_EQ(albedo, 1.0);
  EXPECT_EQ(mcrt::flags_json(app)["seed"], "18446744073709551615");
  for (const auto& [flag, text] : std::vector<std::pair<std::string, std::string>>{
           {"--seed", "18446744073709551616"}, {"--width", "0x10"}, {"--albedo", "nan"}}) {
    try {
      app.parse(std::vector<std::string>{text, flag});
      ADD_FAILURE() << flag << " " << text << " was accepted";
    } catch (const CLI::ValidationError& e) {
      EXPECT_EQ(std::string(e.what()).rfind(flag + ": ", 0), 0u) << e.what();
    }
  }
}

TEST(AddNumberOptionTest, HelpShowsTheTypeTheRangeAndTheDefault) {
  int spp = 4;
  double albedo = 0.5;
  CLI::App app;
  app.option_defaults()->always_capture_default();
  mcrt::add_number_option(app, "--spp", spp, "Samples per pixel", 1, 1 << 16);
  mcrt::add_number_option(app, "--albedo", albedo, "Albedo", 0.0, 1.0);
  const std::string help = app.help();
  EXPECT_NE(help.find("--spp INT:INT in [1 - 65536]=4"), std::string::npos) << help;
  EXPECT_NE(help.find("--albedo FLOAT:FLOAT in [0 - 1]=0.5"), std::string::npos) << help;
  EXPECT_NE(help.find("Samples per pixel"), std::string::npos) << help;
}

}  // namespace
